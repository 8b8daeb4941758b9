#pragma once

#include "core/model/CoveragePath.hpp"
#include "core/model/NeighbourTopology.hpp"
#include "core/model/PlanMetrics.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/model/RegionAllocation.hpp"

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
