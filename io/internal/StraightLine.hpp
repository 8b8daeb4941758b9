#pragma once

#include "core/model/CoveragePath.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::io::internal {

// Whether b lies on the straight segment from a to c, strictly between its ends: a point a path can drop
// without changing its shape.
[[nodiscard]] inline bool collinearAndBetween(const Waypoint& a, const Waypoint& b, const Waypoint& c) {
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

} // namespace mcpp::io::internal
