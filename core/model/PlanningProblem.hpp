#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/parameters/PlannerChoice.hpp"

#include <vector>

namespace mcpp {

struct PlanningProblem {
    ClassGrid grid;
    ClassTable classes;
    std::vector<MapPoint> starts; // one per robot, in the grid's frame
    PlannerChoice planner;
};

} // namespace mcpp
