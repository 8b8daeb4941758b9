#include "core/decomposition/LandCoverSamples.hpp"

#include "core/decomposition/QuadTreeGridSize.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

std::string describePair(double x, double y) {
    std::ostringstream text;
    text.precision(10);
    text << "(" << x << ", " << y << ")";
    return text.str();
}

std::string describeMetres(double metres) {
    std::ostringstream text;
    text.precision(6);
    text << metres;
    return text.str();
}

std::string describeGigabytes(std::int64_t bytes) {
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(1);
    text << static_cast<double>(bytes) / 1e9 << " GB";
    return text.str();
}

void checkGrid(const ClassGrid& grid) {
    if (grid.columns <= 0 || grid.rows <= 0)
        throw PlanningError(Kind::InvalidGrid, "the land-cover grid is empty (" +
                                                   std::to_string(grid.columns) + " x " +
                                                   std::to_string(grid.rows) + " pixels)");
    if (!(grid.pixelWidth > 0.0) || !(grid.pixelHeight > 0.0) || !std::isfinite(grid.pixelWidth) ||
        !std::isfinite(grid.pixelHeight))
        throw PlanningError(Kind::InvalidGrid, "pixel size must be a positive number of metres, got " +
                                                   describePair(grid.pixelWidth, grid.pixelHeight));
    if (!std::isfinite(grid.originX) || !std::isfinite(grid.originY))
        throw PlanningError(Kind::InvalidGrid,
                            "grid origin is not a number: " + describePair(grid.originX, grid.originY));
    const auto expected = static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows);
    if (grid.values.size() != expected)
        throw PlanningError(Kind::InvalidGrid, "grid holds " + std::to_string(grid.values.size()) +
                                                   " values for " + std::to_string(expected) + " pixels");
    if (!grid.outside.empty() && grid.outside.size() != expected)
        throw PlanningError(Kind::InvalidGrid, "outside mask holds " + std::to_string(grid.outside.size()) +
                                                   " values for " + std::to_string(expected) + " pixels");
}

} // namespace

std::vector<std::int32_t> PixelCodes::presentValues() const {
    std::vector<std::int32_t> values;
    for (const DenseClass& entry : classes)
        values.push_back(entry.value);
    return values;
}

void checkDecompositionInputs(const ClassGrid& grid, const ClassTable& classes,
                              const DecompositionOptions& options) {
    checkGrid(grid);
    if (auto problem = classes.validate())
        throw PlanningError(Kind::InvalidClassTable, *problem);
    if (!std::isfinite(options.purityTolerance) || options.purityTolerance < 0.0 ||
        options.purityTolerance >= 1.0)
        throw PlanningError(Kind::InvalidParameter, "purity tolerance must be in [0, 1), got " +
                                                        formatQuantity(options.purityTolerance));
    if (!std::isfinite(options.blockedThreshold) || options.blockedThreshold < 0.0 ||
        options.blockedThreshold > 1.0)
        throw PlanningError(Kind::InvalidParameter, "blocked threshold must be in [0, 1], got " +
                                                        formatQuantity(options.blockedThreshold));
}

PixelCodes codePixels(const ClassGrid& grid, const ClassTable& classes) {
    PixelCodes result;
    std::unordered_map<std::int32_t, std::uint16_t> codeOfValue;
    const std::size_t pixelCount = grid.values.size();
    result.codes.resize(pixelCount);
    std::int32_t lastValue = 0;
    std::uint16_t lastCode = PixelCodes::outside;
    bool haveLast = false;
    for (std::size_t i = 0; i < pixelCount; ++i) {
        if (!grid.outside.empty() && grid.outside[i] != 0) {
            result.codes[i] = PixelCodes::outside;
            continue;
        }
        const std::int32_t value = grid.values[i];
        if (!haveLast || value != lastValue) {
            auto found = codeOfValue.find(value);
            if (found == codeOfValue.end()) {
                const auto* landCoverClass = classes.find(value);
                if (landCoverClass == nullptr) {
                    const auto column = static_cast<int>(i % static_cast<std::size_t>(grid.columns));
                    const auto row = static_cast<int>(i / static_cast<std::size_t>(grid.columns));
                    throw PlanningError(Kind::InvalidClassTable,
                                        "raster value " + std::to_string(value) + " (first at column " +
                                            std::to_string(column) + ", row " + std::to_string(row) +
                                            ") has no row in the class table");
                }
                if (result.classes.size() >= PixelCodes::obstacle)
                    throw PlanningError(Kind::InvalidClassTable,
                                        "more than 65533 distinct classes in the raster");
                found = codeOfValue.emplace(value, static_cast<std::uint16_t>(result.classes.size())).first;
                result.classes.push_back(
                    {value, landCoverClass->isTraversable(), landCoverClass->speedMetresPerSecond});
            }
            lastValue = value;
            lastCode = found->second;
            haveLast = true;
        }
        result.codes[i] = result.classes[lastCode].traversable ? lastCode : PixelCodes::obstacle;
    }
    return result;
}

namespace {

// The window of the pixels whose entry (a code or an outside flag, row-major) is inside.
template <typename Entry, typename Inside>
PixelWindow windowOfEntries(const ClassGrid& grid, const std::vector<Entry>& entries, Inside inside) {
    PixelWindow window{grid.columns, grid.rows, 0, 0};
    for (int row = 0; row < grid.rows; ++row) {
        const Entry* begin = entries.data() + grid.index(0, row);
        const Entry* end = begin + grid.columns;
        const Entry* first = std::find_if(begin, end, inside);
        if (first == end)
            continue;
        const auto last =
            std::find_if(std::make_reverse_iterator(end), std::make_reverse_iterator(begin), inside);
        window.firstColumn = std::min(window.firstColumn, static_cast<int>(first - begin));
        window.endColumn = std::max(window.endColumn, static_cast<int>(last.base() - begin));
        window.firstRow = std::min(window.firstRow, row);
        window.endRow = row + 1;
    }
    if (window.endRow == 0)
        return {0, 0, grid.columns, grid.rows};
    return window;
}

} // namespace

PixelWindow pixelsInside(const ClassGrid& grid, const std::vector<std::uint16_t>& pixelCodes) {
    return windowOfEntries(grid, pixelCodes, [](std::uint16_t code) { return code != PixelCodes::outside; });
}

PixelWindow pixelsInside(const ClassGrid& grid) {
    if (grid.outside.empty())
        return {0, 0, grid.columns, grid.rows};
    // A flag other than 0 says why a pixel is outside.
    return windowOfEntries(grid, grid.outside, [](std::uint8_t flag) { return flag == 0; });
}

TopCellWindow topCellsOver(const QuadTreeGridSize& size, const ClassGrid& grid, const PixelWindow& land) {
    const auto topCellsTo = [&](double metres, int most, bool up) {
        const double cells = metres / size.topCellSize;
        return std::clamp(static_cast<int>(up ? std::ceil(cells - 1e-9) : std::floor(cells + 1e-9)), 0, most);
    };
    TopCellWindow window;
    window.firstColumn = topCellsTo(land.firstColumn * grid.pixelWidth, size.topColumns, false);
    window.firstRow = topCellsTo(land.firstRow * grid.pixelHeight, size.topRows, false);
    window.firstColumn -= window.firstColumn % 2;
    window.firstRow -= window.firstRow % 2;
    const int endColumn = topCellsTo(land.endColumn * grid.pixelWidth, size.topColumns, true);
    const int endRow = topCellsTo(land.endRow * grid.pixelHeight, size.topRows, true);
    window.columns = std::max(1, endColumn - window.firstColumn);
    window.rows = std::max(1, endRow - window.firstRow);
    return window;
}

SampleGrid sampleGrid(const ClassGrid& grid, std::vector<std::uint16_t>&& pixelCodes, double squareSize,
                      std::int64_t columns, std::int64_t rows, MapPoint corner) {
    SampleGrid samples;
    samples.originX = grid.originX;
    samples.originY = grid.originY;
    if (grid.pixelWidth <= squareSize * (1.0 + 1e-9) && grid.pixelHeight <= squareSize * (1.0 + 1e-9)) {
        samples.columns = grid.columns;
        samples.rows = grid.rows;
        samples.sampleWidth = grid.pixelWidth;
        samples.sampleHeight = grid.pixelHeight;
        samples.codes = std::move(pixelCodes);
        return samples;
    }
    samples.originX = corner.x;
    samples.originY = corner.y;
    samples.columns = static_cast<int>(columns);
    samples.rows = static_cast<int>(rows);
    samples.sampleWidth = squareSize;
    samples.sampleHeight = squareSize;
    samples.codes.assign(static_cast<std::size_t>(columns * rows), PixelCodes::outside);
    for (int row = 0; row < samples.rows; ++row) {
        const double y = corner.y - (row + 0.5) * squareSize;
        const auto pixelRow = static_cast<int>(std::floor((grid.originY - y) / grid.pixelHeight));
        if (pixelRow < 0 || pixelRow >= grid.rows)
            continue;
        for (int column = 0; column < samples.columns; ++column) {
            const double x = corner.x + (column + 0.5) * squareSize;
            const auto pixelColumn = static_cast<int>(std::floor((x - grid.originX) / grid.pixelWidth));
            if (pixelColumn < 0 || pixelColumn >= grid.columns)
                continue;
            samples.codes[static_cast<std::size_t>(row) * static_cast<std::size_t>(samples.columns) +
                          static_cast<std::size_t>(column)] = pixelCodes[grid.index(pixelColumn, pixelRow)];
        }
    }
    return samples;
}

CellBudgetEstimate estimateCellBudget(double width, double height, double fovMin, int levels,
                                      std::int64_t bytesPerCell) {
    // Counted in doubles: a field of view of micrometres makes more cells than 64 bits hold.
    const auto bottomCells = [&](double fov) {
        const QuadTreeGridSize size = quadTreeGridSize(width, height, fov, std::min(levels, mostSizedLevels));
        return static_cast<double>(size.bottomColumns) * static_cast<double>(size.bottomRows);
    };
    const auto saturated = [](double count) {
        return count < 9e18 ? static_cast<std::int64_t>(count) : std::numeric_limits<std::int64_t>::max();
    };
    const double cells =
        levels > mostSizedLevels ? std::numeric_limits<double>::infinity() : bottomCells(fovMin);
    CellBudgetEstimate estimate;
    estimate.bottomCells = saturated(cells);
    estimate.allowedBytes = memoryBudgetBytes();
    estimate.neededBytes = saturated(cells * static_cast<double>(bytesPerCell));
    estimate.fittingFieldOfView = fovMin;
    if (estimate.fits())
        return estimate;
    // One top cell is the least a quadtree of these levels makes: where even that does not fit, no FOV does
    // (fields of view far apart), and fittingFieldOfView stays 0.
    const double budget = static_cast<double>(estimate.allowedBytes);
    estimate.fittingFieldOfView = 0.0;
    if (levels > mostSizedLevels ||
        std::ldexp(1.0, 2 * (levels - 1)) * static_cast<double>(bytesPerCell) > budget)
        return estimate;
    // Cells shrink with the square of the field of view: the smallest FOV whose grid fits, rounded up.
    const auto step = [](double fov) { return std::pow(10.0, std::floor(std::log10(fov)) - 1.0); };
    double fitting = fovMin * std::sqrt(static_cast<double>(estimate.neededBytes) / budget);
    fitting = std::ceil(fitting / step(fitting)) * step(fitting); // two significant digits
    while (bottomCells(fitting) * static_cast<double>(bytesPerCell) > budget)
        fitting += step(fitting);
    estimate.fittingFieldOfView = fitting;
    return estimate;
}

void checkCellBudget(double width, double height, double fovMin, int levels, std::int64_t bytesPerCell) {
    // Said before any work starts, rather than failing for want of memory minutes later.
    const CellBudgetEstimate estimate = estimateCellBudget(width, height, fovMin, levels, bytesPerCell);
    if (estimate.fits())
        return;
    const QuadTreeGridSize size = quadTreeGridSize(width, height, fovMin, std::min(levels, mostSizedLevels));
    std::string remedy = "Not even one cell fits in the memory allowed";
    if (estimate.fittingFieldOfView > 0.0)
        remedy = "A smallest field of view of " + describeMetres(estimate.fittingFieldOfView) +
                 " m would fit: raise the field of view of the classes, or crop the raster";
    else if (levels > 1)
        remedy = "No field of view fits while the classes' fields of view need a quadtree of " +
                 std::to_string(levels) + " levels (a top cell spans " +
                 std::to_string(std::int64_t{1} << std::min(levels - 1, 62)) +
                 " bottom cells a side): bring them closer";
    throw PlanningError(Kind::InvalidParameter,
                        "the smallest field of view (" + describeMetres(fovMin) + " m) makes " +
                            std::to_string(size.bottomColumns) + " x " + std::to_string(size.bottomRows) +
                            " bottom cells, which need " + describeGigabytes(estimate.neededBytes) +
                            " of memory to plan; this machine allows " +
                            describeGigabytes(estimate.allowedBytes) + ". " + remedy);
}

double overlapLength(double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

std::pair<int, int> sampleRange(double low, double high, double origin, double step, int count) {
    const int first = std::clamp(static_cast<int>(std::ceil((low - origin) / step - 0.5)), 0, count);
    const int last = std::clamp(static_cast<int>(std::ceil((high - origin) / step - 0.5)), 0, count);
    return {first, last};
}

} // namespace mcpp
