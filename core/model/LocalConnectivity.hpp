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
    NeighbourSource neighbours_;
    std::vector<int> stamp_;
    int stampValue_ = 0;
    std::vector<int> targets_;
    std::vector<int> queue_;
};

} // namespace mcpp
