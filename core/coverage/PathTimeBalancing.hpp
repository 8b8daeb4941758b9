#pragma once

#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"

#include <algorithm>
#include <functional>
#include <vector>

namespace mcpp {

// The last step to balance: costs estimate each path's time, the paths are the time. The region with the
// longest path passes a border cell along a chain of neighbouring regions to one whose path is shorter
// (the shortest first, a direct neighbour being a chain of one), the chain's paths are planned again, and
// the change stays when every new path is shorter than the old longest. It stops when the paths are within
// 0.2 % of their mean, when no chain helps the longest, or when the budget, counted in cells planned, is
// spent (a chain whose regions do not fit in what is left is not tried).
class PathTimeBalancing {
  public:
    PathTimeBalancing(const SpanningTreeCoverage& coverage, std::size_t cellBudget)
        : coverage_(coverage), cellBudget_(cellBudget) {}

    // Each robot's field pace (PlanningRun::fieldPaces): the paths' times in the field are balanced.
    void setFieldPaces(std::vector<double> fieldPaces) { fieldPaces_ = std::move(fieldPaces); }
    // Which robot may take which cell (an aircraft only cells within its flights' reach); unset: any.
    using MayTake = std::function<bool(std::size_t robot, int cell)>;
    void setMayTake(MayTake mayTake) { mayTake_ = std::move(mayTake); }

    // The budget planners give it: about half a second of replanning on any map.
    [[nodiscard]] static std::size_t budgetFor(const CellGraph& graph) {
        return std::min<std::size_t>(250'000 + 2 * graph.size(), 1'000'000);
    }

    // Returns the cells moved.
    int balance(const CellGraph& graph, RegionAllocation& regions, std::vector<CoveragePath>& paths,
                const std::vector<MapPoint>& starts, const ProgressReporter& progress) const;

  private:
    const SpanningTreeCoverage& coverage_;
    std::size_t cellBudget_;
    std::vector<double> fieldPaces_;
    MayTake mayTake_;
};

} // namespace mcpp
