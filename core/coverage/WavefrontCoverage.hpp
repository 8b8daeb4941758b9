#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RobotSorties.hpp"

#include <limits>
#include <memory>
#include <vector>

namespace mcpp {

class ReturnTree;
class SubCellNodes;

// Wavefront coverage of one robot's region on a battery (seed 002, after Zelinsky et al.). Every free
// sub-cell gets a wavefront number from the charger (3 per side step, 4 per diagonal one); the robot steps
// to the unvisited side neighbour of the highest number, so it works from far to near, and when none is
// left it takes the quickest way to the nearest unvisited sub-cell. Before each step it checks that the
// charge left would still bring it home from there; when it would not, it goes home by its return tree,
// charges, flies back out along the way home of where it was heading, reversed, and goes on. Cells of the
// region it could not reach and leave again on one charge are left out and reported.
class WavefrontCoverage {
  public:
    struct Battery {
        double enduranceSeconds = std::numeric_limits<double>::infinity(); // travel and turning per charge
        double rechargeSeconds = 0.0;
        // The robot's own (its battery_s, or its vehicle's flight time), not the planner's battery_s: a
        // battery too short is then the robot's to mend.
        bool ownBattery = false;
    };
    struct Result {
        CoveragePath path; // not yet measured; its pauses are the charges
        RobotSorties sorties;
    };

    // ownSpeed: the robot's own speed over every class (PlanningProblem::robotSpeeds), 0 for the cells'.
    WavefrontCoverage(const CellGraph& graph, Battery battery, double ownSpeed = 0.0)
        : graph_(graph), battery_(battery), ownSpeed_(ownSpeed) {}

    // cells: the robot's region, holding chargerCell, of a single-level grid. transit: the flight from the
    // robot's start to the charger (ChargerTransit) when it starts elsewhere, else empty; the first sortie
    // begins with it. Throws PlanningError when one charge cannot cover the charger's cell and come back.
    [[nodiscard]] Result cover(int robot, const std::vector<int>& cells, int chargerCell, MapPoint charger,
                               const std::vector<Waypoint>& transit, const ProgressReporter& progress) const;

  private:
    // The error for a battery that cannot cover the charger's own cell.
    [[nodiscard]] PlanningError batteryTooShort(int robot) const;
    // The return tree over the usable nodes once every cell out of range is left out of them (and listed
    // in `sorties`).
    [[nodiscard]] std::unique_ptr<ReturnTree>
    treeWithinRange(const SubCellNodes& nodes, int root, int robot, int chargerCell, MapPoint charger,
                    std::vector<char>& usable, RobotSorties& sorties, const ProgressReporter& progress) const;

    const CellGraph& graph_;
    Battery battery_;
    double ownSpeed_;
};

} // namespace mcpp
