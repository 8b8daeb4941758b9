#pragma once

#include "core/model/Cell.hpp"
#include "core/model/GridFrame.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace mcpp {

// What a cell graph stores of a cell: everything but its square, which follows from its placement on the
// frame's bottom grid, and its turn figures, which the graph keeps beside (CellTurnFigures). 24 bytes
// instead of Cell's 56: 2.2 GB less on a map of 69 million cells.
struct CellRecord {
    int column = 0;
    int row = 0;
    std::uint16_t span = 1;
    std::uint8_t level = 1;
    std::uint8_t freeSubCells = allSubCells;
    std::int32_t classValue = 0;
    float speedMetresPerSecond = 0.0F;
    float passableAreaSquareMetres = 0.0F;
};
static_assert(sizeof(CellRecord) == 24);

// The square of a cell placed at (column, row) on the frame's bottom grid, worked out as the quadtree
// builder places its cells: its top cell from the origin, then each level's child from its parent, half a
// side over. Bit for bit the same, so a cell's points meet its neighbours' exactly, as walks expect.
struct CellSquare {
    double minX = 0.0;
    double minY = 0.0;
    double size = 0.0;
};
[[nodiscard]] inline CellSquare squareOf(const GridFrame& frame, int column, int row, int span) {
    if (frame.levels == 1 && span == 1) [[likely]] // a grid: every cell is a top cell
        return {frame.originX + column * frame.bottomCellSize,
                frame.originY - (row + 1) * frame.bottomCellSize, frame.bottomCellSize};
    const int spanShift = std::countr_zero(static_cast<unsigned>(span));
    const int topShift = std::max(frame.levels - 1, spanShift);
    double size = frame.bottomCellSize * static_cast<double>(1U << static_cast<unsigned>(topShift)); // exact
    CellSquare square{frame.originX + (column >> topShift) * size,
                      frame.originY - ((row >> topShift) + 1) * size, size};
    for (int shift = topShift - 1; shift >= spanShift; --shift) {
        size /= 2.0;
        square.minX += ((column >> shift) & 1) * size;
        square.minY += (1 - ((row >> shift) & 1)) * size;
    }
    square.size = size;
    return square;
}

[[nodiscard]] inline CellRecord recordOf(const Cell& cell) {
    return {cell.column,
            cell.row,
            cell.span,
            cell.level,
            cell.freeSubCells,
            cell.classValue,
            cell.speedMetresPerSecond,
            cell.passableAreaSquareMetres};
}

// The cell whole, its turn figures given.
[[nodiscard]] inline Cell cellOf(const CellRecord& record, const GridFrame& frame, float turnSeconds,
                                 float expectedTurns) {
    Cell cell;
    cell.column = record.column;
    cell.row = record.row;
    cell.span = record.span;
    cell.level = record.level;
    cell.freeSubCells = record.freeSubCells;
    cell.classValue = record.classValue;
    const CellSquare square = squareOf(frame, record.column, record.row, record.span);
    cell.minX = square.minX;
    cell.minY = square.minY;
    cell.size = square.size;
    cell.turnSecondsPer90Degrees = turnSeconds;
    cell.speedMetresPerSecond = record.speedMetresPerSecond;
    cell.expectedTurnsPerSubCell = expectedTurns;
    cell.passableAreaSquareMetres = record.passableAreaSquareMetres;
    return cell;
}

} // namespace mcpp
