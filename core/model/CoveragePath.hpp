#pragma once

#include <cstdint>
#include <vector>

namespace mcpp {

// A point of a robot's path. The segment that ends here is travelled at this waypoint's speed.
struct Waypoint {
    double x = 0.0;
    double y = 0.0;
    int activeCell = -1;        // active index of the cell the point lies in
    std::int32_t classValue = 0; // land cover of that cell
    double speedMetresPerSecond = 0.0;
    double fieldOfViewMetres = 0.0;
    double cumulativeSeconds = 0.0; // time from the start to reach this point
};

struct CoveragePath {
    int robot = 0;
    std::vector<Waypoint> waypoints; // the first is the centre of the start cell's first sub-cell
    double lengthMetres = 0.0;
    double timeSeconds = 0.0;
    int turns = 0;
    int repeatedSubCellVisits = 0; // sub-cell centres passed a second time (bridges between cells)
    bool closed = true;
};

} // namespace mcpp
