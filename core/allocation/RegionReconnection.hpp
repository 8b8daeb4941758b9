#pragma once

#include "core/model/CellGraph.hpp"

#include <vector>

namespace mcpp {

// Makes every region one piece holding its robot's start: cells a region's start does not reach through
// the region go to the region that reaches them first, through cells left to nobody. Cells that no start
// reaches stay nobody's (-1). robotOfCell is by cell id; startCells by robot.
void reconnectRegions(const CellGraph& graph, const std::vector<int>& startCells,
                      std::vector<int>& robotOfCell);

} // namespace mcpp
