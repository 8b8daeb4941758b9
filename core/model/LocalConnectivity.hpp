#pragma once

#include "core/model/NeighbourSource.hpp"

#include <vector>

namespace mcpp {

// Whether a region stays in one piece without one of its cells, judged near the cell: the cell's
// neighbours in the region must reach each other within `searchLimit` cells of search. A region that only
// reconnects through a long loop counts as cut, which keeps the check cheap and never splits a region.
// One instance serves many checks on one graph (a stamp per cell, no clearing between them).
class LocalConnectivity {
  public:
    explicit LocalConnectivity(NeighbourSource neighbours)
        : neighbours_(neighbours), stamp_(neighbours.count(), 0) {}

    // owner: the region of every graph cell. False for a cell none of its region touches.
    [[nodiscard]] bool canRemove(int cell, const std::vector<int>& owner, std::size_t searchLimit);

  private:
    // Searches wider than this look first for a neighbour cut off with fewer cells than this.
    static constexpr std::size_t smallSideLimit = 32;

    // Whether some neighbour of `cell` in its region (targets_ after the first) lies in a part of fewer
    // than smallSideLimit cells that `cell` cuts off from all the others. When it does, the search from
    // the first neighbour cannot reach it either: the answer is "would cut", as that search would give.
    bool someNeighbourIsCutOff(int cell, const std::vector<int>& owner);
    // A stamp no cell holds yet.
    int nextMark();

    enum class SearchEnd { FoundAll, RanOut, HitLimit };
    // Breadth first from `from` through the region of `cell` less `cell`, while fewer than `limit` cells are
    // queued, until `wanted` of the other neighbours (targets_ but `from`) are found: FoundAll then, RanOut
    // when every cell it could reach was searched, HitLimit otherwise.
    SearchEnd search(int cell, int from, const std::vector<int>& owner, std::size_t limit,
                     std::size_t wanted);

    NeighbourSource neighbours_;
    std::vector<int> stamp_;
    int stampValue_ = 0;
    std::vector<int> targets_;
    std::vector<int> queue_;
};

} // namespace mcpp
