#pragma once

#include "core/decomposition/OneLevelQuadTree.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/model/NeighbourTopology.hpp"

namespace mcpp {

// Finds, for every active cell, the active cells sharing a border of positive length with it, at any level.
// Same-level positions are looked up in per-level index grids; larger neighbours are found by climbing
// to the ancestor that exists, smaller ones by descending the facing children. O(cells) overall.
class NeighbourTopologyBuilder {
  public:
    [[nodiscard]] NeighbourTopology build(const QuadTree& tree) const;
    // The same lists for a one-level tree's grid: each cell's neighbours north, east, south and west, in
    // the order the tree's lists give them.
    [[nodiscard]] NeighbourTopology build(const OneLevelQuadTree& grid) const;
};

} // namespace mcpp
