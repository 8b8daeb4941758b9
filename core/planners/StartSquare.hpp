#pragma once

#include "core/model/MapPoint.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {

// Where a robot starts: a point, or where only its start cell is known, that cell's square.
struct StartSquare {
    MapPoint centre;
    double halfSide = 0.0;

    // The gap between this square and the square of side `side` centred at (x, y): 0 where they meet.
    [[nodiscard]] double gapTo(double x, double y, double side) const {
        const double across = side / 2.0 + halfSide;
        return std::hypot(std::max(0.0, std::abs(x - centre.x) - across),
                          std::max(0.0, std::abs(y - centre.y) - across));
    }
};

} // namespace mcpp
