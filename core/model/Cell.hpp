#pragma once

#include "core/model/BitCount.hpp"
#include "core/model/MapPoint.hpp"

#include <array>
#include <cstdint>
#include <limits>

namespace mcpp {

// The four sub-cells of a cell in the counter-clockwise order a coverage walk passes them.
enum class SubCell : std::uint8_t { NorthWest = 0, SouthWest = 1, SouthEast = 2, NorthEast = 3 };
inline constexpr std::array<SubCell, 4> subCellsCounterClockwise{SubCell::NorthWest, SubCell::SouthWest,
                                                                 SubCell::SouthEast, SubCell::NorthEast};
inline constexpr std::uint8_t allSubCells = 0b1111;

// The sub-cell in the east or west half and the south or north half of a cell.
[[nodiscard]] constexpr SubCell subCellOf(bool east, bool south) {
    if (south)
        return east ? SubCell::SouthEast : SubCell::SouthWest;
    return east ? SubCell::NorthEast : SubCell::NorthWest;
}

// How many sub-cells a mask of them holds (bitsSet: std::popcount is a library call on the baseline
// x86-64, and cells are counted this way millions of times).
[[nodiscard]] constexpr int subCellsIn(unsigned mask) {
    return static_cast<int>(bitsSet(mask));
}

// Whether a mask of free sub-cells holds `subCell` (Cell::isFree, and a CellRecord's freeSubCells).
[[nodiscard]] constexpr bool holdsSubCell(unsigned mask, SubCell subCell) {
    return (mask >> static_cast<unsigned>(subCell) & 1U) != 0;
}

// One square of a planning decomposition: a quadtree leaf, or a cell of a uniform grid. A robot covers it
// by passing the centres of its free sub-cells, whose side (half the cell's) is the robot's swath there.
// Levels a quadtree may have: its largest cells span 2^15 bottom cells, which Cell::span holds in 16 bits.
inline constexpr int mostQuadTreeLevels = 16;
inline constexpr int largestSpan = 1 << (mostQuadTreeLevels - 1);
// Turns a coverage walk makes per sub-cell where nothing was measured: 0.2 on the uniform benchmark grids
// with 15 % obstacles (26 965 turns over 135 000 sub-cells, 200 x 200 with 4 robots).
inline constexpr float defaultExpectedTurnsPerSubCell = 0.2F;

struct Cell {
    // Placement on the decomposition's bottom grid (squares of the smallest cell side), row 0 at the north.
    int column = 0;
    int row = 0;
    // Side in bottom cells: 2^15 at most, as a quadtree has at most mostQuadTreeLevels levels.
    std::uint16_t span = 1;
    std::uint8_t level = 1;                  // quadtree level, 1 = top; 1 for a single-level grid
    std::uint8_t freeSubCells = allSubCells; // bit i: sub-cell i (SubCell order) may be entered
    std::int32_t classValue = 0;             // majority passable land cover
    double minX = 0.0;
    double minY = 0.0;
    double size = 0.0;                    // side in metres
    float turnSecondsPer90Degrees = 0.0F; // what a turn costs here (CellGraph::applyTurnTime)
    // Harmonic mean over its passable pixels. A float, like its waypoints' speeds: seven digits are more
    // than any class table knows, and a large map holds tens of millions of cells and waypoints.
    float speedMetresPerSecond = 0.0F;
    // Turns a coverage walk makes here per sub-cell, for the cost; a planner may measure it on a first plan
    // (calibrateTurnRates).
    float expectedTurnsPerSubCell = defaultExpectedTurnsPerSubCell;
    // Passable pixels inside its free sub-cells. A float (seven digits): sums over cells are taken in
    // doubles.
    float passableAreaSquareMetres = 0.0F;

    [[nodiscard]] double maxX() const { return minX + size; }
    [[nodiscard]] double maxY() const { return minY + size; }
    [[nodiscard]] double centreX() const { return minX + size / 2.0; }
    [[nodiscard]] double centreY() const { return minY + size / 2.0; }
    [[nodiscard]] double fieldOfView() const { return size / 2.0; }
    [[nodiscard]] bool isFree(SubCell subCell) const { return holdsSubCell(freeSubCells, subCell); }
    [[nodiscard]] int freeSubCellCount() const { return subCellsIn(freeSubCells); }
    [[nodiscard]] MapPoint subCellCentre(SubCell subCell) const {
        const double quarter = size / 4.0;
        switch (subCell) {
        case SubCell::NorthWest:
            return {minX + quarter, maxY() - quarter};
        case SubCell::SouthWest:
            return {minX + quarter, minY + quarter};
        case SubCell::SouthEast:
            return {maxX() - quarter, minY + quarter};
        case SubCell::NorthEast:
            break;
        }
        return {maxX() - quarter, maxY() - quarter};
    }
    // The sub-cell a point inside the cell lies in.
    [[nodiscard]] SubCell subCellAt(MapPoint point) const {
        const bool east = point.x >= centreX();
        const bool north = point.y >= centreY();
        if (north)
            return east ? SubCell::NorthEast : SubCell::NorthWest;
        return east ? SubCell::SouthEast : SubCell::SouthWest;
    }
    // The area of its free sub-cells: what region and taken-over polygons cover of it.
    [[nodiscard]] double freeAreaSquareMetres() const { return size * size * freeSubCellCount() / 4.0; }
    // Seconds of travel to cover it (spec 4): a coverage walk passes each free sub-cell once, a quarter of
    // 2 x size. No walk covers the cell in less.
    [[nodiscard]] double travelSeconds() const {
        return 2.0 * size * (freeSubCellCount() / 4.0) / speedMetresPerSecond;
    }
    // Seconds to cover it, turns included at the rate coverage walks make them: the allocation's cost.
    [[nodiscard]] double coverSeconds() const {
        return travelSeconds() +
               double(expectedTurnsPerSubCell) * freeSubCellCount() * double(turnSecondsPer90Degrees);
    }
};
static_assert(sizeof(Cell) == 56);
static_assert(largestSpan <= std::numeric_limits<decltype(Cell::span)>::max());

} // namespace mcpp
