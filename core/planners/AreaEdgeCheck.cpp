#include "core/planners/AreaEdgeCheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {
namespace {

// Pixels searched around a waypoint for the task area: beyond, the distance is reported as this far.
constexpr int searchRadiusPixels = 32;

double distanceToPixel(const ClassGrid& grid, MapPoint point, int column, int row) {
    const double west = grid.originX + column * grid.pixelWidth;
    const double north = grid.originY - row * grid.pixelHeight;
    const double dx = std::max({west - point.x, 0.0, point.x - (west + grid.pixelWidth)});
    const double dy = std::max({(north - grid.pixelHeight) - point.y, 0.0, point.y - north});
    return std::hypot(dx, dy);
}

// The distance from a point to the nearest pixel of the task area, searched ring by ring.
double distanceToTaskArea(const ClassGrid& grid, MapPoint point, PixelIndex at) {
    double nearest = std::numeric_limits<double>::infinity();
    const double step = std::min(grid.pixelWidth, grid.pixelHeight);
    for (int ring = 1; ring <= searchRadiusPixels; ++ring) {
        if ((ring - 1) * step > nearest)
            break;
        for (int row = at.row - ring; row <= at.row + ring; ++row)
            for (int column = at.column - ring; column <= at.column + ring; ++column) {
                const bool onRing = std::abs(row - at.row) == ring || std::abs(column - at.column) == ring;
                if (!onRing || row < 0 || column < 0 || row >= grid.rows || column >= grid.columns ||
                    grid.isOutside(column, row))
                    continue;
                nearest = std::min(nearest, distanceToPixel(grid, point, column, row));
            }
    }
    return std::isfinite(nearest) ? nearest : searchRadiusPixels * step;
}

} // namespace

WaypointsBeyondArea waypointsBeyondArea(const ClassGrid& grid, const std::vector<CoveragePath>& paths) {
    WaypointsBeyondArea beyond;
    // Most maps have no area of interest: one pass over the flags spares a lookup per waypoint.
    if (std::none_of(grid.outside.begin(), grid.outside.end(), ClassGrid::isDrawnEdge))
        return beyond;
    for (const CoveragePath& path : paths) {
        int here = 0;
        for (const Waypoint& waypoint : path.waypoints) {
            const MapPoint point{waypoint.x, waypoint.y};
            const auto pixel = grid.pixelAt(point);
            const std::uint8_t flag = pixel ? grid.outside[grid.index(pixel->column, pixel->row)] : 0;
            if (!ClassGrid::isDrawnEdge(flag))
                continue;
            ++here;
            beyond.inNoGoZones += flag == ClassGrid::inNoGoZone ? 1 : 0;
            beyond.farthestMetres = std::max(beyond.farthestMetres, distanceToTaskArea(grid, point, *pixel));
        }
        if (here > 0)
            beyond.robots.push_back(path.robot);
        beyond.waypoints += here;
    }
    std::sort(beyond.robots.begin(), beyond.robots.end());
    beyond.pixelMetres = std::max(grid.pixelWidth, grid.pixelHeight);
    return beyond;
}

WaypointsBeyondRaster waypointsBeyondRaster(const ClassGrid& grid, const std::vector<CoveragePath>& paths) {
    WaypointsBeyondRaster beyond;
    for (const CoveragePath& path : paths) {
        int here = 0;
        for (const Waypoint& waypoint : path.waypoints) {
            const double dx = std::max({grid.originX - waypoint.x, 0.0, waypoint.x - grid.maxX()});
            const double dy = std::max({grid.minY() - waypoint.y, 0.0, waypoint.y - grid.originY});
            if (waypoint.cell < 0 || (dx <= 0.0 && dy <= 0.0))
                continue; // a take-off beside the raster, or on the raster, its edge included
            ++here;
            beyond.farthestMetres = std::max(beyond.farthestMetres, std::hypot(dx, dy));
        }
        if (here > 0)
            beyond.robots.push_back(path.robot);
        beyond.waypoints += here;
    }
    std::sort(beyond.robots.begin(), beyond.robots.end());
    return beyond;
}

} // namespace mcpp
