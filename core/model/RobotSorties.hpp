#pragma once

#include "core/model/MapPoint.hpp"
#include "core/model/Sortie.hpp"

#include <cmath>
#include <vector>

namespace mcpp {

// A robot that covers its region in sorties from a charger.
struct RobotSorties {
    int robot = 0;
    MapPoint charger;
    double enduranceSeconds = 0.0; // travel and turning one charge allows
    double rechargeSeconds = 0.0;  // spent at the charger between two sorties
    std::vector<Sortie> sorties;
    double outOfRangeAreaSquareMetres = 0.0; // passable land of its region beyond half the endurance
    std::vector<int> outOfRangeCells;        // those cells, left to no robot

    [[nodiscard]] int charges() const { return sorties.empty() ? 0 : static_cast<int>(sorties.size()) - 1; }
    // Whether the charger lies away from `point` (a millimetre off, after a round trip through another CRS,
    // is still at it).
    [[nodiscard]] bool chargerAwayFrom(MapPoint point) const {
        return std::hypot(charger.x - point.x, charger.y - point.y) > 1e-3;
    }
};

} // namespace mcpp
