#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// MSTC (Hazon & Kaminka) on the grid of 2 x Fd_min cells: one spanning-tree tour of each connected part of
// the map, cut into one piece per robot. Without backtracking each robot follows the tour from its start to
// the next robot's; balanced, the pieces are of equal time and a robot may first walk along the tour,
// forwards or backwards, through other robots' pieces to reach its own. Paths end where the piece ends.
class MstcPlanner final : public Planner {
  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
