#include "core/decomposition/QuadTreeBuilder.hpp"

#include "core/decomposition/LandCoverCounter.hpp"
#include "core/decomposition/LandCoverSamples.hpp"
#include "core/decomposition/QuadTreeGridSize.hpp"
#include "core/model/Cell.hpp"
#include "core/model/CellRecord.hpp"
#include "core/model/ParallelFor.hpp"
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

// What the tree and the one-level grid are both made from: the tree's frame (no cells yet), the samples,
// and their counts per cell of every level by bucket: the level a passable sample needs (1..l), obstacle,
// outside.
struct SampleCounts {
    QuadTree frame;
    SampleGrid samples;
    std::vector<PixelCodes::DenseClass> classes;
    std::vector<std::vector<std::uint32_t>> byLevel;
    int buckets = 0;
    double sampleArea = 0.0;

    [[nodiscard]] std::size_t columnsAt(int level) const {
        return static_cast<std::size_t>(frame.topColumns) << (level - 1);
    }
    [[nodiscard]] std::size_t rowsAt(int level) const {
        return static_cast<std::size_t>(frame.topRows) << (level - 1);
    }
    [[nodiscard]] const std::uint32_t* of(int level, int row, int column) const {
        return &byLevel[static_cast<std::size_t>(level - 1)]
                       [(static_cast<std::size_t>(row) * columnsAt(level) +
                         static_cast<std::size_t>(column)) *
                        static_cast<std::size_t>(buckets)];
    }
};

// Adds each cell's children's counts into it, from the level above the bottom up to the top.
void addUpLevels(SampleCounts& counts) {
    const auto buckets = static_cast<std::size_t>(counts.buckets);
    for (int level = counts.frame.levels - 1; level >= 1; --level) {
        auto& parent = counts.byLevel[static_cast<std::size_t>(level - 1)];
        const auto& child = counts.byLevel[static_cast<std::size_t>(level)];
        const std::size_t parentColumns = counts.columnsAt(level);
        const std::size_t childColumns = counts.columnsAt(level + 1);
        for (std::size_t row = 0; row < counts.rowsAt(level); ++row) {
            for (std::size_t column = 0; column < parentColumns; ++column) {
                std::uint32_t* target = &parent[(row * parentColumns + column) * buckets];
                for (std::size_t dy = 0; dy < 2; ++dy) {
                    for (std::size_t dx = 0; dx < 2; ++dx) {
                        const std::uint32_t* source =
                            &child[((2 * row + dy) * childColumns + 2 * column + dx) * buckets];
                        for (std::size_t b = 0; b < buckets; ++b)
                            target[b] += source[b];
                    }
                }
            }
        }
    }
}

// Counts the bottom cells' samples by bucket, then every level's.
void countBuckets(SampleCounts& counts, const std::vector<int>& levelOfCode) {
    const int levels = counts.frame.levels;
    const int obstacleBucket = levels; // zero-based: levels 1..l are buckets 0..l-1
    const int outsideBucket = levels + 1;
    std::vector<int> bucketOfCode(counts.classes.size());
    for (std::size_t code = 0; code < counts.classes.size(); ++code)
        bucketOfCode[code] = counts.classes[code].traversable ? levelOfCode[code] - 1 : obstacleBucket;
    counts.byLevel.resize(static_cast<std::size_t>(levels));
    for (int level = 1; level <= levels; ++level)
        counts.byLevel[static_cast<std::size_t>(level - 1)].assign(
            counts.columnsAt(level) * counts.rowsAt(level) * static_cast<std::size_t>(counts.buckets), 0U);
    auto& bottom = counts.byLevel[static_cast<std::size_t>(levels - 1)];
    const std::size_t columnsAtBottom = counts.columnsAt(levels);
    const SampleGrid& samples = counts.samples;
    const double bottomSize = 2.0 * counts.frame.fovMin;
    // Samples off the tree's frame (pixels beyond the window of top cells round the land, all outside) are
    // left out.
    constexpr std::size_t offFrame = std::numeric_limits<std::size_t>::max();
    const auto bottomIndex = [&](double offset, std::size_t count) {
        const double index = std::floor(offset / bottomSize);
        return index >= 0.0 && index < static_cast<double>(count) ? static_cast<std::size_t>(index)
                                                                  : offFrame;
    };
    std::vector<std::size_t> cellColumnOfSample(static_cast<std::size_t>(samples.columns));
    for (int column = 0; column < samples.columns; ++column) {
        const double x = samples.originX + (column + 0.5) * samples.sampleWidth;
        cellColumnOfSample[static_cast<std::size_t>(column)] =
            bottomIndex(x - counts.frame.originX, columnsAtBottom);
    }
    for (int row = 0; row < samples.rows; ++row) {
        const double y = samples.originY - (row + 0.5) * samples.sampleHeight;
        const std::size_t cellRow = bottomIndex(counts.frame.originY - y, counts.rowsAt(levels));
        if (cellRow == offFrame)
            continue;
        const std::uint16_t* rowCodes = samples.row(row);
        for (int column = 0; column < samples.columns; ++column) {
            if (cellColumnOfSample[static_cast<std::size_t>(column)] == offFrame)
                continue;
            const std::uint16_t code = rowCodes[column];
            const int bucket = code == PixelCodes::outside    ? outsideBucket
                               : code == PixelCodes::obstacle ? obstacleBucket
                                                              : bucketOfCode[code];
            const std::size_t cell =
                cellRow * columnsAtBottom + cellColumnOfSample[static_cast<std::size_t>(column)];
            ++bottom[cell * static_cast<std::size_t>(counts.buckets) + static_cast<std::size_t>(bucket)];
        }
    }
    addUpLevels(counts);
}

// The top cells the tree is made of: those over the land inside the map (its area, its data), not all of a
// raster of which an area of interest keeps a corner (a 3.5 km square of a 47 x 33 km raster: 15 M bottom
// cells sampled and counted for the 0.12 M the area holds). Whole top cells of the raster's own grid of them,
// from an even one (level-1 rows and columns keep their parity), so the cells are those the whole grid makes.
void placeFrame(QuadTree& tree, const QuadTreeGridSize& size, const ClassGrid& grid,
                const TopCellWindow& window) {
    tree.topCellSize = size.topCellSize;
    tree.originX = grid.originX + window.firstColumn * size.topCellSize;
    tree.originY = grid.originY - window.firstRow * size.topCellSize;
    tree.topColumns = window.columns;
    tree.topRows = window.rows;
}

// The tree's frame from the class table's rounded FOVs, and the samples counted per cell of every level.
SampleCounts countSamples(const ClassGrid& grid, const ClassTable& classes,
                          const DecompositionOptions& options, const ProgressReporter& progress) {
    checkDecompositionInputs(grid, classes, options);
    progress.report("quadtree", 0.0);

    PixelCodes pixels = codePixels(grid, classes);
    progress.throwIfCancelled();

    SampleCounts counts;
    QuadTree& tree = counts.frame;
    tree.roundedFieldsOfView = roundFieldsOfView(classes, pixels.presentValues());
    if (tree.roundedFieldsOfView.empty())
        throw PlanningError(Kind::NoPassableCell,
                            "no passable land cover in the task area: every class present is "
                            "an obstacle (speed 0 or not passable)");
    int levels = 1;
    double fovMin = std::numeric_limits<double>::infinity();
    std::vector<int> levelOfCode(pixels.classes.size(), 0); // quadtree level each passable class needs
    for (const auto& rounded : tree.roundedFieldsOfView) {
        levels = std::max(levels, rounded.level);
        fovMin = std::min(fovMin, rounded.roundedMetres);
        for (std::size_t code = 0; code < pixels.classes.size(); ++code)
            if (pixels.classes[code].value == rounded.classValue)
                levelOfCode[code] = rounded.level;
    }
    // Past mostSizedLevels the grid's size in bottom cells would overflow; the budget's message, which says
    // what field of view fits, goes first for the rest.
    if (levels > mostSizedLevels)
        throwTooManyLevels(levels);
    tree.levels = levels;
    tree.fovMin = fovMin;
    const QuadTreeGridSize size = quadTreeGridSize(grid.width(), grid.height(), fovMin, levels);
    // Counted over the top cells that hold the land, as the tree is built: a small area of interest in a
    // large raster is planned in the memory its own extent needs.
    const TopCellWindow window = topCellsOver(size, grid, pixelsInside(grid, pixels.codes));
    checkCellBudget(window.columns * size.topCellSize, window.rows * size.topCellSize, fovMin, levels,
                    options.bytesPerBottomCell);
    if (levels > mostQuadTreeLevels)
        throwTooManyLevels(levels);
    placeFrame(tree, size, grid, window);
    counts.classes = pixels.classes;
    const std::int64_t bottomPerTop = std::int64_t{1} << (levels - 1);
    counts.samples = sampleGrid(grid, std::move(pixels.codes), 2.0 * fovMin, tree.topColumns * bottomPerTop,
                                tree.topRows * bottomPerTop, {tree.originX, tree.originY});
    counts.sampleArea = counts.samples.sampleWidth * counts.samples.sampleHeight;
    progress.report("quadtree", 0.2);
    progress.throwIfCancelled();

    counts.buckets = levels + 2;
    countBuckets(counts, levelOfCode);
    progress.report("quadtree", 0.5);
    progress.throwIfCancelled();
    return counts;
}

// A cell's verdict: blocked, active or split (auxiliary), with the area of its passable samples. Split while
// samples needing a deeper level, obstacles or outside area exceed the tolerance.
struct Verdict {
    CellState state = CellState::Blocked;
    double passableAreaSquareMetres = 0.0;
};

Verdict judge(const SampleCounts& counts, const ClassGrid& grid, const DecompositionOptions& options,
              int level, int row, int column, double minX, double minY, double size) {
    const int levels = counts.frame.levels;
    const std::uint32_t* bucketCounts = counts.of(level, row, column);
    std::uint64_t total = 0;
    std::uint64_t passable = 0;
    std::uint64_t deeper = 0;
    for (int b = 0; b < counts.buckets; ++b) {
        total += bucketCounts[b];
        if (b < levels)
            passable += bucketCounts[b];
        if (b >= level)
            deeper += bucketCounts[b]; // bucket b holds level b + 1
    }
    const double insideFraction = overlapLength(minX, minX + size, grid.originX, grid.maxX()) *
                                  overlapLength(minY, minY + size, grid.minY(), grid.originY) / (size * size);
    const double passableFraction =
        total == 0 ? 0.0 : insideFraction * static_cast<double>(passable) / static_cast<double>(total);
    const double obstacleFraction = 1.0 - passableFraction;
    Verdict verdict;
    verdict.passableAreaSquareMetres = static_cast<double>(passable) * counts.sampleArea;
    const double deeperFraction = total == 0 ? 1.0
                                             : (1.0 - insideFraction) + insideFraction *
                                                                            static_cast<double>(deeper) /
                                                                            static_cast<double>(total);
    if (passable == 0)
        verdict.state = CellState::Blocked;
    else if (level == levels)
        verdict.state = obstacleFraction > options.blockedThreshold ? CellState::Blocked : CellState::Active;
    else if (deeperFraction <= options.purityTolerance + 1e-12)
        verdict.state = CellState::Active;
    else
        verdict.state = CellState::Auxiliary;
    return verdict;
}

// The tree, top-down from the top cells: each split cell's four children follow it.
QuadTree growTree(const SampleCounts& counts, const ClassGrid& grid, const DecompositionOptions& options,
                  const ProgressReporter& progress) {
    QuadTree tree = counts.frame; // copied: judging reads the frame's levels and top grid
    const auto judgeCell = [&](QuadCell& cell) {
        const Verdict verdict =
            judge(counts, grid, options, cell.level, cell.row, cell.column, cell.minX, cell.minY, cell.size);
        cell.state = verdict.state;
        cell.passableAreaSquareMetres = verdict.passableAreaSquareMetres;
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
                    judgeCell(cell);
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
        judgeCell(cell);
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
    LandCoverCounter landCover(counts.samples, counts.classes);
    for (int cellIndex : tree.activeCells) {
        QuadCell& cell = tree.cells[static_cast<std::size_t>(cellIndex)];
        const LandCoverCounter::Result found = landCover.of(cell.minX, cell.maxX(), cell.minY, cell.maxY());
        cell.classValue = found.classValue;
        cell.speedMetresPerSecond = found.speedMetresPerSecond;
    }
    progress.report("quadtree", 1.0);
    return tree;
}

// One band of a one-level tree's rows, judged on its own thread: its active cells row by row, and the
// passable area of every cell that has some, in the same order, for the caller to add up.
struct GridBand {
    std::vector<CellRecord> cells;
    std::vector<double> passableAreas;
    std::vector<double> areaRoundings; // of each active cell's area kept as a float
};

GridBand judgeBand(const SampleCounts& counts, const ClassGrid& grid, const DecompositionOptions& options,
                   const GridFrame& frame, int firstRow, int endRow) {
    GridBand band;
    LandCoverCounter landCover(counts.samples, counts.classes);
    for (int row = firstRow; row < endRow; ++row) {
        for (int column = 0; column < frame.columns; ++column) {
            const CellSquare square = squareOf(frame, column, row, 1);
            const Verdict verdict =
                judge(counts, grid, options, 1, row, column, square.minX, square.minY, square.size);
            if (verdict.passableAreaSquareMetres != 0.0)
                band.passableAreas.push_back(verdict.passableAreaSquareMetres);
            if (verdict.state != CellState::Active)
                continue;
            CellRecord cell;
            cell.column = column;
            cell.row = row;
            cell.passableAreaSquareMetres = static_cast<float>(verdict.passableAreaSquareMetres);
            band.areaRoundings.push_back(double{cell.passableAreaSquareMetres} -
                                         verdict.passableAreaSquareMetres);
            const LandCoverCounter::Result found =
                landCover.of(square.minX, square.minX + square.size, square.minY, square.minY + square.size);
            cell.classValue = found.classValue;
            cell.speedMetresPerSecond = static_cast<float>(found.speedMetresPerSecond);
            band.cells.push_back(cell);
        }
    }
    return band;
}

// The grid of a one-level tree's cells, each as cellGraphOfQuadTree would make it of the leaf, row by row.
// Bands of rows are judged side by side, a few at a time, and joined in order: the areas are added up in
// the order of one thread, so the figures are the same whatever the number of threads.
OneLevelQuadTree gridOfBottomCells(const SampleCounts& counts, const ClassGrid& grid,
                                   const DecompositionOptions& options, const ProgressReporter& progress) {
    constexpr int rowsPerBand = 64;
    constexpr double cellsForBands = 1 << 20;
    const QuadTree& tree = counts.frame;
    OneLevelQuadTree result;
    result.frame = {tree.originX, tree.originY, 2.0 * tree.fovMin, tree.topColumns, tree.topRows, 1};
    result.roundedFieldsOfView = tree.roundedFieldsOfView;
    // Room for every bottom cell, of which only the pages the active cells fill become resident: no copy
    // as the vector grows.
    result.cells.reserve(static_cast<std::size_t>(tree.topRows) * static_cast<std::size_t>(tree.topColumns));
    // Small grids in one band: starting threads would cost more than they save.
    const bool large = static_cast<double>(tree.topRows) * tree.topColumns >= cellsForBands;
    const auto bandsAtOnce = static_cast<std::size_t>(large ? std::max(1, workerThreads()) : 1);
    std::vector<GridBand> bands(bandsAtOnce);
    for (int firstRow = 0; firstRow < tree.topRows; firstRow += rowsPerBand * static_cast<int>(bandsAtOnce)) {
        progress.throwIfCancelled();
        parallelFor(bandsAtOnce, [&](std::size_t band, int) {
            const int from = firstRow + rowsPerBand * static_cast<int>(band);
            bands[band] = from < tree.topRows ? judgeBand(counts, grid, options, result.frame, from,
                                                          std::min(tree.topRows, from + rowsPerBand))
                                              : GridBand{};
        });
        for (const GridBand& band : bands) {
            for (const double area : band.passableAreas)
                result.passableAreaSquareMetres += area;
            for (const double rounding : band.areaRoundings)
                result.areaRounding += rounding;
            result.cells.insert(result.cells.end(), band.cells.begin(), band.cells.end());
        }
        progress.report("quadtree", 0.5 + 0.5 * firstRow / tree.topRows);
    }
    progress.report("quadtree", 1.0);
    return result;
}

} // namespace

QuadTree QuadTreeBuilder::build(const ClassGrid& grid, const ClassTable& classes,
                                const DecompositionOptions& options, const ProgressReporter& progress) const {
    return growTree(countSamples(grid, classes, options, progress), grid, options, progress);
}

QuadTreeLeaves QuadTreeBuilder::buildLeaves(const ClassGrid& grid, const ClassTable& classes,
                                            const DecompositionOptions& options,
                                            const ProgressReporter& progress) const {
    const SampleCounts counts = countSamples(grid, classes, options, progress);
    if (counts.frame.levels == 1)
        return gridOfBottomCells(counts, grid, options, progress);
    return growTree(counts, grid, options, progress);
}

} // namespace mcpp
