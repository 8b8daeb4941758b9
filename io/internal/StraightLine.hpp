#pragma once

#include "core/model/CoveragePath.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::io::internal {

// Whether b lies on the straight segment from a to c, strictly between its ends, for any three points.
[[nodiscard]] inline bool collinearAndBetweenAnywhere(const Waypoint& a, const Waypoint& b,
                                                      const Waypoint& c) {
    const double abX = b.x - a.x, abY = b.y - a.y, acX = c.x - a.x, acY = c.y - a.y;
    const double lengthAc = std::hypot(acX, acY);
    if (lengthAc == 0.0)
        return false;
    const double cross = abX * acY - abY * acX;
    if (std::abs(cross) > 1e-9 * lengthAc * std::max(lengthAc, 1.0))
        return false;
    const double along = (abX * acX + abY * acY) / (lengthAc * lengthAc);
    return along > 0.0 && along < 1.0;
}

// Whether b lies on the straight segment from a to c, strictly between its ends: a point a path can drop
// without changing its shape.
[[nodiscard]] inline bool collinearAndBetween(const Waypoint& a, const Waypoint& b, const Waypoint& c) {
    // Most points of a path lie on a line of the grid with their neighbours. There, for finite coordinates,
    // collinearAndBetweenAnywhere comes to this without std::hypot (which gives |y| for hypot(0, y)), bit
    // for bit, at a fraction of the cost: a path of tens of millions of points is tested several times over
    // when it is written.
    const bool alongColumn = a.x == b.x && b.x == c.x;
    if (alongColumn || (a.y == b.y && b.y == c.y)) {
        const double ab = alongColumn ? b.y - a.y : b.x - a.x;
        const double ac = alongColumn ? c.y - a.y : c.x - a.x;
        if (ac == 0.0)
            return false;
        const double along = (ab * ac) / (std::abs(ac) * std::abs(ac));
        return along > 0.0 && along < 1.0;
    }
    return collinearAndBetweenAnywhere(a, b, c);
}

} // namespace mcpp::io::internal
