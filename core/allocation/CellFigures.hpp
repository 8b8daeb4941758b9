#pragma once

#include "core/model/CellGraph.hpp"

#include <vector>

namespace mcpp {

// What growing regions reads of a cell (or of a block of cells), side by side: taking one reads all four,
// weighing one its centre.
struct CellFigures {
    double x = 0.0; // centre (area-weighted for a block)
    double y = 0.0;
    double area = 0.0;
    double cost = 0.0; // seconds to cover it
};

// One cell's figures.
[[nodiscard]] CellFigures figuresOf(const Cell& cell);

// The figures of every cell of the graph, by cell id.
[[nodiscard]] std::vector<CellFigures> cellFiguresOf(const CellGraph& graph);

} // namespace mcpp
