#pragma once

#include "core/decomposition/DecompositionOptions.hpp"
#include "core/decomposition/QuadTreeGridSize.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace mcpp {

// Every pixel's land cover as a small code, so decompositions count classes without looking values up.
struct PixelCodes {
    static constexpr std::uint16_t outside = 65535;  // nodata or outside the task area
    static constexpr std::uint16_t obstacle = 65534; // a class robots cannot cross
    struct DenseClass {
        std::int32_t value = 0;
        bool traversable = false;
        double speed = 0.0;
    };
    std::vector<DenseClass> classes;  // by code, in order of first appearance
    std::vector<std::uint16_t> codes; // by pixel, row-major: a passable class's code, obstacle or outside

    [[nodiscard]] std::vector<std::int32_t> presentValues() const;
};

// A grid of samples over which cells count classes: the raster's pixels when they are no larger than the
// decomposition's squares, otherwise one sample at each square's centre (nearest neighbour).
struct SampleGrid {
    int columns = 0;
    int rows = 0;
    double originX = 0.0;
    double originY = 0.0;
    double sampleWidth = 1.0;
    double sampleHeight = 1.0;
    std::vector<std::uint16_t> codes; // PixelCodes' codes

    [[nodiscard]] double sampleArea() const { return sampleWidth * sampleHeight; }
    [[nodiscard]] const std::uint16_t* row(int index) const {
        return codes.data() + static_cast<std::size_t>(index) * static_cast<std::size_t>(columns);
    }
};

// Throws PlanningError when the grid is malformed, the table invalid or an option out of range.
void checkDecompositionInputs(const ClassGrid& grid, const ClassTable& classes,
                              const DecompositionOptions& options);
// Throws PlanningError naming the first raster value without a row in the table.
[[nodiscard]] PixelCodes codePixels(const ClassGrid& grid, const ClassTable& classes);
// Samples for a grid of columns x rows squares of `squareSize` metres whose north-west corner is `corner`
// (the raster origin, or a corner of a square of the raster's own grid of them); the pixel codes are moved in
// when the pixels themselves serve, all of them, at the raster's origin.
[[nodiscard]] SampleGrid sampleGrid(const ClassGrid& grid, std::vector<std::uint16_t>&& pixelCodes,
                                    double squareSize, std::int64_t columns, std::int64_t rows,
                                    MapPoint corner);
// The pixels [firstColumn, endColumn) x [firstRow, endRow) that hold every code not outside; all of the grid
// where every pixel is outside.
struct PixelWindow {
    int firstColumn = 0;
    int firstRow = 0;
    int endColumn = 0;
    int endRow = 0;
};
[[nodiscard]] PixelWindow pixelsInside(const ClassGrid& grid, const std::vector<std::uint16_t>& pixelCodes);
// The same by the grid's outside mask, for counting before any pixel is coded.
[[nodiscard]] PixelWindow pixelsInside(const ClassGrid& grid);
// The whole top cells of a quadtree of `size` over the raster that hold the window's pixels, the first column
// and row rounded down to even ones: the frame the quadtree is built in, and the memory guard counts.
struct TopCellWindow {
    int firstColumn = 0;
    int firstRow = 0;
    int columns = 1;
    int rows = 1;
};
[[nodiscard]] TopCellWindow topCellsOver(const QuadTreeGridSize& size, const ClassGrid& grid,
                                         const PixelWindow& land);
// What planning a map needs against memoryBudgetBytes(), and the smallest FOV whose grid over the same
// extent fits (two significant digits, rounded up).
struct CellBudgetEstimate {
    std::int64_t bottomCells = 0;
    std::int64_t neededBytes = 0;
    std::int64_t allowedBytes = 0;
    double fittingFieldOfView = 0.0; // the FOV itself when it fits; 0 when no FOV does
    [[nodiscard]] bool fits() const { return neededBytes <= allowedBytes; }
};
// A map of width x height metres planned on smallest cells of 2 x fovMin, as many as whole top cells of a
// quadtree of `levels` levels hold (1: a uniform grid), at bytesPerCell each (the planner's peak memory per
// smallest cell, PlannerDescription::bytesPerBottomCell). The fitting FOV is searched on the same grid:
// every FOV scaled alike keeps the levels.
[[nodiscard]] CellBudgetEstimate estimateCellBudget(double width, double height, double fovMin, int levels,
                                                    std::int64_t bytesPerCell);
// Throws PlanningError when that grid would need more memory than memoryBudgetBytes() allows, naming the
// FOV that makes it so and the smallest FOV that would fit.
void checkCellBudget(double width, double height, double fovMin, int levels, std::int64_t bytesPerCell);

// Length of the overlap of [a0, a1) and [b0, b1).
[[nodiscard]] double overlapLength(double a0, double a1, double b0, double b1);
// Index range [first, last) of samples whose centres lie in [low, high) along one axis.
[[nodiscard]] std::pair<int, int> sampleRange(double low, double high, double origin, double step, int count);

} // namespace mcpp
