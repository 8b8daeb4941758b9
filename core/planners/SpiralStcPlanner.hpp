#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// Spiral-STC (Gabriely & Rimon), one robot: the grid of 2 x Fd_min mega-cells without those touching an
// obstacle, a spanning tree grown counter-clockwise from the start, and the walk round it through sub-cell
// centres.
class SpiralStcPlanner final : public Planner {
  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
