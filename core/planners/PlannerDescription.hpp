#pragma once

#include "core/model/MemoryBudget.hpp"
#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mcpp {

// What a planner guarantees about every plan it makes; the invariant suite holds each planner to these.
struct PlannerPromises {
    bool regionsConnected = true;          // each region is connected and holds its robot's start cell
    bool pathsCoverOwnRegion = true;       // each robot passes every free sub-cell of its own region
    bool everyReachableCellCovered = true; // every cell connected to a start belongs to some region
    // Some robot passes the centre of every free sub-cell of the regions (a planner whose sensor model
    // sees farther spaces its passes out instead).
    bool passesEverySubCell = true;
};

// How a planner presents itself to the command line, mission files and the window.
struct PlannerDescription {
    std::string name;    // command-line and mission-file name, e.g. "mcpp-mlct"
    std::string label;   // for people, e.g. "MCPP-MLCT"
    std::string summary; // one line for --help and the planner list
    bool singleRobot = false;
    bool simulatesEvents = false; // plays the problem's events; other planners warn that they ignore them
    // Gives robots of their own speeds (PlanningProblem::robotSpeeds) work in proportion; other planners
    // divide it as if all drove at the class table's speeds, and say so. Every planner times them right.
    bool balancesOwnSpeeds = false;
    // Evens out the robots' time in the field (PlanningProblem::fieldSeconds, PlanningRun::fieldPaces)
    // rather than their path time.
    bool balancesFieldTime = false;
    PlannerPromises promises;
    std::vector<ParameterSpec> parameters; // the planner's and its stages', then those every planner has
    // Peak memory per cell of the finest grid, outputs included: a map that would need more than the
    // machine allows is refused before any work starts, naming a field of view that fits.
    std::int64_t bytesPerBottomCell = unmeasuredBytesPerBottomCell;
    // Plans on the quadtree whose cells grow with each field of view, rather than on the uniform grid of
    // 2 x the smallest FOV; where quadTreeSwitch names a boolean parameter, that parameter chooses.
    bool quadTreeCells = false;
    std::string quadTreeSwitch;
    // A boolean parameter that, on, cuts the work into pieces of equal time whatever the starts, and why
    // a plan with it off may leave a robot little (e.g. MSTC: pieces cut at the starts along one tour). The
    // uneven-plan warning gives that reason and names the switch while it is off.
    std::string balanceSwitch;
    std::string unbalancedBecause;

    [[nodiscard]] bool plansOnQuadTree(const ParameterValues& values) const {
        if (!quadTreeSwitch.empty() && values.has(quadTreeSwitch))
            return values.boolean(quadTreeSwitch);
        return quadTreeCells;
    }

    // Robots fly on batteries (it declares battery_s): their own batteries and chargers matter to it.
    [[nodiscard]] bool fliesOnBatteries() const {
        for (const ParameterSpec& spec : parameters)
            if (spec.key == "battery_s")
                return true;
        return false;
    }
};

} // namespace mcpp
