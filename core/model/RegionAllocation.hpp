#pragma once

#include <vector>

namespace mcpp {

// Which robot covers each active cell. -1 marks a cell no robot can reach.
struct RegionAllocation {
    std::vector<int> robotOfCell;   // by active index
    std::vector<int> startCell;     // by robot: active index of the start cell
    std::vector<double> costSeconds; // by robot: sum of 2 * Cs / Sd over its cells
    int rebalanceMoves = 0;          // cells moved after growth
};

} // namespace mcpp
