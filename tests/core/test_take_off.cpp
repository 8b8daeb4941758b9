#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/StartPointCheck.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace mcpp;

namespace {

// 20 x 20 pixels of grass, 10 m each, whose five western columns lie outside the area of interest (a road
// beside the field, say). Robot 1 stands on it, two and a half pixels west of the area; robot 2 in the field.
PlanningProblem roadsideProblem(std::vector<bool> flying) {
    PlanningProblem problem = test::uniformProblem(20, 20, 10.0, {}, {});
    ClassGrid& grid = problem.grid;
    grid.outside.assign(grid.values.size(), 0);
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < 5; ++column)
            grid.outside[grid.index(column, row)] = ClassGrid::outsideArea;
    problem.starts = {test::pixelCentre(grid, 2, 10), test::pixelCentre(grid, 15, 10)};
    problem.flyingRobots = std::move(flying);
    problem.planner = defaultPlannerChoice(MlctPlanner::plannerName);
    return problem;
}

const PlanIssue* issueCoded(const Plan& plan, const std::string& code) {
    const auto found = std::find_if(plan.issues.begin(), plan.issues.end(),
                                    [&](const PlanIssue& issue) { return issue.code == code; });
    return found == plan.issues.end() ? nullptr : &*found;
}

// Flights of 1000 s, 100 s of them climbing and descending, 300 s between two, out and back at `trip` m/s.
std::vector<FlightLimits> flights(double trip) {
    return {FlightLimits{1000.0, 100.0, 300.0, 1.0, trip}, FlightLimits{}};
}

// Each robot's time in the field: its flights as its limits make of its path.
void timeInTheField(PlanningProblem& problem) {
    problem.fieldSeconds = [limits = problem.robotFlights](const Plan& plan) {
        std::vector<double> seconds;
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot)
            seconds.push_back(limits[robot].leastFieldSecondsFor(plan.paths[robot].timeSeconds));
        return seconds;
    };
}

} // namespace

// An aircraft may stand outside the task area, on an obstacle or in another robot's cell: it takes off there
// and flies to the nearest free cell, where its path begins. A rover there is refused, as before.
class TakeOffTest : public QObject {
    Q_OBJECT
  private slots:
    void anAircraftOutsideTheAreaTakesOffThere() {
        const PlanningProblem problem = roadsideProblem({true, false});
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QVERIFY(plan.paths[0].takeOff.has_value());
        QVERIFY(*plan.paths[0].takeOff == problem.starts[0]);
        QVERIFY(!plan.paths[1].takeOff.has_value());
        // Its path begins in the field (east of the road's five columns), in the free cell nearest the road.
        const Waypoint& first = plan.paths[0].waypoints.front();
        QVERIFY2(first.x > problem.grid.originX + 50.0, qPrintable(QString::number(first.x)));
        const Cell& startCell = plan.cells.cell(plan.regions.startCell[0]);
        for (std::size_t id = 0; id < plan.cells.size(); ++id) {
            const Cell& cell = plan.cells.cell(static_cast<int>(id));
            QVERIFY(std::hypot(cell.centreX() - problem.starts[0].x, cell.centreY() - problem.starts[0].y) >=
                    std::hypot(startCell.centreX() - problem.starts[0].x,
                               startCell.centreY() - problem.starts[0].y) -
                        1e-9);
        }
        const PlanIssue* note = issueCoded(plan, "take-off-outside");
        QVERIFY(note != nullptr);
        QCOMPARE(note->severity, IssueSeverity::Information);
        QVERIFY2(note->message.starts_with("robot 1 takes off at its start " +
                                           describePoint(problem.starts[0]) +
                                           ", which is not in the task area: it lies outside the area of "
                                           "interest; it flies "),
                 note->message.c_str());
        QVERIFY(issueCoded(plan, "start-moved") == nullptr); // not a warning: nothing was moved
        const auto violations = test::checkAllInvariants(problem, plan, {});
        QVERIFY2(violations.empty(), qPrintable(QString::fromStdString(test::describe(violations))));
    }

    void aRoverOutsideTheAreaIsRefused() {
        const PlanningProblem problem = roadsideProblem({false, true});
        try {
            (void)makePlanner(MlctPlanner::plannerName)->plan(problem, {});
            QFAIL("a rover outside the area was planned");
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::StartOutsideArea);
            QCOMPARE(error.robot(), 0);
        }
    }

    // A rover standing in the field's edge cell nearest the road keeps it: the drone taking off beside it
    // flies to another, whichever robot comes first.
    void aRoverKeepsTheCellADroneTakingOffBesideItWouldTake() {
        PlanningProblem problem = roadsideProblem({true, false});
        const Plan alone = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        const Cell& nearest = alone.cells.cell(alone.regions.startCell[0]);
        problem.starts[1] = {nearest.centreX(), nearest.centreY()};
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QCOMPARE(plan.regions.startCell[1], alone.regions.startCell[0]);
        QVERIFY(plan.regions.startCell[0] != plan.regions.startCell[1]);
        QVERIFY(plan.paths[0].takeOff.has_value());
        QVERIFY(!plan.paths[1].takeOff.has_value());
    }

    // Not from a no-go zone (its flights would cross it), and not for a planner that flies on batteries
    // (its sorties start from the start's cell): refused as for a rover.
    void noTakeOffFromANoGoZoneNorOnBatteries() {
        PlanningProblem noGo = roadsideProblem({true, false});
        for (int row = 0; row < noGo.grid.rows; ++row)
            noGo.grid.outside[noGo.grid.index(2, row)] = ClassGrid::inNoGoZone;
        QVERIFY_THROWS_EXCEPTION(PlanningError, (void)makePlanner(MlctPlanner::plannerName)->plan(noGo, {}));
        PlanningProblem batteries = roadsideProblem({true, false});
        batteries.planner = defaultPlannerChoice("wavefront-battery");
        try {
            (void)makePlanner("wavefront-battery")->plan(batteries, {});
            QFAIL("a battery plan took off outside the area");
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::StartOutsideArea);
        }
    }

    // One flight out to where the path begins and back must fit (900 s of flight out and back).
    void aTakeOffBeyondOneFlightsReachIsRefused() {
        PlanningProblem problem = roadsideProblem({true, false});
        problem.robotFlights = flights(1.0); // 450 m: in reach
        timeInTheField(problem);
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QVERIFY(plan.paths[0].takeOff.has_value());
        const Cell& startCell = plan.cells.cell(plan.regions.startCell[0]);
        const double metres =
            std::hypot(startCell.centreX() - problem.starts[0].x, startCell.centreY() - problem.starts[0].y);
        problem.robotFlights = flights(0.9 * metres * 2.0 / 900.0); // reaching 90 % of the way
        try {
            (void)makePlanner(MlctPlanner::plannerName)->plan(problem, {});
            QFAIL("a take-off beyond reach was planned");
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::StartOutsideArea);
            QCOMPARE(error.robot(), 0);
            QVERIFY2(error.detail().find("farther than one flight can go and come back (" +
                                         formatDistance(0.9 * metres) + " each way)") != std::string::npos,
                     error.detail().c_str());
        }
    }

    // Every flight flies out from the take-off point and back: farther out on the road, the bound in the
    // field rises.
    void theBoundInTheFieldCountsTheTripsFromTheTakeOff() {
        std::vector<double> bounds;
        for (const int column : {4, 0}) {
            PlanningProblem problem = roadsideProblem({true, false});
            problem.starts[0] = test::pixelCentre(problem.grid, column, 10);
            problem.robotFlights = flights(0.5);
            timeInTheField(problem);
            const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
            QVERIFY(plan.paths[0].takeOff.has_value());
            QVERIFY(plan.metrics.fieldLowerBoundSeconds > 0.0);
            bounds.push_back(plan.metrics.fieldLowerBoundSeconds);
        }
        QVERIFY2(bounds[1] > bounds[0], qPrintable(QString("%1 vs %2").arg(bounds[1]).arg(bounds[0])));
    }
};

QTEST_APPLESS_MAIN(TakeOffTest)
#include "test_take_off.moc"
