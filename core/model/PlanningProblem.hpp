#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PlanIssue.hpp"
#include "core/model/SpeedEvent.hpp"
#include "core/parameters/PlannerChoice.hpp"

#include <optional>
#include <vector>

namespace mcpp {

// The most robots one plan takes: robot numbers label region outlines in 16 bits (LabelGrid).
inline constexpr std::size_t mostRobots = 32767;

struct PlanningProblem {
    ClassGrid grid;
    ClassTable classes;
    std::vector<MapPoint> starts; // one per robot, in the grid's frame; at most mostRobots
    // Each robot's own battery in seconds, for planners that fly on batteries; missing or 0: the planner's
    // battery_s.
    std::vector<double> batterySeconds;
    // Each robot's own speed over every passable class in m/s (an aircraft's cruise speed beside ground
    // robots); missing or 0: the class table's speeds. Every robot's times are at its own speed, and a
    // planner that balancesOwnSpeeds gives the faster robots more.
    std::vector<double> robotSpeeds;
    // Each robot's charger in the grid's frame, for planners that fly on batteries; missing or none: its
    // start.
    std::vector<std::optional<MapPoint>> chargers;
    // What happens to the robots during the mission (slowing down, stopping), for planners that simulate it.
    std::vector<SpeedEvent> events;
    PlannerChoice planner;
    // What the caller found while making the problem that the plan should tell its readers (planning at the
    // fleet's cruise speed, say): the plan's issues begin with these.
    std::vector<PlanIssue> notes;
};

} // namespace mcpp
