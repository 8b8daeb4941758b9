#pragma once

#include "core/model/Cell.hpp"

namespace mcpp {

// Where a walk counter-clockwise round a cell's sub-cells passes a neighbouring cell: on which side (0 west,
// 1 south, 2 east, 3 north, the side after the corner sub-cell NW, SW, SE or NE) and, along it, in which
// order (smaller first). TreeCircumnavigation and DynamicTreeWalk order neighbours by it, so that an online
// walk round a tree is the walk round the finished tree.
struct RoundPlace {
    int side = 0;
    double position = 0.0;
};

[[nodiscard]] inline RoundPlace roundPlaceOf(const Cell& self, const Cell& neighbour) {
    const double tolerance = 1e-9 * self.size;
    if (neighbour.maxX() <= self.minX + tolerance)
        return {0, -neighbour.centreY()};
    if (neighbour.maxY() <= self.minY + tolerance)
        return {1, neighbour.centreX()};
    if (neighbour.minX >= self.maxX() - tolerance)
        return {2, neighbour.centreY()};
    return {3, -neighbour.centreX()};
}

} // namespace mcpp
