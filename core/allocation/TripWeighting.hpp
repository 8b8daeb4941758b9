#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/FlightLimits.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/RegionAllocation.hpp"

#include <optional>
#include <vector>

namespace mcpp {

// An aircraft works far from where it takes off only on flights that spend the way there and back, so a
// second of work far out takes more of its time in the field than one beside its start: near the edge of
// its reach, most of each flight. A division of cells weighted so evens out time in the field, where cover
// times alone give the robot with the farther region the longer day.
class TripWeighting {
  public:
    // Weighs `cells` for robots taking off at `launchPoints` with `flights`; none where no robot's flights
    // count their trips.
    TripWeighting(const CellGraph& cells, const std::vector<MapPoint>& launchPoints,
                  const std::vector<FlightLimits>& flights);

    // By cell, the field seconds a second of its work takes for the robot that launches nearest it:
    // (flight + turnaround) / (flight - climb and descent - way out and back), the way out and back at most
    // (farthestShare - 1) / farthestShare of a flight's work (beyond one flight's reach); 1 for a robot
    // without trips (a rover works in one go). Empty where no robot's flights count their trips.
    [[nodiscard]] static std::vector<float> weightsOf(const CellGraph& cells,
                                                      const std::vector<MapPoint>& launchPoints,
                                                      const std::vector<FlightLimits>& flights);

    [[nodiscard]] bool weighs() const { return weighted_.has_value(); }
    // The cells a division should share out: each covered its weight times slower; `cells` without weights.
    [[nodiscard]] const CellGraph& divided(const CellGraph& cells) const {
        return weighted_ ? *weighted_ : cells;
    }
    // By robot, its region's weighted cost over its cost: the field seconds a second of its path takes as the
    // division counts them. Empty without weights.
    [[nodiscard]] std::vector<double> paces(const CellGraph& cells, const RegionAllocation& regions) const;

    static constexpr double farthestShare = 20.0;

  private:
    std::optional<CellGraph> weighted_;
};

} // namespace mcpp
