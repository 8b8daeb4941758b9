#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/FlightLimits.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PlanIssue.hpp"
#include "core/model/SpeedEvent.hpp"
#include "core/parameters/PlannerChoice.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace mcpp {

struct Plan;

// The most robots one plan takes: robot numbers label region outlines in 16 bits (LabelGrid).
inline constexpr std::size_t mostRobots = 32767;

struct PlanningProblem {
    ClassGrid grid;
    ClassTable classes;
    std::vector<MapPoint> starts; // one per robot, in the grid's frame; at most mostRobots
    // Each robot's own battery in seconds, for planners that fly on batteries; missing or 0: the planner's
    // battery_s.
    std::vector<double> batterySeconds;
    // Each robot's time at its charger between two sorties in seconds (its vehicle's turnaround), for
    // planners that fly on batteries; missing or 0: the planner's recharge_s.
    std::vector<double> rechargeSeconds;
    // Each robot's own speed over every passable class in m/s (an aircraft's cruise speed beside ground
    // robots); missing or 0: the class table's speeds. Every robot's times are at its own speed, and a
    // planner that balancesOwnSpeeds gives the faster robots more.
    std::vector<double> robotSpeeds;
    // Each robot's time in the field on a plan (its waypoint files' flights and the turnarounds between
    // them), given where some robot's differs from its path's time (an aircraft with a flight time); unset:
    // the paths' times. A planner that balancesFieldTime plans again on each robot's field time per second
    // of its path as measured, while that brings the last robot home sooner.
    std::function<std::vector<double>(const Plan&)> fieldSeconds;
    // By robot, what its flights allow (a flight time, climbs and descents, turnarounds), given with
    // fieldSeconds; missing or without a flight time: it works in one go. The bound in the field counts it.
    std::vector<FlightLimits> robotFlights;
    // By robot, whether it flies (an aircraft): one whose start lies outside the task area, on an obstacle or
    // in another robot's cell takes off there, and its path begins at the nearest free cell. Missing: no.
    std::vector<bool> flyingRobots;
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
