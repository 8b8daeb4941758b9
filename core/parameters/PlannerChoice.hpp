#pragma once

#include "core/parameters/ParameterValues.hpp"

#include <string>

namespace mcpp {

// Which planner to run and with which parameters: what a mission file's "planner" object holds.
struct PlannerChoice {
    std::string planner = "mcpp-mlct";
    ParameterValues parameters; // the planner's declared keys only; missing ones take their defaults

    friend bool operator==(const PlannerChoice&, const PlannerChoice&) = default;
};

} // namespace mcpp
