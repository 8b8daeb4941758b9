#pragma once

#include "core/model/NeighbourTopology.hpp"
#include "core/planners/PlannerSettings.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// The cost of covering a cell for a robot: the STC path through it is 2 * Cs long (spec 4).
[[nodiscard]] inline double cellCostSeconds(const QuadCell& cell) { return 2.0 * cell.size / cell.speedMetresPerSecond; }

// Stage 3 of the pipeline: divides the reachable active cells into one connected region per robot.
class RegionAllocator {
public:
    virtual ~RegionAllocator() = default;
    // startCells: active index of each robot's start cell, all distinct.
    [[nodiscard]] virtual RegionAllocation allocate(const QuadTree& tree, const NeighbourTopology& topology,
                                                    const std::vector<int>& startCells, const PlannerSettings& settings,
                                                    const ProgressReporter& progress) const = 0;
};

} // namespace mcpp
