#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PlanningError.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mcpp {

// Why a robot cannot start at a point, judged on the raster and class table alone.
struct StartPointProblem {
    PlanningError::Kind kind = PlanningError::Kind::StartOnObstacle;
    std::string detail; // what is wrong, without naming the robot: "(x, y) is on class 11 (Open water), ..."
};

// The one rule every caller (planners, batch mode, the window) applies to a start point: it must be a number,
// on the raster, on a pixel inside the task area, of a class the table has and robots can cross. The messages
// name the point `pointName` when given (the caller may know it in degrees too), else by describePoint.
[[nodiscard]] std::optional<StartPointProblem> startPointProblem(const ClassGrid& grid,
                                                                 const ClassTable& classes, MapPoint point,
                                                                 const std::string& pointName = {});
// Whether an aircraft may take off at a start with that problem and fly to the nearest free cell: anywhere
// on the raster (outside the task area, on an obstacle, in another robot's cell) but in a no-go zone, not
// off it (mistyped coordinates, most likely) nor at a point that is not a number.
[[nodiscard]] bool takesOffThere(const ClassGrid& grid, MapPoint point, const StartPointProblem& problem);
// Whether robot `robot` is an aircraft (by robot in `flyingRobots`, as PlanningProblem holds them; missing:
// no) that may take off at its start despite that problem: the one rule the planner and the mission check
// share (the window, which knows whether the one robot it places flies, asks takesOffThere).
[[nodiscard]] bool robotTakesOffThere(const std::vector<bool>& flyingRobots, std::size_t robot,
                                      const ClassGrid& grid, MapPoint point,
                                      const StartPointProblem& problem);
// What to say where a start is refused for that problem: its detail, and for a start off the task area
// (nodata, outside the area of interest, in a no-go zone) where the nearest land a robot can start on lies.
// Worked out only here, where it is said: the search reads up to a few hundred thousand pixels.
[[nodiscard]] std::string startRefusal(const ClassGrid& grid, const ClassTable& classes, MapPoint point,
                                       const StartPointProblem& problem);
// "(512300.25, 4120400.5)": to the centimetre, as the messages give planning-frame points.
[[nodiscard]] std::string describePoint(MapPoint point);

} // namespace mcpp
