#include "core/allocation/OwnFlightReach.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace mcpp;

namespace {

// Flights of 1000 s, 100 s of them climbing and descending, out and back at 1 m/s: 450 m out at most, 425 m
// with a twentieth of the flight at work.
FlightLimits aircraft() {
    return FlightLimits{1000.0, 100.0, 300.0, 1.0, 1.0};
}

// 600 x 200 m of one land cover, one 10 m cell a pixel; robot 0 takes off at the west end, robot 1 at the
// east end; robot 0 holds the first `westColumns` columns and robot 1 the rest.
struct Strip {
    PlanningProblem problem;
    CellGraph graph;
    RegionAllocation regions;
};

Strip divided(int westColumns) {
    Strip strip;
    strip.problem = test::uniformProblem(60, 20, 10.0, {}, {});
    strip.problem.starts = {test::pixelCentre(strip.problem.grid, 0, 10),
                            test::pixelCentre(strip.problem.grid, 59, 10)};
    strip.graph = test::cellPerPixelGraph(strip.problem);
    for (const MapPoint& start : strip.problem.starts)
        strip.regions.startCell.push_back(strip.graph.cellAt(start));
    for (std::size_t id = 0; id < strip.graph.size(); ++id)
        strip.regions.robotOfCell.push_back(strip.graph.cell(static_cast<int>(id)).column < westColumns ? 0
                                                                                                        : 1);
    return strip;
}

// Whether every region is one piece holding its start.
bool regionsWhole(const CellGraph& graph, const RegionAllocation& regions) {
    for (std::size_t robot = 0; robot < regions.startCell.size(); ++robot)
        if (regions.robotOfCell[static_cast<std::size_t>(regions.startCell[robot])] !=
                static_cast<int>(robot) ||
            !test::regionIsConnected(graph, regions.robotOfCell, static_cast<int>(robot)))
            return false;
    return true;
}

} // namespace

class OwnFlightReachTest : public QObject {
    Q_OBJECT
  private slots:
    // A cell is within reach where its farthest free sub-cell centre is: from the west end's pixel centre
    // (x 5 m), column 42's east sub-cells lie 422.5 m off, column 43's 432.5 m, beyond the 425 m.
    void reachesCellsWhoseWaypointsLieWithin() {
        const Strip strip = divided(60);
        const OwnFlightReach reach(strip.problem.starts, {aircraft(), FlightLimits{}});
        QVERIFY(reach.limits());
        const auto cellIn = [&](int column) {
            return strip.graph.cell(strip.graph.cellAt(test::pixelCentre(strip.problem.grid, column, 10)));
        };
        QVERIFY(reach.reaches(0, cellIn(0)));
        QVERIFY(reach.reaches(0, cellIn(42)));
        QVERIFY(!reach.reaches(0, cellIn(43)));
        QVERIFY(!reach.reaches(0, cellIn(59)));
        QVERIFY(reach.reaches(1, cellIn(0))); // a rover reaches everywhere
        QVERIFY(!OwnFlightReach(strip.problem.starts, {FlightLimits{}, FlightLimits{}}).limits());
    }

    // Robot 0's cells beyond its reach go to robot 1, which reaches them and whose region they join; its
    // cells within reach stay; both regions stay whole and their costs are counted again.
    void handsCellsBeyondReachToARobotThatReaches() {
        Strip strip = divided(55);
        // 187.5 m out: robot 0 keeps less than half and takes nothing back, as its region held all it
        // reaches.
        const OwnFlightReach reach(strip.problem.starts,
                                   {FlightLimits{500.0, 100.0, 0.0, 1.0, 1.0}, FlightLimits{}});
        std::size_t beyond = 0;
        for (std::size_t id = 0; id < strip.graph.size(); ++id)
            beyond += strip.regions.robotOfCell[id] == 0 &&
                              !reach.reaches(0, strip.graph.cell(static_cast<int>(id)))
                          ? 1
                          : 0;
        QVERIFY(beyond > 0);
        const std::vector<int> before = strip.regions.robotOfCell;
        QCOMPARE(reach.handOver(strip.graph, strip.regions), static_cast<int>(beyond));
        std::vector<double> costs(2, 0.0);
        for (std::size_t id = 0; id < strip.graph.size(); ++id) {
            const Cell& cell = strip.graph.cell(static_cast<int>(id));
            const int robot = strip.regions.robotOfCell[id];
            QCOMPARE(robot, reach.reaches(0, cell) ? before[id] : 1);
            costs[static_cast<std::size_t>(robot)] += cell.coverSeconds();
        }
        QVERIFY(regionsWhole(strip.graph, strip.regions));
        QCOMPARE(strip.regions.costSeconds.size(), std::size_t{2});
        QVERIFY(std::abs(strip.regions.costSeconds[0] - costs[0]) < 1e-6);
        QVERIFY(std::abs(strip.regions.costSeconds[1] - costs[1]) < 1e-6);
    }

    // Robot 1's cells beyond its reach (425 m from the east end) go to robot 0, which is then left short and
    // takes border cells back from robot 1 within its own reach: the two end within a cell of even, each
    // within its reach and whole.
    void aRobotLeftShortTakesBackWithinItsReach() {
        Strip strip = divided(5);
        const OwnFlightReach reach(strip.problem.starts, {aircraft(), aircraft()});
        QVERIFY(reach.handOver(strip.graph, strip.regions) > 0);
        for (std::size_t id = 0; id < strip.graph.size(); ++id)
            QVERIFY(reach.reaches(static_cast<std::size_t>(strip.regions.robotOfCell[id]),
                                  strip.graph.cell(static_cast<int>(id))));
        QVERIFY(regionsWhole(strip.graph, strip.regions));
        const double cellCost = strip.graph.cell(0).coverSeconds();
        QVERIFY2(std::abs(strip.regions.costSeconds[0] - strip.regions.costSeconds[1]) <= cellCost + 1e-6,
                 qPrintable(QStringLiteral("%1 against %2 s")
                                .arg(strip.regions.costSeconds[0])
                                .arg(strip.regions.costSeconds[1])));
    }

    // A drone whose flights leave no time to work beyond 2.25 m (10 s of a 110 s flight after its climb and
    // descent) keeps only its start cell; the rover beside it takes the rest.
    void aDroneThatCannotWorkKeepsOnlyItsStart() {
        Strip strip = divided(30);
        const OwnFlightReach reach(strip.problem.starts,
                                   {FlightLimits{110.0, 100.0, 0.0, 1.0, 1.0}, FlightLimits{}});
        QVERIFY(reach.handOver(strip.graph, strip.regions) > 0);
        const auto held = std::count(strip.regions.robotOfCell.begin(), strip.regions.robotOfCell.end(), 0);
        QCOMPARE(held, 1);
        QCOMPARE(strip.regions.robotOfCell[static_cast<std::size_t>(strip.regions.startCell[0])], 0);
        QVERIFY(regionsWhole(strip.graph, strip.regions));
    }

    // Where the other robot's flights do not reach those cells either (21.25 m out from the east end), they
    // stay, as do its own beyond its reach: the division is left as it was.
    void cellsNoOtherRobotReachesStay() {
        Strip strip = divided(55);
        const OwnFlightReach reach(strip.problem.starts,
                                   {aircraft(), FlightLimits{150.0, 100.0, 0.0, 1.0, 1.0}});
        const std::vector<int> before = strip.regions.robotOfCell;
        QCOMPARE(reach.handOver(strip.graph, strip.regions), 0);
        QVERIFY(strip.regions.robotOfCell == before);
    }

    // Planned whole: a drone in a corner of 1 x 1 km whose flights work 425 m out beside one whose flights
    // reach the whole square. An even division would give the first about a quarter disc of 800 m; every
    // waypoint of its path lies within its reach instead, and the square is still covered.
    void plannedAircraftKeepToTheirOwnReach() {
        PlanningProblem problem = test::uniformProblem(100, 100, 10.0, {}, {});
        problem.planner = defaultPlannerChoice(MlctPlanner::plannerName);
        problem.starts = {test::pixelCentre(problem.grid, 0, 99), test::pixelCentre(problem.grid, 50, 50)};
        problem.robotFlights = {aircraft(), FlightLimits{5000.0, 100.0, 300.0, 1.0, 1.0}};
        const Plan plan = makePlanner(MlctPlanner::plannerName)->plan(problem, {});
        QCOMPARE(plan.paths.size(), std::size_t{2});
        for (std::size_t robot = 0; robot < 2; ++robot) {
            double farthest = 0.0;
            for (const Waypoint& point : plan.paths[robot].waypoints)
                farthest = std::max(farthest, std::hypot(point.x - problem.starts[robot].x,
                                                         point.y - problem.starts[robot].y));
            QVERIFY2(farthest <= problem.robotFlights[robot].workingReachMetres() + 1e-6,
                     qPrintable(QStringLiteral("robot %1: %2 m").arg(robot).arg(farthest)));
        }
        QVERIFY(plan.paths[0].waypoints.size() > 10); // the first drone still works near its start
        QCOMPARE(plan.metrics.unreachableAreaSquareMetres, 0.0);
        QVERIFY(std::abs(plan.metrics.coveredFraction - 1.0) < 1e-9);
        QVERIFY(test::checkAllInvariants(problem, plan).empty());
        const auto& stages = plan.metrics.stageMilliseconds;
        QVERIFY(std::any_of(stages.begin(), stages.end(),
                            [](const auto& stage) { return stage.first == "reach handover"; }));
    }
};

QTEST_GUILESS_MAIN(OwnFlightReachTest)
#include "test_own_flight_reach.moc"
