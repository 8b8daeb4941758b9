#pragma once

#include "core/parameters/ParameterValue.hpp"

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mcpp {

enum class ParameterType { Boolean, Integer, Real, Choice };

// The value a Real parameter with an `automatic` word holds when the planner is to work it out itself: no
// number typed on the command line or in a mission file can be it.
inline constexpr double automaticParameterValue = -std::numeric_limits<double>::infinity();

// One parameter as a planner (or one of its stages) declares it. The command line, mission files, the
// settings panel and validation are all derived from this declaration.
struct ParameterSpec {
    std::string key;   // command-line and mission-file name: lower case, words joined by underscores
    std::string label; // for people: "Purity tolerance"
    ParameterType type = ParameterType::Real;
    ParameterValue defaultValue = 0.0;
    double minimum = -std::numeric_limits<double>::infinity();
    double maximum = std::numeric_limits<double>::infinity();
    bool maximumIncluded = true; // the minimum always is
    std::vector<std::string> choices;
    std::string unit; // "m", "s", "%"... or empty
    std::string help; // one sentence
    // For a Real: the word ("auto") that stands for automaticParameterValue, a value the planner works out
    // itself; typed, saved and shown as the word. Empty: the parameter always holds a number in range.
    std::string automatic;
    // The key of a boolean parameter of the same planner without which this one has no effect ("only
    // with balanced pieces"): the settings panel greys it out while that is off, --help-planner says so.
    std::string onlyWith;

    // Why the value does not fit the declaration (wrong type, out of range, unknown word), or nothing.
    [[nodiscard]] std::optional<std::string> problemWith(const ParameterValue& value) const;
    // Reads a value written as on the command line ("0.02", "true", "off", "7", "fast"); on failure
    // nothing, with the reason in *error.
    [[nodiscard]] std::optional<ParameterValue> parse(std::string_view text, std::string* error) const;
    // The value as parse() reads it back.
    [[nodiscard]] std::string format(const ParameterValue& value) const;
    // Whether the value is the automatic one of a parameter that has it.
    [[nodiscard]] bool isAutomatic(const ParameterValue& value) const;
    // "a number from 0 up to (not including) 1", "true or false", "one of: a, b", for messages and help.
    [[nodiscard]] std::string expected() const;
};

// Builders for the four kinds, so declarations read as one line each.
[[nodiscard]] ParameterSpec realParameter(std::string key, std::string label, double defaultValue,
                                          double minimum, double maximum, std::string help,
                                          std::string unit = {}, bool maximumIncluded = true);
[[nodiscard]] ParameterSpec integerParameter(std::string key, std::string label, int defaultValue,
                                             int minimum, int maximum, std::string help);
[[nodiscard]] ParameterSpec booleanParameter(std::string key, std::string label, bool defaultValue,
                                             std::string help);
// The spec, declared to have no effect unless the boolean parameter `switchKey` is on
// (ParameterSpec::onlyWith).
[[nodiscard]] ParameterSpec onlyWith(ParameterSpec spec, std::string switchKey);
[[nodiscard]] ParameterSpec choiceParameter(std::string key, std::string label, std::string defaultValue,
                                            std::vector<std::string> choices, std::string help);

} // namespace mcpp
