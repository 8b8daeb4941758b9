#pragma once

#include "core/model/MapPoint.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace mcpp {

// A point of a robot's path, with the speed of the cell it lies in (the cell also gives its land cover and
// field of view). A segment is travelled half at the speed of the waypoint it leaves and half at the speed
// of the one it reaches. 24 bytes: a large map's paths hold tens of millions of them (four per cell), so
// the time to reach a point is worked out when asked for (cumulativeSeconds in PathMeasurement).
struct Waypoint {
    double x = 0.0;
    double y = 0.0;
    int cell = -1;                     // cell of the plan's cell graph the point lies in
    float speedMetresPerSecond = 0.0F; // a float, as the cell's speed is
};
static_assert(sizeof(Waypoint) == 24);

// A stop on the way: the robot waits `seconds` at a waypoint before leaving it (a battery charge, say).
struct PathPause {
    std::size_t waypoint = 0;
    double seconds = 0.0;
};

struct CoveragePath {
    int robot = 0;
    std::vector<Waypoint> waypoints; // the first is the robot's start point
    double lengthMetres = 0.0;
    double timeSeconds = 0.0;
    double turnSeconds = 0.0;      // the part of timeSeconds lost to turns
    std::vector<PathPause> pauses; // by waypoint, ascending; their time is in timeSeconds
    int turns = 0;
    int repeatedSubCellVisits = 0; // sub-cell centres passed again (not counting a closed tour's return)
    bool closed = true;
    // The part of timeSeconds that steps between cells of different sizes take beyond their cells' travel
    // (connectorSeconds in PathMeasurement).
    double connectorSeconds = 0.0;
    // 0 while `waypoints` holds every sub-cell centre the robot passes. On large plans the waypoints along
    // straight runs are merged into the runs' ends once the path is measured (mergeStraightRuns), and this
    // is how many waypoints the path had: its measures are those of all of them.
    std::size_t walkedWaypoints = 0;
    // Once runs are merged, by waypoint: whether waypoints were left out between it and the next.
    std::vector<bool> runFollows;
    // Where an aircraft takes off and lands when that is not the path's first point (a start outside the
    // task area, say on a road beside it): each flight flies from there to its work and back.
    std::optional<MapPoint> takeOff;

    [[nodiscard]] bool runsMerged() const { return walkedWaypoints > 0; }
};

} // namespace mcpp
