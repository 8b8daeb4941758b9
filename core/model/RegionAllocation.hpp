#pragma once

#include <vector>

namespace mcpp {

// Which robot covers each cell of the plan's cell graph. -1 marks a cell no robot covers.
struct RegionAllocation {
    std::vector<int> robotOfCell;    // by cell id
    std::vector<int> startCell;      // by robot: the cell holding its start
    std::vector<double> costSeconds; // by robot: the cover time of its cells
};

} // namespace mcpp
