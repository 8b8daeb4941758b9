#pragma once

#include "core/decomposition/OneLevelQuadTree.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/NeighbourTopology.hpp"

namespace mcpp {

// The hierarchical quadtree of spec sections 2 and 3 as a cell graph: its active cells, in active-index
// order, with the neighbours the topology found for them at any level. Takes the tree to free it before
// the graph is indexed.
[[nodiscard]] CellGraph cellGraphOfQuadTree(QuadTree tree, NeighbourTopology topology);
// The same graph of a one-level tree's grid.
[[nodiscard]] CellGraph cellGraphOfQuadTree(OneLevelQuadTree grid, NeighbourTopology topology);
// The graph of either, with the neighbours found for it.
[[nodiscard]] CellGraph cellGraphOfLeaves(QuadTreeLeaves leaves);

} // namespace mcpp
