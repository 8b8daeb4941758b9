#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PixelRuns.hpp"
#include "core/model/PlanningProblem.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mcpp {

// Land no flight of any robot can work on: farther from every aircraft's start than it can fly out, work a
// little and come back (FlightLimits::reachMetres, less a twentieth of a flight at work). A plan that held it
// would have flights longer than the battery; it is left out of the task area instead and said.
struct LandBeyondReach {
    // The grid's mask with such pixels flagged ClassGrid::beyondFlightReach.
    std::vector<std::uint8_t> outside;
    double passableSquareMetres = 0.0; // of the passable classes among them
    PixelRuns passable;                // those pixels, for exports and pictures
    MapPoint farthest;                 // the passable pixel farthest from every start
    double farthestMetres = 0.0;       // from the start nearest it
    double leastReachMetres = 0.0;     // how far the robots' flights work from their starts
    double mostReachMetres = 0.0;
    bool reachedPassable = false; // whether any passable land is left within reach
};

// The land beyond every robot's reach, where every robot flies out to its work with a known reach; nothing
// where some robot reaches everywhere (a rover, an aircraft without a flight time or cruise speed) or where
// no passable land lies beyond. A pixel counts as reached where the whole cell it may end up in (two of its
// class's fields of view a side) lies within a robot's reach.
[[nodiscard]] std::optional<LandBeyondReach> landBeyondEveryReach(const PlanningProblem& problem);

// Whether a cell the robot covers (robotOfCell) lies on or next to a pixel of the grid flagged
// ClassGrid::beyondFlightReach: a robot confined to a part of the map may be cut off by that land's edge,
// not by impassable land.
[[nodiscard]] bool coversNextToLandBeyondReach(const ClassGrid& grid, const CellGraph& cells,
                                               const std::vector<int>& robotOfCell, int robot);

// What a plan leaving that land out tells its readers.
[[nodiscard]] std::string landBeyondReachMessage(const LandBeyondReach& land);
// Why there is no plan where no passable land is left within reach.
[[nodiscard]] std::string nothingWithinReachMessage(const LandBeyondReach& land);

} // namespace mcpp
