#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace mcpp {

// Counts the sub-cell centres a path passes again, fed one waypoint at a time, as
// countRepeatedSubCellVisits counts them (a closed tour's return to its first sub-cell not counted). Holds a
// byte a cell of the map while it counts.
class RepeatedVisitCounter {
  public:
    explicit RepeatedVisitCounter(const CellGraph& graph) : graph_(graph), seen_(graph.size(), 0) {}

    void add(const Waypoint& waypoint);
    [[nodiscard]] int repeats(bool closed) const;

  private:
    const CellGraph& graph_;
    std::vector<std::uint8_t> seen_; // a bit a sub-cell
    int repeats_ = 0;
    std::size_t added_ = 0;
    std::pair<int, int> firstVisit_{-1, 0};
    std::pair<int, int> lastVisit_{-1, 0};
    std::size_t firstVisitIndex_ = 0;
    std::size_t lastVisitIndex_ = 0;
};

} // namespace mcpp
