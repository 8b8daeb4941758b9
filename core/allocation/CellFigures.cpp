#include "core/allocation/CellFigures.hpp"

namespace mcpp {

std::vector<CellFigures> cellFiguresOf(const CellGraph& graph) {
    std::vector<CellFigures> figures(graph.size());
    for (std::size_t id = 0; id < figures.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        figures[id] = {cell.centreX(), cell.centreY(), cell.size * cell.size, cell.coverSeconds()};
    }
    return figures;
}

} // namespace mcpp
