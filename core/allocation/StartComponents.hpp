#pragma once

#include "core/model/CellGraph.hpp"

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

} // namespace mcpp
