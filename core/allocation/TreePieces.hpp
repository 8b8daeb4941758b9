#pragma once

#include "core/allocation/CellBlocks.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/ProgressReporter.hpp"

#include <vector>

namespace mcpp {

// The map cut into pieces of one turn-minimising tree over all of it (TurnMinimisingTree): subtrees cut
// off bottom-up where they reach `pieceCost` seconds (so a piece costs that, less where it ends at a root
// or a start, up to a few times that where several subtrees just short of it meet) or where they reach
// twice the side of a square of that cost (a piece spans at most about four times it), never two starts
// in one piece. The pieces are numbered in breadth-first order of the cells that head them. Regions grown
// from such pieces have borders where the whole map's tree is cut, so their own trees turn nearly as little
// as it does: the cost of a border lies in the straight runs it cuts. Where cells differ in size the tree
// weighs time, the steps between sizes included, as a region's tree does. pieceCosts: one level of pieces per
// cost, dearest first; each level's pieces lie within the last one's. progress, where given: a cancel request
// stops the whole map's tree (PlanningError), which takes seconds on maps of a million cells.
[[nodiscard]] std::vector<CellBlocks> treePieces(const CellGraph& graph, const std::vector<int>& startCells,
                                                 const std::vector<double>& pieceCosts,
                                                 const ProgressReporter* progress = nullptr);

} // namespace mcpp
