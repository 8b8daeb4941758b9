#include "render/PlanFrame.hpp"

#include "core/model/SortieLayer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace mcpp::render {

namespace {

// Below this share of the raster's width and height the picture closes in on the plans.
constexpr double wholeRasterShare = 0.8;
constexpr double marginShare = 0.2;
constexpr double minimumMarginShare = 0.05; // of the raster's extent
constexpr double maximumMarginShare = 0.25; // of the plans' extent, for the raster's share
// How far past the plans, in shares of their extent, a ring may reach to widen the frame (a ring reaching
// further is left to be cut by the frame's edge: the plans would shrink to a corner of a circle); and the
// room left round a ring for its dashed line.
constexpr double ringReachShare = 1.0;
constexpr double ringMarginShare = 0.03;

struct Bounds {
    double minX = std::numeric_limits<double>::infinity();
    double minY = std::numeric_limits<double>::infinity();
    double maxX = -std::numeric_limits<double>::infinity();
    double maxY = -std::numeric_limits<double>::infinity();
    [[nodiscard]] bool empty() const { return !(minX <= maxX && minY <= maxY); }
    [[nodiscard]] Bounds grownBy(double metres) const {
        return {minX - metres, minY - metres, maxX + metres, maxY + metres};
    }
    void take(const Bounds& other) {
        if (other.empty())
            return;
        minX = std::min(minX, other.minX);
        minY = std::min(minY, other.minY);
        maxX = std::max(maxX, other.maxX);
        maxY = std::max(maxY, other.maxY);
    }
};

// The plans' cells and the take-off points beside them.
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
        // An aircraft taking off beside the area: its start and the leg to its path are in the picture.
        for (const CoveragePath& path : plan->paths)
            if (path.takeOff)
                bounds.take({path.takeOff->x, path.takeOff->y, path.takeOff->x, path.takeOff->y});
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
    extent.trueNorthRadians = grid.trueNorthRadians;
    return extent;
}

// Whether a ring holds all of the bounds: then nothing lies beyond it to see, and the plans keep the frame.
bool ringHolds(const FrameRing& ring, const Bounds& bounds) {
    const double farX =
        std::max(std::abs(bounds.minX - ring.centre.x), std::abs(bounds.maxX - ring.centre.x));
    const double farY =
        std::max(std::abs(bounds.minY - ring.centre.y), std::abs(bounds.maxY - ring.centre.y));
    return std::hypot(farX, farY) <= ring.radiusMetres;
}

// The plans' bounds with their margin and the rings, as far as they may widen it.
Bounds framedBounds(const ClassGrid& grid, const Bounds& bounds, const std::vector<FrameRing>& rings) {
    const double extent = std::max(bounds.maxX - bounds.minX, bounds.maxY - bounds.minY);
    // A fifth of the plans' extent around them, and at least a twentieth of the raster's: a plan of a few
    // cells keeps some of the land around it. Never more than a quarter of the plans' extent, though: a small
    // area of interest on a country's raster would be a speck amid its surroundings.
    const double rasterMargin =
        std::min(minimumMarginShare * std::max(grid.width(), grid.height()), maximumMarginShare * extent);
    Bounds framed = bounds.grownBy(std::max(marginShare * extent, rasterMargin));
    const Bounds limit = bounds.grownBy(ringReachShare * extent);
    for (const FrameRing& ring : rings) {
        if (!(ring.radiusMetres > 0.0) || !std::isfinite(ring.centre.x) || !std::isfinite(ring.centre.y) ||
            ringHolds(ring, bounds))
            continue;
        const double reach = ring.radiusMetres * (1.0 + ringMarginShare);
        const Bounds box{ring.centre.x - reach, ring.centre.y - reach, ring.centre.x + reach,
                         ring.centre.y + reach};
        if (box.minX >= limit.minX && box.minY >= limit.minY && box.maxX <= limit.maxX &&
            box.maxY <= limit.maxY)
            framed.take(box);
    }
    return framed;
}

} // namespace

MapPoint flightHomeOf(const Plan& plan, const CoveragePath& path) {
    if (const RobotSorties* sorties = sortiesOfRobot(plan, path.robot); sorties != nullptr)
        return sorties->charger;
    return path.takeOff ? *path.takeOff : MapPoint{path.waypoints.front().x, path.waypoints.front().y};
}

std::vector<FrameRing> flightReachRings(const Plan& plan, const std::vector<double>& reachMetres) {
    std::vector<FrameRing> rings;
    for (const CoveragePath& path : plan.paths) {
        const auto robot = static_cast<std::size_t>(path.robot);
        if (path.waypoints.empty() || robot >= reachMetres.size() || !(reachMetres[robot] > 0.0))
            continue;
        rings.push_back({flightHomeOf(plan, path), reachMetres[robot]});
    }
    return rings;
}

bool someRingShows(const ClassGrid& frame, const std::vector<FrameRing>& rings) {
    const double minX = frame.originX;
    const double maxX = frame.maxX();
    const double minY = frame.minY();
    const double maxY = frame.originY;
    return std::any_of(rings.begin(), rings.end(), [&](const FrameRing& ring) {
        const double x = ring.centre.x;
        const double y = ring.centre.y;
        const double nearest =
            std::hypot(std::max({minX - x, 0.0, x - maxX}), std::max({minY - y, 0.0, y - maxY}));
        const double farthest = std::hypot(std::max(std::abs(x - minX), std::abs(x - maxX)),
                                           std::max(std::abs(y - minY), std::abs(y - maxY)));
        return ring.radiusMetres > 0.0 && nearest <= ring.radiusMetres && ring.radiusMetres <= farthest;
    });
}

namespace {

// The frame round `bounds` (planFrame's rule): the whole raster where they take most of it.
ClassGrid frameAround(const ClassGrid& grid, const Bounds& bounds, const std::vector<FrameRing>& rings) {
    ClassGrid frame = extentOf(grid);
    if (bounds.empty() || grid.pixelWidth <= 0.0 || grid.pixelHeight <= 0.0)
        return frame;
    const Bounds framed = framedBounds(grid, bounds, rings);
    // Whole pixels of the raster, clamped to it (in doubles first: cells far off it stay in range).
    const auto pixelIndex = [](double value, int limit) {
        return static_cast<int>(std::clamp(value, 0.0, static_cast<double>(limit)));
    };
    const int firstColumn =
        pixelIndex(std::floor((framed.minX - grid.originX) / grid.pixelWidth), grid.columns);
    const int lastColumn =
        pixelIndex(std::ceil((framed.maxX - grid.originX) / grid.pixelWidth), grid.columns);
    const int firstRow = pixelIndex(std::floor((grid.originY - framed.maxY) / grid.pixelHeight), grid.rows);
    const int lastRow = pixelIndex(std::ceil((grid.originY - framed.minY) / grid.pixelHeight), grid.rows);
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

// The task area's pixels: those neither outside the area of interest nor nodata (a raster read only round
// its area has nodata beyond it). Empty where none is left out, or none is in.
Bounds taskAreaBounds(const ClassGrid& grid) {
    if (grid.outside.empty())
        return {};
    int firstColumn = grid.columns;
    int lastColumn = -1;
    int firstRow = grid.rows;
    int lastRow = -1;
    bool leftOut = false;
    for (int row = 0; row < grid.rows; ++row) {
        const std::uint8_t* flags = grid.outside.data() + grid.index(0, row);
        for (int column = 0; column < grid.columns; ++column) {
            if (flags[column] == ClassGrid::outsideArea || flags[column] == ClassGrid::outsideNodata) {
                leftOut = true;
                continue;
            }
            firstColumn = std::min(firstColumn, column);
            lastColumn = std::max(lastColumn, column);
            firstRow = std::min(firstRow, row);
            lastRow = std::max(lastRow, row);
        }
    }
    if (!leftOut || lastColumn < 0)
        return {};
    return {grid.originX + firstColumn * grid.pixelWidth, grid.originY - (lastRow + 1) * grid.pixelHeight,
            grid.originX + (lastColumn + 1) * grid.pixelWidth, grid.originY - firstRow * grid.pixelHeight};
}

} // namespace

ClassGrid planFrame(const ClassGrid& grid, const std::vector<const Plan*>& plans,
                    const std::vector<FrameRing>& rings) {
    return frameAround(grid, cellBounds(plans), rings);
}

ClassGrid taskAreaFrame(const ClassGrid& grid) {
    return frameAround(grid, taskAreaBounds(grid), {});
}

} // namespace mcpp::render
