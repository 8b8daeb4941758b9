#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// Full Spiral-STC (Gabriely & Rimon), one robot: like Spiral-STC, but mega-cells with at least one free
// sub-cell stay, joined through single- and double-sided edges; the walk keeps out of blocked sub-cells
// and passes some sub-cells twice where an edge is single-sided. Higher coverage next to obstacles.
class FullSpiralStcPlanner final : public Planner {
  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
