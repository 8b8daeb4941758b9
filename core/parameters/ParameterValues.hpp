#pragma once

#include "core/parameters/ParameterValue.hpp"

#include <map>
#include <string>

namespace mcpp {

// Parameter values by key. Typed getters expect the value to be there with the declared type: a planner
// reads only what resolveParameters() checked.
class ParameterValues {
  public:
    void set(const std::string& key, ParameterValue value) { values_[key] = std::move(value); }
    void erase(const std::string& key) { values_.erase(key); }
    [[nodiscard]] bool has(const std::string& key) const { return values_.count(key) != 0; }
    [[nodiscard]] const ParameterValue* find(const std::string& key) const {
        const auto found = values_.find(key);
        return found == values_.end() ? nullptr : &found->second;
    }
    [[nodiscard]] const std::map<std::string, ParameterValue>& all() const { return values_; }
    [[nodiscard]] bool empty() const { return values_.empty(); }

    [[nodiscard]] bool boolean(const std::string& key) const { return std::get<bool>(values_.at(key)); }
    [[nodiscard]] int integer(const std::string& key) const { return std::get<int>(values_.at(key)); }
    [[nodiscard]] double real(const std::string& key) const {
        const ParameterValue& value = values_.at(key);
        return std::holds_alternative<int>(value) ? std::get<int>(value) : std::get<double>(value);
    }
    [[nodiscard]] const std::string& choice(const std::string& key) const {
        return std::get<std::string>(values_.at(key));
    }

    friend bool operator==(const ParameterValues&, const ParameterValues&) = default;

  private:
    std::map<std::string, ParameterValue> values_;
};

} // namespace mcpp
