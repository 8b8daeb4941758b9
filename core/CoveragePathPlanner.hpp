#pragma once

#include "core/CoveragePath.hpp"
#include "core/MapPoint.hpp"
#include "core/NeighbourTopology.hpp"
#include "core/PlannerSettings.hpp"
#include "core/ProgressReporter.hpp"
#include "core/QuadTree.hpp"
#include "core/RegionAllocation.hpp"

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
