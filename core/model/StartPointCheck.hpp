#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PlanningError.hpp"

#include <optional>
#include <string>

namespace mcpp {

// Why a robot cannot start at a point, judged on the raster and class table alone.
struct StartPointProblem {
    PlanningError::Kind kind = PlanningError::Kind::StartOnObstacle;
    std::string detail; // what is wrong, without naming the robot: "(x, y) is on class 11 (Open water), ..."
};

// The one rule every caller (planners, batch mode, the window) applies to a start point: it must be a number,
// on the raster, on a pixel inside the task area, of a class the table has and robots can cross.
[[nodiscard]] std::optional<StartPointProblem> startPointProblem(const ClassGrid& grid,
                                                                 const ClassTable& classes, MapPoint point);
// "(512300.25, 4120400.5)" with the precision the messages use.
[[nodiscard]] std::string describePoint(MapPoint point);

} // namespace mcpp
