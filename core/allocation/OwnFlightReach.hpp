#pragma once

#include "core/model/Cell.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/FlightLimits.hpp"
#include "core/model/LocalConnectivity.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/RegionAllocation.hpp"

#include <cstddef>
#include <utility>
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

    // By robot, its seconds for a second of cell cost (as AzimuthTrendAllocator::setPaces); empty: all 1.
    void setPaces(std::vector<double> paces) { paces_ = std::move(paces); }

    // Whether some robot's flights do not reach everywhere.
    [[nodiscard]] bool limits() const { return limits_; }
    // Whether every waypoint the robot's path may hold in the cell (its free sub-cells' centres) lies within
    // the robot's reach.
    [[nodiscard]] bool reaches(std::size_t robot, const Cell& cell) const;

    // Cells of each region beyond its robot's reach go to a robot that reaches them and whose region they
    // join, through cells so handed over (the fewest steps from its region first); those no such robot
    // joins stay. Regions are made whole again and their costs counted again over `graph`'s cells. A robot
    // left below the fair share then takes border cells within its reach back from neighbours above it.
    // Returns the cells handed over.
    int handOver(const CellGraph& graph, RegionAllocation& regions) const;

  private:
    // One round of the handover, regions made whole again after it.
    int handOverOnce(const CellGraph& graph, RegionAllocation& regions) const;
    // Robots below the fair share (in their paced costs) take cells within their reach from neighbours above
    // it, nearest their regions first, while the giver stays whole and above it. Returns the cells taken.
    int topUp(const CellGraph& graph, RegionAllocation& regions) const;
    // One robot's pass: border cells of richer neighbours within its reach, nearest its region first, while
    // it is below `fair` and the giver stays at or above it and whole.
    int takeWithinReach(const CellGraph& graph, RegionAllocation& regions, std::size_t taker, double fair,
                        LocalConnectivity& connectivity) const;
    [[nodiscard]] double paceOf(std::size_t robot) const {
        return robot < paces_.size() && paces_[robot] > 0.0 ? paces_[robot] : 1.0;
    }
    [[nodiscard]] double pacedCost(const RegionAllocation& regions, std::size_t robot) const {
        return regions.costSeconds[robot] * paceOf(robot);
    }

    std::vector<MapPoint> launchPoints_;
    std::vector<double> reachMetres_; // by robot; infinite: everywhere
    bool limits_ = false;
    std::vector<double> paces_;
};

} // namespace mcpp
