#include "core/decomposition/QuadTreeBuilder.hpp"

#include "core/decomposition/LandCoverCounter.hpp"
#include "core/decomposition/LandCoverSamples.hpp"
#include "core/decomposition/QuadTreeGridSize.hpp"
#include "core/model/Cell.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

// Past mostQuadTreeLevels (Cell.hpp) a cell's span would not fit its 16 bits.
[[noreturn]] void throwTooManyLevels(int levels) {
    throw PlanningError(Kind::InvalidClassTable,
                        "fields of view differ by a factor of 2^" + std::to_string(mostQuadTreeLevels) +
                            " or more; the quadtree would need " + std::to_string(levels) +
                            " levels, at most " + std::to_string(mostQuadTreeLevels) + " are planned");
}

} // namespace

QuadTree QuadTreeBuilder::build(const ClassGrid& grid, const ClassTable& classes,
                                const DecompositionOptions& options, const ProgressReporter& progress) const {
    checkDecompositionInputs(grid, classes, options);
    progress.report("quadtree", 0.0);

    PixelCodes pixels = codePixels(grid, classes);
    const auto& dense = pixels.classes;
    constexpr std::uint16_t outsideCode = PixelCodes::outside;
    constexpr std::uint16_t obstacleCode = PixelCodes::obstacle;
    progress.throwIfCancelled();

    QuadTree tree;
    tree.roundedFieldsOfView = roundFieldsOfView(classes, pixels.presentValues());
    if (tree.roundedFieldsOfView.empty())
        throw PlanningError(Kind::NoPassableCell,
                            "no passable land cover in the task area: every class present is "
                            "an obstacle (speed 0 or not passable)");
    int levels = 1;
    double fovMin = std::numeric_limits<double>::infinity();
    std::vector<int> levelOfCode(dense.size(), 0); // quadtree level each passable class needs
    for (const auto& rounded : tree.roundedFieldsOfView) {
        levels = std::max(levels, rounded.level);
        fovMin = std::min(fovMin, rounded.roundedMetres);
        for (std::size_t code = 0; code < dense.size(); ++code)
            if (dense[code].value == rounded.classValue)
                levelOfCode[code] = rounded.level;
    }
    // Past mostSizedLevels the grid's size in bottom cells would overflow; the budget's message, which says
    // what field of view fits, goes first for the rest.
    if (levels > mostSizedLevels)
        throwTooManyLevels(levels);
    tree.levels = levels;
    tree.fovMin = fovMin;
    const double bottomSize = 2.0 * fovMin;
    const QuadTreeGridSize size = quadTreeGridSize(grid.width(), grid.height(), fovMin, levels);
    tree.topCellSize = size.topCellSize;
    tree.originX = grid.originX;
    tree.originY = grid.originY;
    tree.topColumns = size.topColumns;
    tree.topRows = size.topRows;
    const std::int64_t bottomColumns = size.bottomColumns;
    const std::int64_t bottomRows = size.bottomRows;
    checkCellBudget(grid.width(), grid.height(), fovMin, levels, options.bytesPerBottomCell);
    if (levels > mostQuadTreeLevels)
        throwTooManyLevels(levels);
    const SampleGrid samples =
        sampleGrid(grid, std::move(pixels.codes), bottomSize, bottomColumns, bottomRows);
    const double sampleArea = samples.sampleWidth * samples.sampleHeight;
    progress.report("quadtree", 0.2);
    progress.throwIfCancelled();

    // Count samples per bottom cell by bucket: the level a passable sample needs (1..l), obstacle, outside.
    const int buckets = levels + 2;
    const int obstacleBucket = levels; // zero-based: levels 1..l are buckets 0..l-1
    const int outsideBucket = levels + 1;
    std::vector<int> bucketOfCode(dense.size());
    for (std::size_t code = 0; code < dense.size(); ++code)
        bucketOfCode[code] = dense[code].traversable ? levelOfCode[code] - 1 : obstacleBucket;
    std::vector<std::vector<std::uint32_t>> counts(static_cast<std::size_t>(levels));
    auto levelColumns = [&](int level) { return static_cast<std::size_t>(tree.topColumns) << (level - 1); };
    auto levelRows = [&](int level) { return static_cast<std::size_t>(tree.topRows) << (level - 1); };
    for (int level = 1; level <= levels; ++level)
        counts[static_cast<std::size_t>(level - 1)].assign(
            levelColumns(level) * levelRows(level) * static_cast<std::size_t>(buckets), 0U);
    {
        auto& bottom = counts[static_cast<std::size_t>(levels - 1)];
        const std::size_t columnsAtBottom = levelColumns(levels);
        std::vector<std::size_t> cellColumnOfSample(static_cast<std::size_t>(samples.columns));
        for (int column = 0; column < samples.columns; ++column) {
            const double x = samples.originX + (column + 0.5) * samples.sampleWidth;
            cellColumnOfSample[static_cast<std::size_t>(column)] =
                static_cast<std::size_t>(std::floor((x - tree.originX) / bottomSize));
        }
        for (int row = 0; row < samples.rows; ++row) {
            const double y = samples.originY - (row + 0.5) * samples.sampleHeight;
            const auto cellRow = static_cast<std::size_t>(std::floor((tree.originY - y) / bottomSize));
            const std::uint16_t* rowCodes =
                samples.codes.data() +
                static_cast<std::size_t>(row) * static_cast<std::size_t>(samples.columns);
            for (int column = 0; column < samples.columns; ++column) {
                const std::uint16_t code = rowCodes[column];
                const int bucket = code == outsideCode    ? outsideBucket
                                   : code == obstacleCode ? obstacleBucket
                                                          : bucketOfCode[code];
                const std::size_t cell =
                    cellRow * columnsAtBottom + cellColumnOfSample[static_cast<std::size_t>(column)];
                ++bottom[cell * static_cast<std::size_t>(buckets) + static_cast<std::size_t>(bucket)];
            }
        }
        for (int level = levels - 1; level >= 1; --level) {
            auto& parent = counts[static_cast<std::size_t>(level - 1)];
            const auto& child = counts[static_cast<std::size_t>(level)];
            const std::size_t parentColumns = levelColumns(level);
            const std::size_t childColumns = levelColumns(level + 1);
            for (std::size_t row = 0; row < levelRows(level); ++row) {
                for (std::size_t column = 0; column < parentColumns; ++column) {
                    std::uint32_t* target =
                        &parent[(row * parentColumns + column) * static_cast<std::size_t>(buckets)];
                    for (std::size_t dy = 0; dy < 2; ++dy) {
                        for (std::size_t dx = 0; dx < 2; ++dx) {
                            const std::uint32_t* source =
                                &child[((2 * row + dy) * childColumns + 2 * column + dx) *
                                       static_cast<std::size_t>(buckets)];
                            for (int b = 0; b < buckets; ++b)
                                target[b] += source[b];
                        }
                    }
                }
            }
        }
    }
    progress.report("quadtree", 0.5);
    progress.throwIfCancelled();

    // Top-down: split a cell while samples needing a deeper level, obstacles or outside area exceed the
    // tolerance.
    const double rasterMaxX = grid.maxX();
    const double rasterMinY = grid.minY();
    const double tolerance = options.purityTolerance;
    // Sets a cell's passable share and area, and whether it is blocked, active or split (auxiliary).
    auto judge = [&](QuadCell& cell) {
        const std::uint32_t* bucketCounts =
            &counts[static_cast<std::size_t>(cell.level - 1)]
                   [(static_cast<std::size_t>(cell.row) * levelColumns(cell.level) +
                     static_cast<std::size_t>(cell.column)) *
                    static_cast<std::size_t>(buckets)];
        std::uint64_t total = 0;
        std::uint64_t passable = 0;
        std::uint64_t deeper = 0;
        for (int b = 0; b < buckets; ++b) {
            total += bucketCounts[b];
            if (b < levels)
                passable += bucketCounts[b];
            if (b >= cell.level)
                deeper += bucketCounts[b]; // bucket b holds level b + 1
        }
        const double insideFraction = overlapLength(cell.minX, cell.maxX(), grid.originX, rasterMaxX) *
                                      overlapLength(cell.minY, cell.maxY(), rasterMinY, grid.originY) /
                                      (cell.size * cell.size);
        const double passableFraction =
            total == 0 ? 0.0 : insideFraction * static_cast<double>(passable) / static_cast<double>(total);
        const double obstacleFraction = 1.0 - passableFraction;
        cell.passableAreaSquareMetres = static_cast<double>(passable) * sampleArea;
        const double deeperFraction = total == 0 ? 1.0
                                                 : (1.0 - insideFraction) + insideFraction *
                                                                                static_cast<double>(deeper) /
                                                                                static_cast<double>(total);
        if (passable == 0)
            cell.state = CellState::Blocked;
        else if (cell.level == levels)
            cell.state = obstacleFraction > options.blockedThreshold ? CellState::Blocked : CellState::Active;
        else if (deeperFraction <= tolerance + 1e-12)
            cell.state = CellState::Active;
        else
            cell.state = CellState::Auxiliary;
    };
    auto topCell = [&](int row, int column) {
        QuadCell cell;
        cell.level = 1;
        cell.row = row;
        cell.column = column;
        cell.size = tree.topCellSize;
        cell.minX = tree.originX + column * tree.topCellSize;
        cell.minY = tree.originY - (row + 1) * tree.topCellSize;
        return cell;
    };
    // Child 0..3: north-west, north-east, south-east, south-west.
    auto childOf = [](const QuadCell& cell, int child) {
        const int dxs[4] = {0, 1, 1, 0};
        const int dys[4] = {0, 0, 1, 1};
        const double half = cell.size / 2.0;
        QuadCell childCell;
        childCell.level = cell.level + 1;
        childCell.row = cell.row * 2 + dys[child];
        childCell.column = cell.column * 2 + dxs[child];
        childCell.size = half;
        childCell.minX = cell.minX + dxs[child] * half;
        childCell.minY = cell.minY + (1 - dys[child]) * half;
        return childCell;
    };
    // Counted first so the cells take exactly their memory: growing the vector by doubling held up to
    // twice it, 3.5 GB on an 18 M-cell map.
    std::size_t cellCount = 0;
    std::size_t activeCount = 0;
    {
        std::vector<QuadCell> stack;
        for (int row = 0; row < tree.topRows; ++row) {
            progress.throwIfCancelled();
            for (int column = 0; column < tree.topColumns; ++column) {
                stack.push_back(topCell(row, column));
                while (!stack.empty()) {
                    QuadCell cell = stack.back();
                    stack.pop_back();
                    ++cellCount;
                    judge(cell);
                    activeCount += cell.state == CellState::Active ? 1 : 0;
                    if (cell.state == CellState::Auxiliary)
                        for (int child = 0; child < 4; ++child)
                            stack.push_back(childOf(cell, child));
                }
            }
        }
    }
    tree.cells.reserve(cellCount);
    tree.activeCells.reserve(activeCount);
    for (int row = 0; row < tree.topRows; ++row)
        for (int column = 0; column < tree.topColumns; ++column)
            tree.cells.push_back(topCell(row, column));
    std::vector<int> pending;
    for (int index = static_cast<int>(tree.cells.size()) - 1; index >= 0; --index)
        pending.push_back(index);
    while (!pending.empty()) {
        const int index = pending.back();
        pending.pop_back();
        QuadCell cell = tree.cells[static_cast<std::size_t>(index)];
        judge(cell);
        if (cell.state == CellState::Auxiliary) {
            cell.firstChild = static_cast<int>(tree.cells.size());
            for (int child = 0; child < 4; ++child)
                tree.cells.push_back(childOf(cell, child));
            for (int child = 3; child >= 0; --child)
                pending.push_back(cell.child(child));
        }
        if (cell.state == CellState::Active) {
            cell.activeIndex = static_cast<int>(tree.activeCells.size());
            tree.activeCells.push_back(index);
        }
        tree.cells[static_cast<std::size_t>(index)] = cell;
    }
    progress.report("quadtree", 0.8);
    progress.throwIfCancelled();

    // Land cover of each active cell: its majority passable class; speed: harmonic mean over passable
    // samples.
    double passableTotal = 0.0;
    for (const auto& cell : tree.cells)
        if (cell.state != CellState::Auxiliary)
            passableTotal += cell.passableAreaSquareMetres;
    tree.passableAreaSquareMetres = passableTotal;
    LandCoverCounter landCover(samples, dense);
    for (int cellIndex : tree.activeCells) {
        QuadCell& cell = tree.cells[static_cast<std::size_t>(cellIndex)];
        const LandCoverCounter::Result found = landCover.of(cell.minX, cell.maxX(), cell.minY, cell.maxY());
        cell.classValue = found.classValue;
        cell.speedMetresPerSecond = found.speedMetresPerSecond;
    }
    progress.report("quadtree", 1.0);
    return tree;
}

} // namespace mcpp
