#pragma once

#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// The last step to balance: costs estimate each path's time, the paths are the time. The robot with the
// longest path gives a border cell to a neighbouring region whose path is shorter, both paths are planned
// again, and the move stays when the longer of the two new paths is shorter than the old longest. It stops
// when the longest path has no such move or the trials run out (each replans two regions, so the budget is
// counted in cells planned).
class PathTimeBalancing {
  public:
    PathTimeBalancing(const SpanningTreeCoverage& coverage, std::size_t cellBudget)
        : coverage_(coverage), cellBudget_(cellBudget) {}

    // Returns the cells moved.
    int balance(const CellGraph& graph, RegionAllocation& regions, std::vector<CoveragePath>& paths,
                const std::vector<MapPoint>& starts, const ProgressReporter& progress) const;

  private:
    const SpanningTreeCoverage& coverage_;
    std::size_t cellBudget_;
};

} // namespace mcpp
