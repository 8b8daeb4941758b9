#pragma once

#include "core/coverage/RegionAdjacency.hpp"
#include "core/coverage/SizeChangeConnectors.hpp"
#include "core/model/ProgressReporter.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace mcpp {

// A spanning tree over a region whose circumnavigation turns little. A coverage walk turns twice in a cell
// the tree enters from one side (a leaf), from two perpendicular sides or from three, four times in a cell
// joined on all four, and never in a cell joined on two opposite sides only. The tree is built in three
// steps: the fewest straight runs (straightRuns), joined where that adds the fewest turns (cheapest first,
// costs updated as cells gain sides), then edge swaps that lower the count, each closing a cycle whose two
// sides climb at most `cycleLimit` cells each, so the work stays linear in the region's size. Where cells
// differ in size, the swaps weigh time instead: turns at their cells' price and the steps between cells of
// different sizes (SizeChangeConnectors).
// With plateauRounds, on cells of one size, the swaps go on across plateaus: each round takes every swap
// that keeps the count (in a seeded shuffled order, so the tree is the same on every run), then the swaps
// that lower it around the cells those moved; the tree with the fewest turns seen is kept.
class TurnMinimisingTree {
  public:
    struct Options {
        int cycleLimit = 64;
        int swapPasses = 2;
        int plateauRounds = 0;
        // Where given, a cancel request stops the build (PlanningError) between its steps, every 65 536
        // edges its swap passes scan and each plateau round: a region of millions of cells takes tens of
        // seconds.
        const ProgressReporter* progress = nullptr;
    };

    // connectors: null where every cell has one size.
    TurnMinimisingTree(const RegionAdjacency& adjacency, Options options,
                       const SizeChangeConnectors* connectors = nullptr);

    // Tree edges as (node, node) pairs; a forest if the region is not connected.
    [[nodiscard]] std::vector<std::pair<int, int>> edges() const;
    // Turns the walk round the tree makes by the count above (exact on a grid of equal cells).
    [[nodiscard]] int estimatedTurns() const;
    // Whether the search across plateaus found a cheaper tree; if not, the tree is the one built without it.
    [[nodiscard]] bool searchLowered() const { return searchLowered_; }

  private:
    using SideCounts = std::array<std::uint16_t, 4>;

    [[nodiscard]] int turnChangeAdding(int node, CellSide side) const;
    [[nodiscard]] int turnChangeRemoving(int node, CellSide side) const;
    [[nodiscard]] int joinCost(int edge) const;
    [[nodiscard]] double swapCostAdding(int edge);
    [[nodiscard]] double swapCostRemoving(int edge);
    [[nodiscard]] double turnSecondsOf(int node, int turns) const;
    void link(int edge);
    void unlink(int edge);
    void joinRuns(const std::vector<char>& inRuns);
    void throwIfCancelled() const;
    void rootTree();
    enum class Accept { Fewer, FewerOrAsMany };
    struct Drop {
        int child = -1;
        double change = 0.0;
    };
    bool trySwap(int edge, Accept accept = Accept::Fewer);
    [[nodiscard]] Drop edgeToDrop(int u, int v, int meeting, double adding, Accept accept);
    void searchPlateaus();
    void shuffle(std::vector<int>& order);
    void restore(const std::vector<char>& tree);
    void reverseChain(int from, int to, int newParent, int viaEdge);

    const RegionAdjacency& adjacency_;
    Options options_;
    const SizeChangeConnectors* connectors_;
    std::vector<SideCounts> sides_;
    std::vector<char> inTree_;
    std::vector<int> parent_;
    std::vector<int> parentEdge_;
    std::vector<int> stamp_;
    int stampValue_ = 0;
    std::vector<int> chain_; // reverseChain's buffer
    // searchPlateaus' state: the count as swaps change it, the round a cell last changed in, and the
    // shuffle's generator (xorshift32: the same sequence on every platform).
    int turns_ = 0;
    bool searchLowered_ = false;
    int round_ = 0;
    std::vector<int> changedInRound_;
    std::uint32_t shuffleState_ = 2463534242U;
};

} // namespace mcpp
