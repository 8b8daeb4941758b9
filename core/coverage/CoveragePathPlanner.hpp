#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// The coverage stage: one path per robot through its region.
class CoveragePathPlanner {
  public:
    virtual ~CoveragePathPlanner() = default;
    [[nodiscard]] virtual std::vector<CoveragePath> plan(const CellGraph& graph,
                                                         const RegionAllocation& regions,
                                                         const std::vector<MapPoint>& starts,
                                                         const ProgressReporter& progress) const = 0;
};

} // namespace mcpp
