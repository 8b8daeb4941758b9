#include "render/PlanFrame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp::render {

namespace {

// Below this share of the raster's width and height the picture closes in on the plans.
constexpr double wholeRasterShare = 0.8;
constexpr double marginShare = 0.2;

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
    const double margin = marginShare * std::max(bounds.maxX - bounds.minX, bounds.maxY - bounds.minY);
    // Whole pixels of the raster, clamped to it.
    const int firstColumn =
        std::max(0, static_cast<int>(std::floor((bounds.minX - margin - grid.originX) / grid.pixelWidth)));
    const int lastColumn = std::min(
        grid.columns, static_cast<int>(std::ceil((bounds.maxX + margin - grid.originX) / grid.pixelWidth)));
    const int firstRow =
        std::max(0, static_cast<int>(std::floor((grid.originY - bounds.maxY - margin) / grid.pixelHeight)));
    const int lastRow = std::min(
        grid.rows, static_cast<int>(std::ceil((grid.originY - bounds.minY + margin) / grid.pixelHeight)));
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
