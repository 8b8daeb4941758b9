#pragma once

namespace mcpp {

// A position in the planning frame: metres, x to the east, y to the north.
struct MapPoint {
    double x = 0.0;
    double y = 0.0;

    friend bool operator==(const MapPoint&, const MapPoint&) = default;
};

} // namespace mcpp
