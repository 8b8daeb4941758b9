#pragma once

#include "core/model/MapPoint.hpp"
#include "core/model/Plan.hpp"

namespace mcpp {

// Passable land that no region holds, told apart by why: cut off from every start by impassable land or the
// area's edge, or joined to a start by neighbouring cells but left out by the planner (beyond a battery's
// reach).
struct UncoveredLand {
    double cutOffSquareMetres = 0.0;
    double leftOutSquareMetres = 0.0;
    int cutOffPieces = 0;                  // pieces of cut-off cells joined by neighbours
    double largestPieceSquareMetres = 0.0; // the largest of them
    MapPoint largestPieceCentre;           // the centre of its largest cell
};

[[nodiscard]] UncoveredLand uncoveredLand(const Plan& plan);

} // namespace mcpp
