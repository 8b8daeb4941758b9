#pragma once

#include "core/model/CellGraph.hpp"

#include <vector>

namespace mcpp {

// MDSTC's first division (seed 003): every region starts at its robot's cell and the regions take turns
// to claim a cell next to them, the one with the least cover time so far first, nearest cells first, until
// no cell is left that a region touches. Returns the robot of each cell, -1 where none reaches.
[[nodiscard]] std::vector<int> expandRegions(const CellGraph& graph, const std::vector<int>& startCells);

} // namespace mcpp
