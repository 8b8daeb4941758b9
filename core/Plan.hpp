#pragma once

#include "core/CoveragePath.hpp"
#include "core/NeighbourTopology.hpp"
#include "core/PlanMetrics.hpp"
#include "core/QuadTree.hpp"
#include "core/RegionAllocation.hpp"

#include <string>
#include <vector>

namespace mcpp {

// Everything a planner produced: the cells, who covers which, the paths and the figures.
struct Plan {
    std::string planner;
    QuadTree quadTree;
    NeighbourTopology topology;
    RegionAllocation allocation;
    std::vector<CoveragePath> paths; // by robot
    PlanMetrics metrics;
    std::vector<std::string> warnings;
};

} // namespace mcpp
