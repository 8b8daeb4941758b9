#pragma once

#include "core/ClassGrid.hpp"
#include "core/ClassTable.hpp"
#include "core/MapPoint.hpp"
#include "core/PlannerSettings.hpp"

#include <vector>

namespace mcpp {

struct PlanningProblem {
    ClassGrid grid;
    ClassTable classes;
    std::vector<MapPoint> starts; // one per robot, in the grid's frame
    PlannerSettings settings;
};

} // namespace mcpp
