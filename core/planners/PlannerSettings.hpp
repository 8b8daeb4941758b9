#pragma once

#include <string>

namespace mcpp {

struct PlannerSettings {
    std::string planner = "mcpp-mlct";
    // A class covering at most this fraction of a cell's pixels does not force a split (spec 2).
    double purityTolerance = 0.0;
    // A bottom-level cell whose obstacle + outside fraction exceeds this is blocked (spec 2).
    double blockedThreshold = 0.5;
    // Closed tours end where they start; open paths stop at the last sub-cell centre.
    bool closedTour = true;
    // Cap on rebalancing moves after the regions are grown; 0 picks a cap from the problem size.
    int rebalanceIterations = 0;
    // Move a start on an obstacle, outside the area or sharing a cell to the nearest free cell, with a
    // warning.
    bool snapStartsToFreeCells = false;

    friend bool operator==(const PlannerSettings&, const PlannerSettings&) = default;
};

} // namespace mcpp
