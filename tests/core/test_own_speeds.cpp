#include "core/allocation/BatteryRange.hpp"
#include "core/coverage/OwnSpeeds.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>
#include <numbers>

using namespace mcpp;

namespace {

// 30 x 30 cells of grass at 1 m/s, two robots in opposite corners; the second at its own `speed`.
PlanningProblem fleetProblem(double speed, const std::string& planner, double turnSeconds) {
    PlanningProblem problem = test::uniformProblem(30, 30, 10.0, {}, {});
    problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 29, 29)};
    problem.robotSpeeds = {0.0, speed};
    problem.planner = defaultPlannerChoice(planner);
    problem.planner.parameters.set("turn_s", turnSeconds);
    return problem;
}

// The path's quarter turns, from its geometry: 1 for a right angle, 2 for a U-turn.
double quarterTurns(const CoveragePath& path) {
    double quarters = 0.0;
    for (std::size_t i = 1; i + 1 < path.waypoints.size(); ++i) {
        const Waypoint& a = path.waypoints[i - 1];
        const Waypoint& b = path.waypoints[i];
        const Waypoint& c = path.waypoints[i + 1];
        if ((a.x == b.x && a.y == b.y) || (b.x == c.x && b.y == c.y))
            continue;
        double angle = std::abs(std::atan2(c.y - b.y, c.x - b.x) - std::atan2(b.y - a.y, b.x - a.x));
        if (angle > std::numbers::pi)
            angle = 2.0 * std::numbers::pi - angle;
        quarters += angle / (std::numbers::pi / 2.0);
    }
    return quarters;
}

int issueCount(const Plan& plan, const std::string& code) {
    int count = 0;
    for (const PlanIssue& issue : plan.issues)
        count += issue.code == code ? 1 : 0;
    return count;
}

} // namespace

class OwnSpeedsTest : public QObject {
    Q_OBJECT

  private slots:
    // A robot three times as fast takes about three times the ground, and both finish together.
    void aFasterRobotTakesMoreGround() {
        const PlanningProblem problem = fleetProblem(3.0, "mcpp-mlct", 2.0);
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, plan);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        const RobotMetrics& slow = plan.metrics.robots[0];
        const RobotMetrics& fast = plan.metrics.robots[1];
        QVERIFY2(fast.areaSquareMetres > 2.0 * slow.areaSquareMetres,
                 qPrintable(
                     QStringLiteral("%1 against %2").arg(fast.areaSquareMetres).arg(slow.areaSquareMetres)));
        const double longer = std::max(slow.timeSeconds, fast.timeSeconds);
        const double shorter = std::min(slow.timeSeconds, fast.timeSeconds);
        QVERIFY2(longer <= 1.03 * shorter,
                 qPrintable(QStringLiteral("%1 against %2").arg(longer).arg(shorter)));
        QCOMPARE(issueCount(plan, "own-speeds-unbalanced"), 0);
        // Each robot drives at its speed, every turn at the fixed 2 s a quarter turn.
        for (const Waypoint& waypoint : plan.paths[1].waypoints)
            QCOMPARE(waypoint.speedMetresPerSecond, 3.0F);
        for (const Waypoint& waypoint : plan.paths[0].waypoints)
            QCOMPARE(waypoint.speedMetresPerSecond, 1.0F);
        const CoveragePath& path = plan.paths[1];
        const double expected = path.lengthMetres / 3.0 + 2.0 * quarterTurns(path);
        QVERIFY2(std::abs(path.timeSeconds - expected) < 1e-6 * expected,
                 qPrintable(QStringLiteral("%1 against %2").arg(path.timeSeconds).arg(expected)));
        QCOMPARE(plan.robotSpeeds, problem.robotSpeeds);
    }

    // With free turns the bound is the map's travel shared by what each robot does in a second: a robot at
    // 1 m/s and one at 3 m/s do a quarter and three quarters of it.
    void theBoundSharesTheWorkByEachRobotsSpeed() {
        const PlanningProblem problem = fleetProblem(3.0, "mcpp-mlct", 0.0);
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        double travel = 0.0;
        for (std::size_t id = 0; id < plan.cells.size(); ++id)
            if (plan.regions.robotOfCell[id] >= 0)
                travel += plan.cells.cell(static_cast<int>(id)).travelSeconds();
        QVERIFY(travel > 0.0);
        QVERIFY2(std::abs(plan.metrics.lowerBoundSeconds - travel / 4.0) < 1e-9 * travel,
                 qPrintable(
                     QStringLiteral("%1 against %2").arg(plan.metrics.lowerBoundSeconds).arg(travel / 4.0)));
        QVERIFY(plan.metrics.makespanSeconds >= plan.metrics.lowerBoundSeconds);
        QVERIFY2(plan.metrics.ratio < 1.05, qPrintable(QString::number(plan.metrics.ratio)));
    }

    // A planner that divides the work at one speed still times each robot at its own, and says so.
    void otherPlannersTimeOwnSpeedsAndSaySo() {
        const PlanningProblem problem = fleetProblem(3.0, "darp", 2.0);
        const Plan plan = makePlanner("darp")->plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, plan);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        QCOMPARE(issueCount(plan, "own-speeds-unbalanced"), 1);
        const CoveragePath& path = plan.paths[1];
        QVERIFY(std::abs(path.timeSeconds - (path.lengthMetres / 3.0 + 2.0 * quarterTurns(path))) <
                1e-6 * path.timeSeconds);
    }

    // Robots on batteries fly their sorties at their own speeds: a drone three times as fast reaches
    // farther on one charge, takes more ground, and no sortie outlasts its battery.
    void batterySortiesAreFlownAtOwnSpeeds() {
        const PlanningProblem problem = fleetProblem(3.0, "wavefront-battery", 2.0);
        const Plan plan = makePlanner("wavefront-battery")->plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, plan);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        QCOMPARE(issueCount(plan, "own-speeds-ignored"), 0);
        QCOMPARE(issueCount(plan, "own-speeds-unbalanced"), 0);
        QCOMPARE(plan.robotSpeeds, problem.robotSpeeds);
        for (const Waypoint& waypoint : plan.paths[1].waypoints)
            QCOMPARE(waypoint.speedMetresPerSecond, 3.0F);
        QVERIFY(plan.paths[0].waypoints.front().speedMetresPerSecond < 3.0F);
        const double slowArea = plan.metrics.robots[0].areaSquareMetres;
        const double fastArea = plan.metrics.robots[1].areaSquareMetres;
        QVERIFY2(fastArea > 1.5 * slowArea,
                 qPrintable(QStringLiteral("%1 against %2").arg(fastArea).arg(slowArea)));
    }

    // A drone behind a slow rover's charger, on a corridor: the rover's slow way does not bar the drone's
    // from the land past the rover, which only the drone reaches on one charge (its region stops at the
    // rover's, so the land is left out by the rover rather than beyond every charger).
    void aSlowRobotDoesNotBarAFastOnesReach() {
        PlanningProblem problem =
            test::drawnProblem(std::vector<std::string>(2, std::string(100, '.')), {{0.5, 0.5}, {10.5, 0.5}});
        problem.robotSpeeds = {5.0, 0.0};
        problem.planner = defaultPlannerChoice("wavefront-battery");
        problem.planner.parameters.set("battery_s", 101.0);
        problem.planner.parameters.set("turn_s", 0.0);
        const Plan plan = makePlanner("wavefront-battery")->plan(problem, {});
        const auto violations =
            test::checkAllInvariants(problem, plan, makePlanner("wavefront-battery")->description().promises);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        QCOMPARE(issueCount(plan, "beyond-every-charger"), 0);
        // The far end is the drone's 98 m away at 5 m/s, not the rover's 88 m at 1 m/s.
        const BatteryRange range{101.0, problem.robotSpeeds};
        const std::vector<double> seconds = range.secondsFromChargers(plan.cells, plan.regions.startCell);
        const int farEnd = plan.cells.cellAt({problem.grid.originX + 99.0, problem.grid.originY - 1.0});
        QVERIFY(farEnd >= 0);
        QVERIFY2(std::abs(seconds[static_cast<std::size_t>(farEnd)] - 98.0 / 5.0) < 1e-9,
                 qPrintable(QString::number(seconds[static_cast<std::size_t>(farEnd)])));
    }

    // A robot walled into a pocket is still named, though the parts' even shares no longer bound the plan.
    void aWalledInRobotIsStillNamed() {
        std::vector<bool> blocked(30 * 30, false);
        for (int row = 0; row < 30; ++row)
            blocked[static_cast<std::size_t>(row * 30 + 8)] = true; // a wall along column 8
        PlanningProblem problem = test::uniformProblem(30, 30, 10.0, blocked, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 29, 29),
                          test::pixelCentre(problem.grid, 12, 0)};
        problem.robotSpeeds = {0.0, 3.0, 0.0};
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, plan);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        QCOMPARE(plan.metrics.confinedRobots.size(), std::size_t{1});
        QCOMPARE(plan.metrics.confinedRobots.front().robot, 0);
        QVERIFY(plan.metrics.makespanSeconds >= plan.metrics.lowerBoundSeconds);
    }

    // Priced from the speed (the default, at 1 m/s2), a quarter turn costs the fast robot 3 s, the other 1 s.
    void turnsArePricedAtTheRobotsOwnSpeed() {
        PlanningProblem problem = fleetProblem(3.0, "mcpp-mlct", 0.0);
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, plan);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        for (std::size_t robot = 0; robot < 2; ++robot) {
            const CoveragePath& path = plan.paths[robot];
            const double speed = robot == 0 ? 1.0 : 3.0;
            QVERIFY(quarterTurns(path) > 10.0);
            const double expected = path.lengthMetres / speed + speed * quarterTurns(path);
            QVERIFY2(std::abs(path.timeSeconds - expected) < 1e-6 * expected,
                     qPrintable(QStringLiteral("robot %1: %2 against %3")
                                    .arg(robot)
                                    .arg(path.timeSeconds)
                                    .arg(expected)));
        }
    }

    void pacesFollowTheSpeed() {
        const PlanningProblem problem = fleetProblem(4.0, "mcpp-mlct", 0.0);
        const CellGraph graph = test::cellPerPixelGraph(problem);
        const std::vector<double> paces = robotPaces(graph, problem.robotSpeeds, 2);
        QCOMPARE(paces[0], 1.0);
        QVERIFY(std::abs(paces[1] - 0.25) < 1e-12); // no turns priced: travel alone, four times as fast
        QVERIFY(!someOwnSpeed({0.0, 0.0}));
        QCOMPARE(ownSpeedOf({0.0, 4.0}, 5), 0.0);
    }
};

QTEST_APPLESS_MAIN(OwnSpeedsTest)
#include "test_own_speeds.moc"
