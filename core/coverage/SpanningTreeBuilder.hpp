#pragma once

#include "core/coverage/RegionAdjacency.hpp"
#include "core/coverage/SpanningTree.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/ProgressReporter.hpp"

#include <optional>
#include <vector>

namespace mcpp {

enum class EdgeDirection { EastWest, NorthSouth };

// The edges (node pairs of `adjacency`) of the tree fewestTurns builds over `cells`: a TurnMinimisingTree
// whose swaps weigh time where the cells differ in size (SizeChangeConnectors), turns otherwise, then with
// plateauRounds of its search. A forest where the cells are not connected. progress: as
// TurnMinimisingTree::Options'.
[[nodiscard]] std::vector<std::pair<int, int>>
fewestTurnEdges(const CellGraph& graph, const std::vector<int>& cells, const RegionAdjacency& adjacency,
                bool cellsDifferInSize, int plateauRounds, const ProgressReporter* progress = nullptr);

// Spanning trees over a region of a cell graph, rooted at the start cell.
class SpanningTreeBuilder {
  public:
    // scratchIndex: one int per graph cell, all -1, which the builder leaves so; or empty, to number
    // regions listed in ascending order by rank instead (CellIndexScope). plateauRounds: fewestTurns'
    // search across plateaus of equal turns (TurnMinimisingTree::Options), 0 for none.
    // progress, where given: its cancel request stops a fewestTurns tree between steps of its build.
    SpanningTreeBuilder(const CellGraph& graph, std::vector<int>& scratchIndex, int plateauRounds = 0,
                        const ProgressReporter* progress = nullptr)
        : graph_(graph), index_(scratchIndex), plateauRounds_(plateauRounds), progress_(progress) {}

    // Kruskal over the region's adjacencies, the preferred direction's edges first: long straight spines
    // give boustrophedon-like paths with few turns (DARP's idea; spec 5).
    [[nodiscard]] SpanningTree preferring(std::vector<int> cells, int rootCell,
                                          EdgeDirection preferred) const;

    // A tree that turns little (TurnMinimisingTree): straight runs joined where that adds the fewest turns;
    // where cells differ in size, its swaps weigh time, the steps between sizes included.
    [[nodiscard]] SpanningTree fewestTurns(std::vector<int> cells, int rootCell) const;
    // fewestTurns with the search across plateaus where that search lowers the turns; nothing where it
    // does not (the tree is then fewestTurns' without it), where cells differ in size (their tree weighs
    // time) or without plateau rounds.
    [[nodiscard]] std::optional<SpanningTree> fewestTurnsSearched(std::vector<int> cells, int rootCell) const;

    // The trees coverage planners choose among by the time of their walks: fewestTurns first, then
    // preferring east-west and north-south. On one cell size fewestTurns won every region of the benchmarks,
    // so the others are built only where cells differ in size; there they win some regions (a forest map of
    // 4.8 M cells: 54 990 turns with fewestTurns alone, 50 746 with the best of the three).
    static constexpr int candidateCount = 3;
    [[nodiscard]] int candidatesFor(const std::vector<int>& cells) const;
    [[nodiscard]] bool cellsDifferInSize(const std::vector<int>& cells) const;
    [[nodiscard]] SpanningTree candidate(int which, std::vector<int> cells, int rootCell) const;

    // Spiral-STC (Gabriely & Rimon): a depth-first tree grown from the start, each cell scanning its
    // neighbours counter-clockwise from the one it was entered from and entering the first new one.
    [[nodiscard]] SpanningTree spiral(std::vector<int> cells, int rootCell) const;

  private:
    template <typename EdgesOf>
    [[nodiscard]] std::optional<SpanningTree> treeOver(std::vector<int> cells, int rootCell,
                                                       EdgesOf edgesOf) const;

    const CellGraph& graph_;
    std::vector<int>& index_;
    int plateauRounds_;
    const ProgressReporter* progress_;
};

} // namespace mcpp
