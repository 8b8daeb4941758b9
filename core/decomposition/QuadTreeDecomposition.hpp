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
// The same graph of a one-level tree's grid, with neighbour lists, or finding each cell's neighbours on
// the grid when asked (CellGraph::ofGrid).
[[nodiscard]] CellGraph cellGraphOfQuadTree(OneLevelQuadTree grid, bool withLists);
// From how many cells a one-level tree's graph keeps no neighbour lists and finds each cell's neighbours on
// its grid when asked: 20 bytes a cell less (1.4 GB on a map of 69 million cells), at the price of slower
// reading, which smaller maps are spared (the 15 benchmark grids' allocation: 0.37 s with lists, 0.54-0.62 s
// without).
constexpr std::size_t fewestCellsForGridNeighbours = 4'000'000;
// The graph of either, with the neighbours found for it.
[[nodiscard]] CellGraph cellGraphOfLeaves(QuadTreeLeaves leaves,
                                          std::size_t fewestCellsWithoutLists = fewestCellsForGridNeighbours);

} // namespace mcpp
