#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/Plan.hpp"

#include <vector>

namespace mcpp::render {

// The part of the raster a picture of plans shows, as a grid of the raster's pixels holding no values (its
// extent alone): the whole raster, or, where the plans cover a small part of it (an area of interest), the
// pixels around their cells with a margin of a fifth of their extent on each side (at least a twentieth of
// the raster's). Null plans are skipped.
//
// Rings drawn round points (an aircraft's flight reach round its start) are taken in too where they cross
// the plans and reach no further than the plans' extent again on each side of them: a ring far larger than
// the plans would shrink them to a dot, and one round all of them has nothing beyond it to show; both are
// cut by the frame's edge instead.
struct FrameRing {
    MapPoint centre;
    double radiusMetres = 0.0;
};
[[nodiscard]] ClassGrid planFrame(const ClassGrid& grid, const std::vector<const Plan*>& plans,
                                  const std::vector<FrameRing>& rings = {});
// The same frame round the task area's pixels (neither outside the area of interest nor nodata): what a
// view of the map before any plan fits to. The whole raster where they take most of it.
[[nodiscard]] ClassGrid taskAreaFrame(const ClassGrid& grid);
// Where a robot's flights take off and land: the charger of a battery plan's sorties, else its take-off
// point beside the area, else its path's first waypoint.
[[nodiscard]] MapPoint flightHomeOf(const Plan& plan, const CoveragePath& path);
// The flight-reach rings of a plan's robots: round where each takes off (flightHomeOf), of the robot's
// reach in metres (by robot; 0 or missing: none).
[[nodiscard]] std::vector<FrameRing> flightReachRings(const Plan& plan,
                                                      const std::vector<double>& reachMetres);
// Whether some ring's outline crosses the frame: one wholly outside it, or wholly round it, shows nothing.
[[nodiscard]] bool someRingShows(const ClassGrid& frame, const std::vector<FrameRing>& rings);

} // namespace mcpp::render
