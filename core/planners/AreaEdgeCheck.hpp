#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/CoveragePath.hpp"

#include <vector>

namespace mcpp {

// Waypoints over ground left out of the task area by an area of interest or a no-go zone: cells that
// straddle the area's edge are covered whole, so paths pass a little beyond it. What a drone flying
// within a geofence drawn on that edge needs to know.
struct WaypointsBeyondArea {
    int waypoints = 0;
    int inNoGoZones = 0;         // of those, in a no-go zone rather than outside the area of interest
    std::vector<int> robots;     // ascending, those with any such waypoint
    double farthestMetres = 0.0; // the largest distance from one of them to the task area's pixels
    double pixelMetres = 0.0;    // the grid's pixel side: the area's own edge may lie up to half of it nearer
};

// Only pixels outside the area of interest or in a no-go zone count (ClassGrid::isDrawnEdge): nodata is the
// raster's edge, not a fence.
[[nodiscard]] WaypointsBeyondArea waypointsBeyondArea(const ClassGrid& grid,
                                                      const std::vector<CoveragePath>& paths);

// Waypoints past the raster's edge, over ground the map says nothing of: a cell the edge cuts through is
// covered whole where the part beyond, counted as obstacle, is within the blocked threshold (a raster of an
// odd number of rows, cells of two pixels: half a cell).
struct WaypointsBeyondRaster {
    int waypoints = 0;
    std::vector<int> robots;     // ascending, those with any such waypoint
    double farthestMetres = 0.0; // the largest distance from one of them to the raster's edge
};

[[nodiscard]] WaypointsBeyondRaster waypointsBeyondRaster(const ClassGrid& grid,
                                                          const std::vector<CoveragePath>& paths);

} // namespace mcpp
