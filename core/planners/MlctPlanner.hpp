#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// MCPP-MLCT: hierarchical quadtree -> neighbour topology -> azimuth-trend allocation -> improved STC -> metrics.
class MlctPlanner final : public Planner {
public:
    static constexpr const char* plannerName = "mcpp-mlct";

    [[nodiscard]] std::string name() const override { return plannerName; }
    [[nodiscard]] Plan plan(const PlanningProblem& problem, const ProgressReporter& progress) const override;
};

// The active cell (active index) holding each start, after the checks of spec section 4: a start outside
// the area, on an obstacle or sharing a cell with another is an error, or with snapping, moved to the
// nearest free active cell with a warning appended to `warnings`.
[[nodiscard]] std::vector<int> locateStartCells(const QuadTree& tree, const PlanningProblem& problem,
                                                std::vector<MapPoint>& starts, std::vector<std::string>& warnings);

} // namespace mcpp
