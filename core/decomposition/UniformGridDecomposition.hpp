#pragma once

#include "core/decomposition/DecompositionOptions.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/ProgressReporter.hpp"

namespace mcpp {

// Which cells of the grid a planner covers, judged on their sub-cells (side Fd_min, the robot's swath).
// A sub-cell is blocked when its obstacle + outside share exceeds the blocked threshold.
enum class GridCellRule {
    // A cell is kept when its own obstacle + outside share is at most the threshold, as at MCPP-MLCT's bottom
    // level; all four sub-cells are then covered (DARP, MSTC).
    WholeCell,
    // Kept only when all four sub-cells are free: a mega-cell touching an obstacle is dropped (Spiral-STC).
    AllSubCellsFree,
    // Kept when at least one sub-cell is free; the blocked ones are marked and never entered (Full
    // Spiral-STC).
    AnySubCellFree,
};

// The grid planners' decomposition (seed planners): square cells of 2 x Fd_min over the raster, anchored at
// its origin like the quadtree's bottom level, with land cover and speed found as the quadtree finds them
// (majority passable class, harmonic mean speed). Neighbours are cells whose free sub-cells face each other
// across a shared side.
class UniformGridDecomposition {
  public:
    UniformGridDecomposition(DecompositionOptions options, GridCellRule rule)
        : options_(options), rule_(rule) {}

    [[nodiscard]] CellGraph decompose(const ClassGrid& grid, const ClassTable& classes,
                                      const ProgressReporter& progress = {}) const;

  private:
    DecompositionOptions options_;
    GridCellRule rule_;
};

} // namespace mcpp
