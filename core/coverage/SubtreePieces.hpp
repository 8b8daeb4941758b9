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
// The cut is made bottom up where a subtree with a start reaches a fair share, the tree held from whichever
// start cuts most evenly; the pieces are then evened out in time by moving a branch of one
// piece to a neighbouring piece through a grid edge: of the moves an estimate ranks best at lowering the
// sum of the squares of the pieces' times, each is made for real and undone, and of those that lower it
// well the one that adds the fewest turns is made (at most `mostMoves`; the division whose longest piece
// was shortest is kept).
// Where a start cell is the only way into part of the map, or all ways to it are taken by a few pieces,
// those pieces stay large: the caller compares with another division.
class SubtreePieces {
  public:
    // tree: over the part's cells, each start cell in it; startCells and starts by robot of the part.
    SubtreePieces(const CellGraph& graph, const SpanningTree& tree, const std::vector<int>& startCells,
                  const std::vector<MapPoint>& starts, const ProgressReporter& progress,
                  int mostMoves = 4096);

    // Hands small branches to neighbouring pieces wherever the two walks then turn less and neither takes
    // longer than `mostSeconds` or, if that is more, than the longest piece does now: pieces below the
    // longest spend their spare time on straighter borders. Stops after `mostWalkedNodes` nodes walked in
    // trials; returns the turns saved.
    int saveTurns(double mostSeconds, const ProgressReporter& progress, double mostWalkedNodes = 2e7);

    // Each robot's piece as a tree rooted at its start cell (graph cells, as SpanningTree holds them).
    // Not to be called from two threads at once: it shares a scratch index.
    [[nodiscard]] SpanningTree pieceTree(std::size_t robot) const;
    // The pieces' walks from their starts: the mean and the longest time, and all their turns.
    [[nodiscard]] double meanSeconds() const;
    [[nodiscard]] double longestSeconds() const;
    [[nodiscard]] int totalTurns() const;

  private:
    static constexpr int mostBranchCells = 8; // what saveTurns hands over at a time
    struct Move {
        int branch = -1; // the node whose subtree moves, rooted in its piece at the piece's start
        int from = -1;   // its node that joins the other piece
        int to = -1;     // the other piece's node it joins
        double change = 0.0;
    };
    // What a move would do: the change of the sum of the squares of the pieces' times and of the two
    // pieces' turns, and the longer of the two pieces' times after it.
    struct TrialOutcome {
        double squaresChange = 0.0;
        int turnsChange = 0;
        double longerSeconds = 0.0;
    };

    void cutFromBestRoot(const ProgressReporter& progress);
    void evenOut(const ProgressReporter& progress, int mostMoves);
    void labelAndMeasureAll();
    void cutBottomUp(int root);
    void cutEdge(int a, int b);
    [[nodiscard]] double sumOfSquares() const;
    [[nodiscard]] bool evenEnough() const;
    void label(std::size_t robot);
    void measure(std::size_t robot);
    template <typename Visit> void forEachBorder(Visit&& visit) const;
    [[nodiscard]] std::vector<Move> candidateMoves(std::size_t count) const;
    [[nodiscard]] Move bestMove();
    [[nodiscard]] std::vector<Move> smallBorderMoves() const;
    [[nodiscard]] bool stillPossible(const Move& move) const;
    [[nodiscard]] int sideOf(int node, int other) const;
    [[nodiscard]] unsigned sidesWithEdges(int node) const;
    [[nodiscard]] int turnChangeOnGrid(const Move& move) const;
    [[nodiscard]] TrialOutcome trial(const Move& move);
    void apply(const Move& move);

    const CellGraph& graph_;
    const SpanningTree& tree_;
    const std::vector<MapPoint>& starts_;
    std::vector<int> nodeOfCell_;              // by graph cell, -1 outside the tree
    std::vector<int> startNode_;               // by robot
    std::vector<std::vector<int>> adjacency_;  // the forest's edges, by node
    std::vector<int> piece_;                   // robot by node
    std::vector<int> parent_;                  // in its piece, rooted at the start; -1 at the start
    mutable std::vector<int> localOfNode_;     // pieceTree's scratch, by node: -1 between calls
    std::vector<int> subtreeCells_;            // cells below each node in its piece, itself included
    std::vector<std::vector<int>> pieceNodes_; // by robot, in breadth-first order from the start
    std::vector<double> seconds_;              // by robot
    std::vector<int> turns_;                   // by robot
};

} // namespace mcpp
