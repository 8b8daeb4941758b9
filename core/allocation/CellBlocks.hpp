#pragma once

#include "core/allocation/CellFigures.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/NeighbourTopology.hpp"

#include <vector>

namespace mcpp {

// A graph's cells grouped into blocks, and which blocks touch: the coarse graph on which regions are grown
// before they are settled cell by cell. groupIntoBlocks makes square blocks of a very large map; the tree
// pieces (treePieces) are blocks too.
struct CellBlocks {
    std::vector<int> blockOfCell;     // by cell id
    std::vector<CellFigures> figures; // by block: area and cost summed, centre weighted by area
    NeighbourTopology adjacency;      // blocks holding two neighbouring cells, ascending
    // Whether every block's cells are linked among themselves: then a connected set of blocks is a connected
    // set of cells.
    bool everyBlockConnected = false;
};

// Square blocks of `side` x `side` bottom cells (each cell in the block that holds its north-west corner),
// numbered in the order of their first cell.
[[nodiscard]] CellBlocks groupIntoBlocks(const CellGraph& graph, int side);

// The graph's cells grouped as `blockOfCell` says (blocks 0..blockCount-1, none empty), each block's cells
// linked among themselves: the caller made them so.
[[nodiscard]] CellBlocks groupIntoConnectedBlocks(const CellGraph& graph, std::vector<int> blockOfCell,
                                                  int blockCount);

} // namespace mcpp
