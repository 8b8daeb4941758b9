#include "core/decomposition/LandCoverSamples.hpp"

#include "core/model/HumanUnits.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
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

SampleGrid sampleGrid(const ClassGrid& grid, std::vector<std::uint16_t>&& pixelCodes, double squareSize,
                      std::int64_t columns, std::int64_t rows) {
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
    samples.columns = static_cast<int>(columns);
    samples.rows = static_cast<int>(rows);
    samples.sampleWidth = squareSize;
    samples.sampleHeight = squareSize;
    samples.codes.assign(static_cast<std::size_t>(columns * rows), PixelCodes::outside);
    for (int row = 0; row < samples.rows; ++row) {
        const double y = grid.originY - (row + 0.5) * squareSize;
        const auto pixelRow = static_cast<int>(std::floor((grid.originY - y) / grid.pixelHeight));
        if (pixelRow < 0 || pixelRow >= grid.rows)
            continue;
        for (int column = 0; column < samples.columns; ++column) {
            const double x = grid.originX + (column + 0.5) * squareSize;
            const auto pixelColumn = static_cast<int>(std::floor((x - grid.originX) / grid.pixelWidth));
            if (pixelColumn < 0 || pixelColumn >= grid.columns)
                continue;
            samples.codes[static_cast<std::size_t>(row) * static_cast<std::size_t>(samples.columns) +
                          static_cast<std::size_t>(column)] = pixelCodes[grid.index(pixelColumn, pixelRow)];
        }
    }
    return samples;
}

CellBudgetEstimate estimateCellBudget(double fovMin, std::int64_t columns, std::int64_t rows) {
    CellBudgetEstimate estimate;
    estimate.bottomCells = columns * rows;
    estimate.allowedBytes = memoryBudgetBytes();
    estimate.neededBytes = estimate.bottomCells * bytesPerBottomCell;
    estimate.fittingFieldOfView = fovMin;
    if (estimate.fits())
        return estimate;
    // Cells shrink with the square of the field of view: the smallest FOV whose grid fits, rounded up.
    const double width = static_cast<double>(columns) * 2.0 * fovMin;
    const double height = static_cast<double>(rows) * 2.0 * fovMin;
    const double budget = static_cast<double>(estimate.allowedBytes);
    double fitting = fovMin * std::sqrt(static_cast<double>(estimate.neededBytes) / budget);
    const auto fits = [&](double fov) {
        const double cells = std::ceil(width / (2.0 * fov)) * std::ceil(height / (2.0 * fov));
        return cells * static_cast<double>(bytesPerBottomCell) <= budget;
    };
    const double step = std::pow(10.0, std::floor(std::log10(fitting)) - 1.0); // two significant digits
    fitting = std::ceil(fitting / step) * step;
    while (!fits(fitting))
        fitting += step;
    estimate.fittingFieldOfView = fitting;
    return estimate;
}

CellBudgetEstimate estimateCellBudgetForExtent(double width, double height, double fovMin) {
    const auto cells = [fovMin](double length) {
        return std::max<std::int64_t>(1,
                                      static_cast<std::int64_t>(std::ceil(length / (2.0 * fovMin) - 1e-9)));
    };
    return estimateCellBudget(fovMin, cells(width), cells(height));
}

void checkCellBudget(double fovMin, std::int64_t columns, std::int64_t rows) {
    // Said before any work starts, rather than failing for want of memory minutes later.
    const CellBudgetEstimate estimate = estimateCellBudget(fovMin, columns, rows);
    if (estimate.fits())
        return;
    throw PlanningError(Kind::InvalidParameter,
                        "the smallest field of view (" + describeMetres(fovMin) + " m) makes " +
                            std::to_string(columns) + " x " + std::to_string(rows) +
                            " bottom cells, which need " + describeGigabytes(estimate.neededBytes) +
                            " of memory to plan; this machine allows " +
                            describeGigabytes(estimate.allowedBytes) + ". A smallest field of view of " +
                            describeMetres(estimate.fittingFieldOfView) +
                            " m would fit: raise the field of view of the classes, or crop the raster");
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
