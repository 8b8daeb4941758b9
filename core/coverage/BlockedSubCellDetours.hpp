#pragma once

#include "core/coverage/SubCellLattice.hpp"
#include "core/model/CoveragePath.hpp"

#include <vector>

namespace mcpp {

// Full Spiral-STC's walk from a walk round a tree of partly occupied cells: the centres of blocked sub-cells
// are dropped and each gap left between consecutive free sub-cells is bridged by the shortest way through
// free ones. Where a tree edge has free sub-cells on one side only (a single-sided edge) the bridge passes
// sub-cells again: the repeated coverage Full Spiral-STC pays for covering next to obstacles.
[[nodiscard]] std::vector<Waypoint> avoidBlockedSubCells(const SubCellLattice& lattice,
                                                         const std::vector<Waypoint>& walk);

} // namespace mcpp
