#pragma once

#include "core/decomposition/QuadTree.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/NeighbourTopology.hpp"

namespace mcpp {

// The hierarchical quadtree of spec sections 2 and 3 as a cell graph: its active cells, in active-index
// order, with the neighbours the topology found for them at any level.
[[nodiscard]] CellGraph cellGraphOfQuadTree(const QuadTree& tree, NeighbourTopology topology);

} // namespace mcpp
