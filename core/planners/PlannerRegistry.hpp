#pragma once

#include "core/planners/Planner.hpp"
#include "core/planners/PlannerDescription.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcpp {

// The planners this build offers, in menu order, by the names used on the command line and in mission files.
[[nodiscard]] std::vector<PlannerDescription> plannerDescriptions();
[[nodiscard]] std::vector<std::string> availablePlanners();
// Nullptr when the name is unknown; an empty name is the default planner.
[[nodiscard]] std::unique_ptr<Planner> makePlanner(const std::string& name);
[[nodiscard]] const std::string& defaultPlannerName();

} // namespace mcpp
