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
    double costSeconds = 0.0; // allocation cost of its region
    int turns = 0;
};

// What a plan reports (spec section 6).
struct PlanMetrics {
    std::vector<RobotMetrics> robots;
    double makespanSeconds = 0.0;
    double lowerBoundSeconds = 0.0; // sum of all reachable cell costs / robots
    double ratio = 0.0;             // makespan / lower bound
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
