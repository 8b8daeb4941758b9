#pragma once

#include "core/model/Cell.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/FlightLimits.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/RegionAllocation.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// How far each robot's own flights work from where they take off (FlightLimits::workingReachMetres). A
// division evened out by cost alone gives an aircraft started near the map's edge as much land as the
// others, some of it beyond its own reach though within another's: every flight working there would be
// longer than its battery. Such cells are handed over to a robot that reaches them.
class OwnFlightReach {
  public:
    // By robot, where its flights take off and its flight limits (a robot without them reaches everywhere).
    OwnFlightReach(std::vector<MapPoint> launchPoints, const std::vector<FlightLimits>& flights);

    // Whether some robot's flights do not reach everywhere.
    [[nodiscard]] bool limits() const { return limits_; }
    // Whether every waypoint the robot's path may hold in the cell (its free sub-cells' centres) lies within
    // the robot's reach.
    [[nodiscard]] bool reaches(std::size_t robot, const Cell& cell) const;

    // Cells of each region beyond its robot's reach go to a robot that reaches them and whose region they
    // join, through cells so handed over (the fewest steps from its region first); those no such robot
    // joins stay. Regions are made whole again and their costs counted again over `graph`'s cells. Returns
    // the cells handed over.
    int handOver(const CellGraph& graph, RegionAllocation& regions) const;

  private:
    std::vector<MapPoint> launchPoints_;
    std::vector<double> reachMetres_; // by robot; infinite: everywhere
    bool limits_ = false;
};

} // namespace mcpp
