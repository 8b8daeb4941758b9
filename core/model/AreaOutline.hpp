#pragma once

#include "core/model/MapPoint.hpp"

#include <vector>

namespace mcpp {

// The task area's edges as the user gave them: the area of interest's polygons and the no-go zones', each
// polygon as its rings (the outer ring, then its holes), each ring as its corners in the planning frame.
// Drawn over the map, they let a plan be checked against the area it was asked for: the planner lays them on
// the raster's pixels, and cells along the edge may reach past it.
struct AreaOutline {
    using Ring = std::vector<MapPoint>;
    using Polygon = std::vector<Ring>;

    std::vector<Polygon> include; // the area of interest; none: the whole raster
    std::vector<Polygon> exclude; // the no-go zones

    [[nodiscard]] bool empty() const { return include.empty() && exclude.empty(); }
};

} // namespace mcpp
