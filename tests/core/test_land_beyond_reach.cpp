#include "core/model/PlanningError.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "core/planners/LandBeyondReach.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace mcpp;

namespace {

// Flights of 1000 s, 100 s of them climbing and descending, out and back at 1 m/s: 450 m out at most.
FlightLimits aircraft() {
    return FlightLimits{1000.0, 100.0, 300.0, 1.0, 1.0};
}

// A 1000 x 100 m strip of one land cover (10 m pixels, FOV 5 m) with an aircraft starting at its west end.
PlanningProblem westEndStrip() {
    PlanningProblem problem = test::uniformProblem(100, 10, 10.0, {}, {});
    problem.planner = defaultPlannerChoice(MlctPlanner::plannerName);
    problem.starts = {test::pixelCentre(problem.grid, 0, 4)};
    problem.robotFlights = {aircraft()};
    return problem;
}

// The area of the strip's pixels whose centres lie within (`within`) or beyond `metres` of the start.
double stripArea(const PlanningProblem& problem, double metres, bool within) {
    double area = 0.0;
    for (int row = 0; row < problem.grid.rows; ++row)
        for (int column = 0; column < problem.grid.columns; ++column) {
            const MapPoint centre = test::pixelCentre(problem.grid, column, row);
            const double distance =
                std::hypot(centre.x - problem.starts[0].x, centre.y - problem.starts[0].y);
            if ((distance <= metres) == within)
                area += problem.grid.pixelWidth * problem.grid.pixelHeight;
        }
    return area;
}

const PlanIssue* issueCoded(const Plan& plan, const std::string& code) {
    const auto found = std::find_if(plan.issues.begin(), plan.issues.end(),
                                    [&code](const PlanIssue& issue) { return issue.code == code; });
    return found == plan.issues.end() ? nullptr : &*found;
}

} // namespace

class LandBeyondReachTest : public QObject {
    Q_OBJECT
  private slots:
    // No waypoint lies farther than one flight reaches (450 m): the land beyond is left out, counted as
    // passable land no robot covers, and said; land well within the reach is still covered.
    void leavesOutLandNoFlightCanWork() {
        const PlanningProblem problem = westEndStrip();
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QCOMPARE(plan.paths.size(), std::size_t{1});
        double farthest = 0.0;
        for (const Waypoint& point : plan.paths[0].waypoints)
            farthest =
                std::max(farthest, std::hypot(point.x - problem.starts[0].x, point.y - problem.starts[0].y));
        QVERIFY2(farthest <= aircraft().reachMetres(), qPrintable(QString::number(farthest)));
        const PlanMetrics& metrics = plan.metrics;
        QCOMPARE(metrics.passableAreaSquareMetres, 100000.0);
        QVERIFY(metrics.unreachableAreaSquareMetres >= stripArea(problem, aircraft().reachMetres(), false));
        QVERIFY(metrics.coveredAreaSquareMetres >= stripArea(problem, 350.0, true));
        QCOMPARE(metrics.coveredFraction, metrics.coveredAreaSquareMetres / metrics.passableAreaSquareMetres);
        const PlanIssue* said = issueCoded(plan, "beyond-flight-reach");
        QVERIFY(said != nullptr);
        QCOMPARE(said->severity, IssueSeverity::Warning);
        QVERIFY2(said->message.find("left out of the plan") != std::string::npos, said->message.c_str());
        QVERIFY2(said->message.find("991 m from the nearest start") != std::string::npos,
                 said->message.c_str());
        QVERIFY(test::checkAllInvariants(problem, plan).empty());
        // The time finding that land took is the plan's first stage: the report's timings add up.
        QCOMPARE(metrics.stageMilliseconds.front().first, std::string("flight reach"));
    }

    // The land found beyond: its area, the mask flagging it and nothing else, and the farthest point.
    void findsTheLandBeyondEveryReach() {
        PlanningProblem problem = westEndStrip();
        problem.grid.values[problem.grid.index(99, 0)] = 99; // water in a far corner: not passable land
        // Nor a class marked passable at 0 m/s: an obstacle too.
        problem.classes.set({7, "stopped", 0x808080, 0.0, 5.0, true});
        problem.grid.values[problem.grid.index(98, 0)] = 7;
        const std::optional<LandBeyondReach> land = landBeyondEveryReach(problem);
        QVERIFY(land.has_value());
        const auto flagged = static_cast<double>(
            std::count(land->outside.begin(), land->outside.end(), ClassGrid::beyondFlightReach));
        QCOMPARE(land->passableSquareMetres, (flagged - 2.0) * 100.0);
        QVERIFY(flagged * 100.0 >= stripArea(problem, aircraft().reachMetres(), false));
        QVERIFY(land->leastReachMetres < aircraft().reachMetres());
        QCOMPARE(land->leastReachMetres, land->mostReachMetres);
        // The pixel at the strip's far corner, 990 m east and 50 m south of the start.
        QCOMPARE(land->farthest.x, test::pixelCentre(problem.grid, 99, 9).x);
        QCOMPARE(land->farthest.y, test::pixelCentre(problem.grid, 99, 9).y);
        QVERIFY(std::abs(land->farthestMetres - std::hypot(990.0, 50.0)) < 1e-6);
        QVERIFY(problem.grid.outside.empty()); // the problem itself is not changed
    }

    // The land left out has no cells, yet the plan's labels (what regions.tif, the unreachable layer and the
    // picture are drawn from) mark it as land no robot covers: as much of it as the plan counts, and none
    // within the reach.
    void theLandLeftOutIsLabelledUnreachable() {
        const PlanningProblem problem = westEndStrip();
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QVERIFY(!plan.landBeyondReach.empty());
        const LabelGrid labels = regionLabels(plan);
        double unreachableArea = 0.0;
        double nearest = std::numeric_limits<double>::infinity();
        for (int row = 0; row < labels.rows; ++row)
            for (int column = 0; column < labels.columns; ++column)
                if (labels.at(column, row) == unreachableLabel) {
                    unreachableArea += labels.pixelSize * labels.pixelSize;
                    nearest = std::min(nearest, std::hypot(labels.x(column + 0.5) - problem.starts[0].x,
                                                           labels.y(row + 0.5) - problem.starts[0].y));
                }
        QVERIFY2(std::abs(unreachableArea - plan.metrics.unreachableAreaSquareMetres) <=
                     1e-9 * plan.metrics.unreachableAreaSquareMetres,
                 qPrintable(QStringLiteral("%1 against %2")
                                .arg(unreachableArea)
                                .arg(plan.metrics.unreachableAreaSquareMetres)));
        QVERIFY2(nearest > 350.0, qPrintable(QString::number(nearest)));
        // The grid reaches the strip's east end, past the plan's cells.
        QVERIFY(labels.x(labels.columns) >= problem.grid.maxX() - 1e-9);
    }

    // A robot reaching everywhere (a rover, or an aircraft whose trips are not counted) covers the land the
    // aircraft cannot: nothing is left out.
    void nothingLeftOutWhereARobotReachesEverywhere() {
        PlanningProblem problem = westEndStrip();
        problem.starts.push_back(test::pixelCentre(problem.grid, 1, 4));
        problem.robotFlights.push_back(FlightLimits{});
        QVERIFY(!landBeyondEveryReach(problem).has_value());
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QVERIFY(issueCoded(plan, "beyond-flight-reach") == nullptr);
        QCOMPARE(plan.metrics.unreachableAreaSquareMetres, 0.0);
    }

    // Land within reach joined to the start only through land beyond it is cut off by the reach's edge: the
    // warning of unreachable land names that edge.
    void landCutOffByTheReachSaysSo() {
        // 500 x 500 m, a wall of water 200 m east of the start with its gap 490 m south, beyond reach.
        std::vector<bool> wall(50 * 50, false);
        for (int row = 0; row < 49; ++row)
            wall[static_cast<std::size_t>(row * 50 + 20)] = true;
        PlanningProblem problem = test::uniformProblem(50, 50, 10.0, wall, {});
        problem.planner = defaultPlannerChoice(MlctPlanner::plannerName);
        problem.starts = {test::pixelCentre(problem.grid, 0, 0)};
        problem.robotFlights = {aircraft()};
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        const PlanIssue* cutOff = issueCoded(plan, "unreachable-area");
        QVERIFY(cutOff != nullptr);
        QVERIFY2(cutOff->message.find("the edge of the flights' reach cuts it off") != std::string::npos,
                 cutOff->message.c_str());
        QVERIFY(issueCoded(plan, "beyond-flight-reach") != nullptr);
    }

    // A drone of short flights at the west end, one of long flights at the east end: the land between them
    // lies beyond both reaches, so the west drone is confined to the little it reaches. The warning names the
    // reach's edge as what may cut it off and asks for a nearer start or longer flights, not for a start in
    // the largest part (which it could not fly from its own start). A wall of water in the same place says
    // the usual words.
    void aDroneConfinedByTheReachIsToldWhy() {
        PlanningProblem problem = westEndStrip();
        problem.starts.push_back(test::pixelCentre(problem.grid, 99, 4));
        problem.robotFlights = {FlightLimits{300.0, 100.0, 300.0, 1.0, 1.0},   // 100 m out at most
                                FlightLimits{1400.0, 100.0, 300.0, 1.0, 1.0}}; // 650 m out
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QVERIFY(issueCoded(plan, "beyond-flight-reach") != nullptr);
        const PlanIssue* confined = issueCoded(plan, "confined-robot");
        QVERIFY(confined != nullptr);
        QCOMPARE(confined->severity, IssueSeverity::Warning); // it stands idle most of the mission
        QVERIFY2(confined->message.starts_with("robot 1 starts in a part of the map cut off from the rest ("),
                 confined->message.c_str());
        QVERIFY2(
            confined->message.find(") by the land beyond every flight's reach or by impassable land, and "
                                   "can cover only that part") != std::string::npos,
            confined->message.c_str());
        QVERIFY2(confined->message.find("give it a longer flight time") != std::string::npos,
                 confined->message.c_str());
        QVERIFY2(confined->message.find("start it in the largest part") == std::string::npos,
                 confined->message.c_str());

        // Water from 100 m to 350 m east of the west start, and rovers: the land cover cuts the part off.
        std::vector<bool> water(100 * 10, false);
        for (int row = 0; row < 10; ++row)
            for (int column = 10; column < 35; ++column)
                water[static_cast<std::size_t>(row * 100 + column)] = true;
        PlanningProblem walled = test::uniformProblem(100, 10, 10.0, water, {});
        walled.planner = problem.planner;
        walled.starts = problem.starts;
        const Plan walledPlan = makePlanner(MlctPlanner::plannerName)->plan(walled, {});
        const PlanIssue* walledIn = issueCoded(walledPlan, "confined-robot");
        QVERIFY(walledIn != nullptr);
        QVERIFY2(walledIn->message.find("flight's reach") == std::string::npos, walledIn->message.c_str());
        QVERIFY2(walledIn->message.find("start it in the largest part") != std::string::npos,
                 walledIn->message.c_str());
    }

    // Cells far larger than what is left within reach (two 100 m fields of view a side, 42 m of reach
    // left): no plan, and the error says the reach is why, not the land cover.
    void cellsTooLargeForTheReachSayTheReach() {
        PlanningProblem problem = westEndStrip();
        problem.classes.set({1, "grass", 0x88cc44, 1.0, 100.0, true});
        problem.robotFlights = {FlightLimits{200.0, 20.0, 0.0, 1.0, 1.0}}; // 90 m out at most
        std::string said;
        try {
            (void)makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::NoPassableCell);
            said = error.what();
        }
        QVERIFY2(said.starts_with("no passable land lies within what one flight can cover from any start"),
                 said.c_str());
    }

    // Aircraft whose flights reach the whole map leave nothing out.
    void nothingLeftOutWithinReach() {
        PlanningProblem problem = westEndStrip();
        problem.robotFlights = {FlightLimits{3000.0, 100.0, 300.0, 1.0, 1.0}}; // 1450 m out
        QVERIFY(!landBeyondEveryReach(problem).has_value());
    }
};

QTEST_GUILESS_MAIN(LandBeyondReachTest)
#include "test_land_beyond_reach.moc"
