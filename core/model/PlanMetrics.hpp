#pragma once

#include <algorithm>
#include <cmath>
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
    // When it is done in the field, where the problem measures it (PlanningProblem::fieldSeconds): its
    // flights and the turnarounds between them, or its path's time for a robot that works in one go; 0
    // otherwise.
    double fieldSeconds = 0.0;
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
    // Where robots confined to a part of their own set the bound (their part's work is theirs alone, so
    // every plan has the same ratio), the balance of the others: the largest, over parts shared by several
    // robots, of their longest time over the part's own bound. 0 elsewhere: the map one part, no part
    // shared, a shared part or a battery's charges setting the bound.
    double sharedPartsRatio = 0.0;
    // A detection plan's bound: the passes its targets need, each priced at the fastest class's speed and
    // the best sensor's reach. Sound, but far looser than other plans' bounds: its ratio reads high for an
    // even plan and is not to be set beside theirs.
    bool boundOfDetectionPasses = false;
    // Where the mission gives robots speeds of their own, the planner timed them at the class table's
    // (own-speeds-ignored): its times are not to be set beside a plan's that keeps them.
    bool ownSpeedsIgnored = false;
    // Where the problem measures time in the field (PlanningProblem::fieldSeconds), when the last robot is
    // done there; and where some robot's path is split into flights (PlanningProblem::robotFlights), the
    // least any plan making these turns could take there: the work the path bound counts, shared out in full
    // flights with the fewest turnarounds; where aircraft at a cruise speed reach all their work, each of
    // their flights spends 2 d getting to work farther than d from its start and back. 0 otherwise, and both
    // 0 for a battery plan, whose paths hold their charges.
    double fieldMakespanSeconds = 0.0;
    double fieldLowerBoundSeconds = 0.0;
    // Where some robot flies out to its work but cannot reach all of it in one flight, the bound in the
    // field leaves the trips out (their flights are longer than a battery). Not kept in saved plans.
    bool fieldBoundWithoutTrips = false;
    double passableAreaSquareMetres = 0.0;
    double coveredAreaSquareMetres = 0.0;
    double coveredFraction = 0.0; // of the passable area
    double unreachableAreaSquareMetres = 0.0;
    double repeatedFraction = 0.0; // path length beyond one pass over every sub-cell, relative to it
    std::vector<std::pair<std::string, double>> stageMilliseconds;

    // Whether the ratio says less of balance than sharedPartsRatio does: robots alone in parts of their own
    // set the bound, and the robots sharing parts are balanced otherwise (to the third decimal).
    [[nodiscard]] bool boundSetByLoneRobots() const {
        return sharedPartsRatio > 0.0 && std::abs(sharedPartsRatio - ratio) >= 0.0005;
    }

    // Whether the plan says when its robots are done in the field (flights split its missions): then that,
    // not the paths' makespan, is what a field team waits for and what plans are ranked by.
    [[nodiscard]] bool timedInTheField() const {
        return fieldMakespanSeconds > 0.0 && fieldLowerBoundSeconds > 0.0;
    }
    // The longest time in the field over the shortest, among robots with work: how evenly the robots come
    // home; 0 without times in the field. (Makespan over the bound in the field says more of how far the
    // work lies from the starts than of the plan.)
    [[nodiscard]] double fieldSpread() const {
        const auto [first, last] = firstAndLastHome();
        return first != nullptr ? last->fieldSeconds / first->fieldSeconds : 0.0;
    }
    // The robots with work that come home first and last (null without times in the field).
    [[nodiscard]] std::pair<const RobotMetrics*, const RobotMetrics*> firstAndLastHome() const {
        const RobotMetrics* first = nullptr;
        const RobotMetrics* last = nullptr;
        for (const RobotMetrics& robot : robots) {
            if (!(robot.fieldSeconds > 0.0))
                continue;
            if (first == nullptr || robot.fieldSeconds < first->fieldSeconds)
                first = &robot;
            if (last == nullptr || robot.fieldSeconds > last->fieldSeconds)
                last = &robot;
        }
        return {first, last};
    }
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
