#pragma once

#include "core/decomposition/QuadTree.hpp"
#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/planners/PlannerDescription.hpp"

#include <string>
#include <vector>

namespace mcpp::test {

// The invariants of spec section 7, shared by every planner test and read from the planner-neutral plan
// alone. Each checker returns the violations found (empty when the plan holds), each naming the cell,
// robot or waypoint concerned. Where a planner promises less (PlannerPromises), less is checked.

// Sorties of battery plans: from the charger and back, within the endurance, a charge between two.
[[nodiscard]] std::vector<std::string> checkSorties(const Plan& plan);
// Plans with a detection layer: what every path sees, recounted apart from the planner's code (an exact
// integral of the sensor profile), matches the layer, and every target reaches the required probability.
[[nodiscard]] std::vector<std::string> checkDetection(const PlanningProblem& problem, const Plan& plan);

// Cells lie on the frame's bottom grid, never overlap and have a positive speed; neighbour lists are
// symmetric, list no cell twice and name exactly the cells sharing a border of positive length.
[[nodiscard]] std::vector<std::string> checkCells(const Plan& plan);
// Every cell connected to a start has a robot, no other cell has one; regions connected and holding their
// start cell where promised.
[[nodiscard]] std::vector<std::string> checkRegions(const Plan& plan, const PlannerPromises& promises = {});
// Paths begin at their start, closed ones return, each step stays in one cell or crosses into a neighbour,
// no waypoint leaves the robot's cells or enters a blocked sub-cell, every free sub-cell centre of every
// region is passed (by its own robot where promised), and the repeated visits reported are the ones made.
[[nodiscard]] std::vector<std::string> checkPaths(const PlanningProblem& problem, const Plan& plan,
                                                  const PlannerPromises& promises = {});
// Times equal the sum of segment length / speed; makespan, lower bound and ratio follow from them; region
// costs add up to the total.
[[nodiscard]] std::vector<std::string> checkTimes(const Plan& plan);
// All of the above.
[[nodiscard]] std::vector<std::string> checkAllInvariants(const PlanningProblem& problem, const Plan& plan,
                                                          const PlannerPromises& promises = {});

// Quadtree only: leaves tile the bottom grid exactly once and, with no purity tolerance, an active cell above
// the bottom holds only classes whose rounded FOV is at least its sub-cell side.
[[nodiscard]] std::vector<std::string> checkQuadTreeTiling(const PlanningProblem& problem,
                                                           const QuadTree& tree);

// At most the first `limit` violations, one per line, for a test failure message.
// Whether the cells `owner` gives to `region` are one connected piece (false when it has none).
[[nodiscard]] bool regionIsConnected(const CellGraph& graph, const std::vector<int>& owner, int region);

[[nodiscard]] std::string describe(const std::vector<std::string>& violations, std::size_t limit = 10);

} // namespace mcpp::test
