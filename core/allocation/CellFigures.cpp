#include "core/allocation/CellFigures.hpp"

namespace mcpp {

CellFigures figuresOf(const Cell& cell) {
    return {cell.centreX(), cell.centreY(), cell.size * cell.size, cell.coverSeconds()};
}

std::vector<CellFigures> cellFiguresOf(const CellGraph& graph) {
    std::vector<CellFigures> figures(graph.size());
    for (std::size_t id = 0; id < figures.size(); ++id)
        figures[id] = figuresOf(graph.cell(static_cast<int>(id)));
    return figures;
}

} // namespace mcpp
