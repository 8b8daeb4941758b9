#pragma once

#include "core/parameters/PlannerChoice.hpp"
#include "core/planners/Planner.hpp"
#include "core/planners/PlannerDescription.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mcpp {

// The planners this build offers, in menu order, by the names used on the command line and in mission files.
[[nodiscard]] std::vector<PlannerDescription> plannerDescriptions();
[[nodiscard]] std::vector<std::string> availablePlanners();
// The description of the planner of that name, or nothing.
[[nodiscard]] std::optional<PlannerDescription> findPlannerDescription(const std::string& name);
// The least memory per cell of the finest grid any planner declares: no plan of a larger grid fits the
// budget.
[[nodiscard]] std::int64_t leastBytesPerBottomCell();
// "unknown planner \"x\" (available: a, b, c)"
[[nodiscard]] std::string unknownPlannerMessage(const std::string& name);
// Nullptr when the name is unknown; an empty name is the default planner.
[[nodiscard]] std::unique_ptr<Planner> makePlanner(const std::string& name);
[[nodiscard]] const std::string& defaultPlannerName();
// The planner with every parameter at its default (the default planner for an empty name).
[[nodiscard]] PlannerChoice defaultPlannerChoice(const std::string& name = {});
// Another planner, keeping the values of the parameters both planners declare (a user who set a blocked
// threshold keeps it when trying another planner); the rest at their defaults.
[[nodiscard]] PlannerChoice switchPlanner(const PlannerChoice& current, const std::string& name);

} // namespace mcpp
