#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// A connected part of the cell graph that holds robots' start cells: its cells, starts' part first, and
// its robots in robot order.
struct StartComponent {
    std::vector<int> cells;
    std::vector<int> robots;
};

// The parts of the graph reached from the starts, in order of their first robot. Cells no start reaches
// are in none.
[[nodiscard]] std::vector<StartComponent> componentsWithStarts(const CellGraph& graph,
                                                               const std::vector<int>& startCells);

// Whether the robots' regions are all linked, region touching region: then every start cell
// (regions.startCell) lies in one connected part, for each robot's cells lie in its start's part (regions
// grow from the start cells, and paths walk them) and cells that touch lie in one part. False also where a
// robot has no cells; componentsWithStarts then tells.
[[nodiscard]] bool regionsLinkEveryRobot(const CellGraph& graph, const RegionAllocation& regions);

} // namespace mcpp
