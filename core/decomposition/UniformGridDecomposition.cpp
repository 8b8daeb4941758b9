#include "core/decomposition/UniformGridDecomposition.hpp"

#include "core/decomposition/FieldOfViewRounding.hpp"
#include "core/decomposition/GridNeighbours.hpp"
#include "core/decomposition/LandCoverCounter.hpp"
#include "core/decomposition/LandCoverSamples.hpp"
#include "core/decomposition/QuadTreeGridSize.hpp"
#include "core/model/CellRecord.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

// Samples counted per sub-cell: all of them, and the passable ones.
struct SubCellCounts {
    std::vector<std::uint32_t> total;
    std::vector<std::uint32_t> passable;
};

// The grid's geometry: cells of 2 x fovMin, sub-cells of fovMin, counted from the window's north-west corner.
struct GridShape {
    double cellSize = 0.0;
    int columns = 0;
    int rows = 0;
    [[nodiscard]] int subColumns() const { return 2 * columns; }
    [[nodiscard]] int subRows() const { return 2 * rows; }
};

// The sub-cell bit of SubCell order (NW, SW, SE, NE) for sub-cell (dx, dy) of a cell, dy 0 = north.
int subCellBit(int dx, int dy) {
    static constexpr int bits[2][2] = {{0, 3}, {1, 2}}; // [dy][dx]
    return bits[dy][dx];
}

SubCellCounts countSubCells(const SampleGrid& samples, const GridShape& shape, double originX,
                            double originY) {
    const double subSize = shape.cellSize / 2.0;
    const auto subColumns = static_cast<std::size_t>(shape.subColumns());
    SubCellCounts counts;
    counts.total.assign(subColumns * static_cast<std::size_t>(shape.subRows()), 0U);
    counts.passable.assign(counts.total.size(), 0U);
    // Samples off the grid (pixels beyond the window of cells round the task area, all outside) are left
    // out.
    constexpr std::size_t offGrid = std::numeric_limits<std::size_t>::max();
    const auto subIndex = [&](double offset, std::size_t count) {
        const double index = std::floor(offset / subSize);
        return index >= 0.0 && index < static_cast<double>(count) ? static_cast<std::size_t>(index) : offGrid;
    };
    std::vector<std::size_t> subColumnOfSample(static_cast<std::size_t>(samples.columns));
    for (int column = 0; column < samples.columns; ++column) {
        const double x = samples.originX + (column + 0.5) * samples.sampleWidth;
        subColumnOfSample[static_cast<std::size_t>(column)] = subIndex(x - originX, subColumns);
    }
    for (int row = 0; row < samples.rows; ++row) {
        const double y = samples.originY - (row + 0.5) * samples.sampleHeight;
        const std::size_t subRow = subIndex(originY - y, static_cast<std::size_t>(shape.subRows()));
        if (subRow == offGrid)
            continue;
        const std::uint16_t* codes = samples.row(row);
        for (int column = 0; column < samples.columns; ++column) {
            const std::size_t subColumn = subColumnOfSample[static_cast<std::size_t>(column)];
            if (subColumn == offGrid)
                continue;
            const std::size_t index = subRow * subColumns + subColumn;
            ++counts.total[index];
            if (codes[column] < PixelCodes::obstacle)
                ++counts.passable[index];
        }
    }
    return counts;
}

} // namespace

CellGraph UniformGridDecomposition::decompose(const ClassGrid& grid, const ClassTable& classes,
                                              const ProgressReporter& progress) const {
    checkDecompositionInputs(grid, classes, options_);
    progress.report("grid", 0.0);
    PixelCodes pixels = codePixels(grid, classes);
    const std::vector<RoundedFieldOfView> fieldsOfView = roundFieldsOfView(classes, pixels.presentValues());
    if (fieldsOfView.empty())
        throw PlanningError(Kind::NoPassableCell,
                            "no passable land cover in the task area: every class present is "
                            "an obstacle (speed 0 or not passable)");
    double fovMin = std::numeric_limits<double>::infinity();
    for (const auto& rounded : fieldsOfView)
        fovMin = std::min(fovMin, rounded.roundedMetres);
    // Cells over the task area's pixels only, on the raster's own grid of them (the quadtree's rule with one
    // level): a small area of interest in a large raster is planned in the memory its own extent needs.
    const QuadTreeGridSize size = quadTreeGridSize(grid.width(), grid.height(), fovMin, 1);
    const TopCellWindow window = topCellsOver(size, grid, pixelsInside(grid, pixels.codes));
    const GridShape shape{size.topCellSize, window.columns, window.rows};
    const MapPoint corner{grid.originX + window.firstColumn * shape.cellSize,
                          grid.originY - window.firstRow * shape.cellSize};
    checkCellBudget(shape.columns * shape.cellSize, shape.rows * shape.cellSize, fovMin, 1,
                    options_.bytesPerBottomCell);
    progress.throwIfCancelled();

    const std::vector<PixelCodes::DenseClass> dense = pixels.classes;
    const SampleGrid samples =
        sampleGrid(grid, std::move(pixels.codes), fovMin, shape.subColumns(), shape.subRows(), corner);
    const SubCellCounts counts = countSubCells(samples, shape, corner.x, corner.y);
    progress.report("grid", 0.4);
    progress.throwIfCancelled();

    const double subSize = fovMin;
    const double threshold = options_.blockedThreshold;
    // The share of a square that is passable: its passable samples, scaled by how much of it lies on the
    // raster.
    const auto passableShare = [&](double minX, double maxY, double side, std::uint64_t passable,
                                   std::uint64_t total) {
        const double inside = overlapLength(minX, minX + side, grid.originX, grid.maxX()) *
                              overlapLength(maxY - side, maxY, grid.minY(), grid.originY) / (side * side);
        return total == 0 ? 0.0 : inside * static_cast<double>(passable) / static_cast<double>(total);
    };

    GridFrame frame{corner.x, corner.y, shape.cellSize, shape.columns, shape.rows, 1};
    std::vector<Cell> cells;
    // What storing areas as floats changed, added to the total so that the cells never add up to more.
    double rounding = 0.0;
    LandCoverCounter landCover(samples, dense);
    for (int row = 0; row < shape.rows; ++row) {
        for (int column = 0; column < shape.columns; ++column) {
            std::uint8_t free = 0;
            std::uint64_t cellPassable = 0;
            std::uint64_t cellTotal = 0;
            std::uint64_t freePassable = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const std::size_t index = static_cast<std::size_t>(2 * row + dy) *
                                                  static_cast<std::size_t>(shape.subColumns()) +
                                              static_cast<std::size_t>(2 * column + dx);
                    cellPassable += counts.passable[index];
                    cellTotal += counts.total[index];
                    const double share =
                        passableShare(frame.x(column) + dx * subSize, frame.y(row) - dy * subSize, subSize,
                                      counts.passable[index], counts.total[index]);
                    if (1.0 - share <= threshold && counts.passable[index] > 0) {
                        free = static_cast<std::uint8_t>(free | (1U << subCellBit(dx, dy)));
                        freePassable += counts.passable[index];
                    }
                }
            const double cellShare =
                passableShare(frame.x(column), frame.y(row), shape.cellSize, cellPassable, cellTotal);
            bool kept = false;
            switch (rule_) {
            case GridCellRule::WholeCell:
                kept = cellPassable > 0 && 1.0 - cellShare <= threshold;
                free = allSubCells;
                freePassable = cellPassable;
                break;
            case GridCellRule::AllSubCellsFree:
                kept = free == allSubCells;
                break;
            case GridCellRule::AnySubCellFree:
                kept = free != 0;
                break;
            }
            if (!kept)
                continue;
            Cell cell;
            cell.column = column;
            cell.row = row;
            cell.span = 1;
            cell.level = 1;
            cell.minX = frame.x(column);
            cell.size = shape.cellSize;
            cell.minY = squareOf(frame, column, row, 1).minY; // as the graph works it out again
            cell.freeSubCells = free;
            const double area = static_cast<double>(freePassable) * samples.sampleArea();
            cell.passableAreaSquareMetres = static_cast<float>(area);
            rounding += double{cell.passableAreaSquareMetres} - area;
            const LandCoverCounter::Result found =
                landCover.of(cell.minX, cell.maxX(), cell.minY, cell.maxY());
            cell.classValue = found.classValue;
            cell.speedMetresPerSecond = found.speedMetresPerSecond;
            cells.push_back(cell);
        }
        if ((row & 63) == 0) {
            progress.throwIfCancelled();
            progress.report("grid", 0.4 + 0.5 * row / shape.rows);
        }
    }

    double passableSamples = 0.0;
    for (std::uint32_t count : counts.passable)
        passableSamples += count;
    NeighbourTopology adjacency = gridNeighbours(frame, cells);
    CellGraph graph(frame, cells, std::move(adjacency));
    graph.fieldsOfView = fieldsOfView;
    graph.passableAreaSquareMetres = passableSamples * samples.sampleArea() + rounding;
    progress.report("grid", 1.0);
    return graph;
}

} // namespace mcpp
