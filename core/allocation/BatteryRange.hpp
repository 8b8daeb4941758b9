#pragma once

#include "core/model/CellGraph.hpp"

#include <vector>

namespace mcpp {

// Where robots on batteries can work: a cell is in range when some charger's robot can fly out to it and
// back on one charge of its own battery, judged from cell centre to cell centre.
struct BatteryRange {
    double enduranceSeconds = 0.0; // the longest robot's (and any robot's without one of its own)
    // By robot, its own speed over every class (PlanningProblem::robotSpeeds); 0 or missing: the cells'.
    std::vector<double> robotSpeeds = {};
    // By robot, its own endurance; 0 or missing: enduranceSeconds.
    std::vector<double> robotEndurances = {};

    [[nodiscard]] double enduranceOf(std::size_t robot) const {
        return robot < robotEndurances.size() && robotEndurances[robot] > 0.0 ? robotEndurances[robot]
                                                                              : enduranceSeconds;
    }
    [[nodiscard]] bool withinRangeOf(std::size_t robot, double secondsFromCharger) const {
        return 2.0 * secondsFromCharger < enduranceOf(robot);
    }
    // Seconds of travel from each cell's centre to the nearest start cell's, through neighbours (infinity
    // where none is reachable), each robot at its own speed.
    [[nodiscard]] std::vector<double> secondsFromChargers(const CellGraph& graph,
                                                          const std::vector<int>& startCells) const;

    struct AllocationGraph {
        CellGraph graph;
        std::vector<int> outOfRange; // cells farther than half its own endurance from every robot's charger
    };
    // The graph to allocate on: the same cells and ids, those beyond every charger's range (each robot's
    // on its own battery) cut off from their neighbours so that no region takes them and no region's
    // balance counts them.
    [[nodiscard]] AllocationGraph allocationGraph(const CellGraph& graph,
                                                  const std::vector<int>& startCells) const;

    // Cells their robots left out of range, handed to another robot whose charger reaches them: ways grow
    // from the chargers through their own regions' cells and the left-out ones (never one the robot itself
    // left out), quickest first, and a left-out cell goes to the robot whose way reaches it within its own
    // range.
    // leftOutBy: by cell, the robot that left it out, or -1 (robotOfCell is -1 there). Returns the robots
    // that gained cells, ascending.
    std::vector<int> handOver(const CellGraph& graph, std::vector<int>& robotOfCell,
                              const std::vector<int>& startCells, const std::vector<int>& leftOutBy) const;
};

// The same cells and ids with those marked in `cutOff` (by cell, nonzero) cut off from their neighbours, so
// that no region grown over it takes them and no region's balance counts them.
[[nodiscard]] CellGraph cutOffCells(const CellGraph& graph, const std::vector<char>& cutOff);

} // namespace mcpp
