#pragma once

#include "core/model/CoveragePath.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/NeighbourTopology.hpp"
#include "core/planners/PlannerSettings.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// Stage 4 of the pipeline: one coverage path per robot through its region.
class CoveragePathPlanner {
public:
    virtual ~CoveragePathPlanner() = default;
    [[nodiscard]] virtual std::vector<CoveragePath> plan(const QuadTree& tree, const NeighbourTopology& topology,
                                                         const RegionAllocation& allocation,
                                                         const std::vector<MapPoint>& starts,
                                                         const PlannerSettings& settings,
                                                         const ProgressReporter& progress) const = 0;
};

} // namespace mcpp
