#pragma once

#include <string>
#include <variant>

namespace mcpp {

// The value of one planner parameter: a switch, a whole number, a real number or one of a set of words.
using ParameterValue = std::variant<bool, int, double, std::string>;

} // namespace mcpp
