#pragma once

#include "core/model/LandCoverClass.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mcpp {

// The classes of one map, kept in insertion order and looked up by raster value.
class ClassTable {
  public:
    ClassTable() = default;
    explicit ClassTable(std::vector<LandCoverClass> classes);

    // Adds a class or replaces the one with the same value.
    void set(const LandCoverClass& landCoverClass);
    bool remove(std::int32_t value);
    // One field of view over every class, as a camera's footprint is over any land cover.
    void setEveryFieldOfView(double metres);

    [[nodiscard]] const LandCoverClass* find(std::int32_t value) const;
    [[nodiscard]] const std::vector<LandCoverClass>& classes() const { return classes_; }
    [[nodiscard]] bool empty() const { return classes_.empty(); }
    [[nodiscard]] std::size_t size() const { return classes_.size(); }

    // The first problem with the table (NaN, negative or zero FOV of a passable class, negative speed,
    // duplicate value), as a message naming the class; nothing when the table is usable.
    [[nodiscard]] std::optional<std::string> validate() const;

    friend bool operator==(const ClassTable&, const ClassTable&) = default;

  private:
    std::vector<LandCoverClass> classes_;
};

} // namespace mcpp
