#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// The allocation stage: divides the cells reachable from the starts into one region per robot.
class RegionAllocator {
  public:
    virtual ~RegionAllocator() = default;
    // startCells: the cell holding each robot's start, all distinct.
    [[nodiscard]] virtual RegionAllocation allocate(const CellGraph& graph,
                                                    const std::vector<int>& startCells,
                                                    const ProgressReporter& progress) const = 0;
};

} // namespace mcpp
