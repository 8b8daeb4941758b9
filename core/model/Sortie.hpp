#pragma once

#include <cstddef>

namespace mcpp {

// One flight on one charge: a stretch of a robot's path from its charger back to it, as waypoint indices
// of that path (the last is where the robot charges, and the next sortie's first).
struct Sortie {
    std::size_t firstWaypoint = 0;
    std::size_t lastWaypoint = 0;
};

} // namespace mcpp
