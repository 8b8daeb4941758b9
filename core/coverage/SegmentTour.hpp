#pragma once

#include "core/model/MapPoint.hpp"

#include <vector>

namespace mcpp {

// The order in which one robot flies its detection passes (seed 001's TSP over the segments' end points):
// nearest pass first from the start, then 2-opt moves that reverse a run of passes (each flown the other
// way) while that shortens the straight-line legs between them. The route ends after its last pass.
class SegmentTour {
  public:
    struct Pass {
        MapPoint from;
        MapPoint to;
    };
    struct Visit {
        int pass = 0;
        bool reversed = false; // flown from `to` to `from`
    };

    [[nodiscard]] static std::vector<Visit> order(const std::vector<Pass>& passes, MapPoint start);
    // The first step of order(): each time the pass with the end nearest where the robot is, from that end.
    [[nodiscard]] static std::vector<Visit> nearestFirst(const std::vector<Pass>& passes, MapPoint start);
    // Metres of straight legs from the start through the visits, passes themselves not counted.
    [[nodiscard]] static double legMetres(const std::vector<Pass>& passes, MapPoint start,
                                          const std::vector<Visit>& visits);
};

} // namespace mcpp
