#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mcpp {

struct RobotMetrics {
    int robot = 0;
    int cells = 0;
    double areaSquareMetres = 0.0;
    double lengthMetres = 0.0;
    double timeSeconds = 0.0;
    double turnSeconds = 0.0; // the part of timeSeconds lost to turns
    double costSeconds = 0.0; // allocation cost of its region
    int turns = 0;
    double connectorSeconds = 0.0; // what its steps between cells of different sizes take beyond their travel
};

// A robot that starts in a part of the map cut off from the largest part (by area) holding starts: it can
// cover only its pocket, whatever the allocation.
struct ConfinedRobot {
    int robot = 0;
    double pocketAreaSquareMetres = 0.0;
    int robotsInPocket = 1;
};

// What a plan reports (spec section 6).
struct PlanMetrics {
    std::vector<RobotMetrics> robots;
    double makespanSeconds = 0.0;
    // No plan making these turns and these steps between cells of different sizes can finish sooner: the
    // largest, over the map's connected parts holding starts, of the part's cells' travel time and its
    // robots' turn and connector time, divided by the robots starting in it. The ratio to it measures
    // balance of real time; turns and connectors are counted apart.
    double lowerBoundSeconds = 0.0;
    std::vector<ConfinedRobot> confinedRobots; // robots outside the largest such part
    double ratio = 0.0;                        // makespan / lower bound
    double passableAreaSquareMetres = 0.0;
    double coveredAreaSquareMetres = 0.0;
    double coveredFraction = 0.0; // of the passable area
    double unreachableAreaSquareMetres = 0.0;
    double repeatedFraction = 0.0; // path length beyond one pass over every sub-cell, relative to it
    std::vector<std::pair<std::string, double>> stageMilliseconds;

    [[nodiscard]] int totalTurns() const {
        int turns = 0;
        for (const RobotMetrics& robot : robots)
            turns += robot.turns;
        return turns;
    }
    [[nodiscard]] double totalLengthMetres() const {
        double length = 0.0;
        for (const RobotMetrics& robot : robots)
            length += robot.lengthMetres;
        return length;
    }
};

} // namespace mcpp
