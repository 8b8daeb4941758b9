#include "render/PlanFrame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp::render {

namespace {

// Below this share of the raster's width and height the picture closes in on the plans.
constexpr double wholeRasterShare = 0.8;
constexpr double marginShare = 0.2;
constexpr double minimumMarginShare = 0.05;

struct Bounds {
    double minX = std::numeric_limits<double>::infinity();
    double minY = std::numeric_limits<double>::infinity();
    double maxX = -std::numeric_limits<double>::infinity();
    double maxY = -std::numeric_limits<double>::infinity();
    [[nodiscard]] bool empty() const { return !(minX <= maxX && minY <= maxY); }
};

Bounds cellBounds(const std::vector<const Plan*>& plans) {
    Bounds bounds;
    for (const Plan* plan : plans) {
        if (plan == nullptr)
            continue;
        for (const Cell& cell : plan->cells.cells()) {
            bounds.minX = std::min(bounds.minX, cell.minX);
            bounds.minY = std::min(bounds.minY, cell.minY);
            bounds.maxX = std::max(bounds.maxX, cell.maxX());
            bounds.maxY = std::max(bounds.maxY, cell.maxY());
        }
    }
    return bounds;
}

ClassGrid extentOf(const ClassGrid& grid) {
    ClassGrid extent;
    extent.columns = grid.columns;
    extent.rows = grid.rows;
    extent.pixelWidth = grid.pixelWidth;
    extent.pixelHeight = grid.pixelHeight;
    extent.originX = grid.originX;
    extent.originY = grid.originY;
    return extent;
}

} // namespace

ClassGrid planFrame(const ClassGrid& grid, const std::vector<const Plan*>& plans) {
    ClassGrid frame = extentOf(grid);
    const Bounds bounds = cellBounds(plans);
    if (bounds.empty() || grid.pixelWidth <= 0.0 || grid.pixelHeight <= 0.0)
        return frame;
    // A fifth of the plans' extent around them, and at least a twentieth of the raster's: a plan of a few
    // cells keeps some of the land around it.
    const double margin =
        std::max(marginShare * std::max(bounds.maxX - bounds.minX, bounds.maxY - bounds.minY),
                 minimumMarginShare * std::max(grid.width(), grid.height()));
    // Whole pixels of the raster, clamped to it (in doubles first: cells far off it stay in range).
    const auto pixelIndex = [](double value, int limit) {
        return static_cast<int>(std::clamp(value, 0.0, static_cast<double>(limit)));
    };
    const int firstColumn =
        pixelIndex(std::floor((bounds.minX - margin - grid.originX) / grid.pixelWidth), grid.columns);
    const int lastColumn =
        pixelIndex(std::ceil((bounds.maxX + margin - grid.originX) / grid.pixelWidth), grid.columns);
    const int firstRow =
        pixelIndex(std::floor((grid.originY - bounds.maxY - margin) / grid.pixelHeight), grid.rows);
    const int lastRow =
        pixelIndex(std::ceil((grid.originY - bounds.minY + margin) / grid.pixelHeight), grid.rows);
    const int columns = lastColumn - firstColumn;
    const int rows = lastRow - firstRow;
    if (columns <= 0 || rows <= 0 ||
        (columns >= wholeRasterShare * grid.columns && rows >= wholeRasterShare * grid.rows))
        return frame;
    frame.columns = columns;
    frame.rows = rows;
    frame.originX = grid.originX + firstColumn * grid.pixelWidth;
    frame.originY = grid.originY - firstRow * grid.pixelHeight;
    return frame;
}

} // namespace mcpp::render
