#include "core/outlines/RegionLabels.hpp"

#include "core/outlines/OutlineTracer.hpp"
#include "core/outlines/RegionOutlines.hpp"

#include <algorithm>

namespace mcpp {

namespace {

// Fills the pixels of one free sub-cell: a square of span x span pixels of the sub-cell grid.
void fillSubCell(LabelGrid& grid, const Cell& cell, SubCell subCell, std::int32_t label) {
    const bool east = subCell == SubCell::NorthEast || subCell == SubCell::SouthEast;
    const bool south = subCell == SubCell::SouthWest || subCell == SubCell::SouthEast;
    const int firstColumn = 2 * cell.column + (east ? cell.span : 0);
    const int firstRow = 2 * cell.row + (south ? cell.span : 0);
    for (int row = firstRow; row < firstRow + cell.span; ++row) {
        const auto begin = grid.labels.begin() + static_cast<std::ptrdiff_t>(grid.index(firstColumn, row));
        std::fill(begin, begin + cell.span, label);
    }
}

} // namespace

LabelGrid regionLabels(const Plan& plan) {
    const CellGraph& graph = plan.cells;
    const GridFrame& frame = graph.frame();
    int columns = frame.columns;
    int rows = frame.rows;
    for (const Cell& cell : graph.cells()) {
        columns = std::max(columns, cell.column + cell.span);
        rows = std::max(rows, cell.row + cell.span);
    }
    LabelGrid grid;
    grid.columns = 2 * columns;
    grid.rows = 2 * rows;
    grid.originX = frame.originX;
    grid.originY = frame.originY;
    grid.pixelSize = frame.bottomCellSize / 2.0;
    grid.labels.assign(static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows),
                       LabelGrid::noLabel);
    const auto& owner = plan.regions.robotOfCell;
    for (std::size_t id = 0; id < owner.size() && id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        const std::int32_t label = owner[id] >= 0 ? owner[id] : unreachableLabel;
        for (const SubCell subCell : subCellsCounterClockwise) {
            if (cell.isFree(subCell))
                fillSubCell(grid, cell, subCell, label);
        }
    }
    return grid;
}

RegionOutlines regionOutlines(const Plan& plan) {
    RegionOutlines outlines;
    outlines.labels = regionLabels(plan);
    outlines.polygons = traceOutlines(outlines.labels);
    return outlines;
}

} // namespace mcpp
