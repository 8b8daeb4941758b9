#pragma once

#include "core/coverage/SpanningTree.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/ProgressReporter.hpp"

#include <vector>

namespace mcpp {

// One spanning tree of a connected part cut into a subtree per robot, each holding that robot's start: a
// robot walks round its own subtree from its start, with no way to go to its piece first, and the tree's
// straight runs are cut only where two pieces meet (a piece of the tour, by contrast, must be reached).
// The cut is made bottom up where a subtree with a start reaches a fair share; the pieces are then evened
// out in time by moving a branch of one piece to a neighbouring piece through a grid edge, the move that
// lowers the sum of the squares of the pieces' time differences most, until none does (at most
// `mostMoves`). Where a start cell is the only way into part of the map, that part stays with its robot:
// the caller compares with another division.
class SubtreePieces {
  public:
    // tree: over the part's cells, each start cell in it; startCells and starts by robot of the part.
    SubtreePieces(const CellGraph& graph, const SpanningTree& tree, const std::vector<int>& startCells,
                  const std::vector<MapPoint>& starts, const ProgressReporter& progress,
                  int mostMoves = 4096);

    // Each robot's piece as a tree rooted at its start cell (graph cells, as SpanningTree holds them).
    [[nodiscard]] SpanningTree pieceTree(std::size_t robot) const;

  private:
    struct Move {
        int branch = -1; // the node whose subtree moves, rooted in its piece at the piece's start
        int from = -1;   // its node that joins the other piece
        int to = -1;     // the other piece's node it joins
        double change = 0.0;
    };

    void cutBottomUp();
    void cutEdge(int a, int b);
    [[nodiscard]] bool evenEnough() const;
    void label(std::size_t robot);
    void measure(std::size_t robot);
    [[nodiscard]] Move bestMove() const;
    void apply(const Move& move);

    const CellGraph& graph_;
    const SpanningTree& tree_;
    const std::vector<MapPoint>& starts_;
    std::vector<int> nodeOfCell_;              // by graph cell, -1 outside the tree
    std::vector<int> startNode_;               // by robot
    std::vector<std::vector<int>> adjacency_;  // the forest's edges, by node
    std::vector<int> piece_;                   // robot by node
    std::vector<int> parent_;                  // in its piece, rooted at the start; -1 at the start
    std::vector<int> subtreeCells_;            // cells below each node in its piece, itself included
    std::vector<std::vector<int>> pieceNodes_; // by robot, in breadth-first order from the start
    std::vector<double> seconds_;              // by robot
    int moves_ = 0;
};

} // namespace mcpp
