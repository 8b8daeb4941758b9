#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"

#include <string>
#include <vector>

namespace mcpp::test {

// The invariants of spec section 7, shared by every planner test. Each checker returns the violations
// found (empty when the plan holds), each naming the cell, robot or waypoint concerned.
[[nodiscard]] std::vector<std::string> checkTiling(const PlanningProblem& problem, const Plan& plan);
[[nodiscard]] std::vector<std::string> checkRegions(const Plan& plan);
[[nodiscard]] std::vector<std::string> checkPaths(const PlanningProblem& problem, const Plan& plan);
[[nodiscard]] std::vector<std::string> checkTimes(const Plan& plan);
// All of the above.
[[nodiscard]] std::vector<std::string> checkAllInvariants(const PlanningProblem& problem, const Plan& plan);

// At most the first `limit` violations, one per line, for a test failure message.
[[nodiscard]] std::string describe(const std::vector<std::string>& violations, std::size_t limit = 10);

} // namespace mcpp::test
