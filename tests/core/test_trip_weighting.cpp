#include "core/allocation/TripWeighting.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace mcpp;

namespace {

// Flights of 1000 s, 100 s of them climbing and descending, 300 s between two, out and back at `trip` m/s.
FlightLimits aircraft(double trip) {
    return FlightLimits{1000.0, 100.0, 300.0, 1.0, trip};
}

// A robot's time in the field as flights from `home` make of its path, each waypoint reached at `trip` m/s
// from home and flown to the next at the path's own times: a flight climbs and descends, flies out to where
// its work begins and back from where it ends, and works while that return still fits; turnarounds between.
double fieldSecondsOf(const CoveragePath& path, MapPoint home, const FlightLimits& limits) {
    const auto way = [&](const Waypoint& point) {
        return std::hypot(point.x - home.x, point.y - home.y) / limits.tripMetresPerSecond;
    };
    const std::vector<Waypoint>& points = path.waypoints;
    double field = 0.0;
    std::size_t at = 0;
    while (at + 1 < points.size()) {
        double used = limits.climbAndDescentSeconds + way(points[at]);
        std::size_t next = at + 1;
        const auto legSeconds = [&](std::size_t to) {
            return std::hypot(points[to].x - points[to - 1].x, points[to].y - points[to - 1].y) /
                   points[to - 1].speedMetresPerSecond;
        };
        // At least one leg a flight, as a mission part holds two points.
        used += legSeconds(next);
        while (next + 1 < points.size() &&
               used + legSeconds(next + 1) + way(points[next + 1]) <= limits.flightSeconds)
            used += legSeconds(++next);
        field += used + way(points[next]) + (at > 0 ? limits.turnaroundSeconds : 0.0);
        at = next;
    }
    return field;
}

// Two aircraft taking off near the west end of a 600 x 200 m field, 120 m apart, flying out at
// `tripSpeed` m/s.
struct WestEndField {
    explicit WestEndField(double tripSpeed) : flights{aircraft(tripSpeed), aircraft(tripSpeed)} {
        problem = test::uniformProblem(60, 20, 10.0, {}, {});
        problem.planner = defaultPlannerChoice(MlctPlanner::plannerName);
        problem.planner.parameters.set("turn_s", 0.0);
        problem.starts = {test::pixelCentre(problem.grid, 0, 9), test::pixelCentre(problem.grid, 12, 10)};
    }
    // By robot, its time in the field.
    [[nodiscard]] std::vector<double> inTheField(const Plan& plan) const {
        std::vector<double> seconds;
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot)
            seconds.push_back(fieldSecondsOf(plan.paths[robot], problem.starts[robot], flights[robot]));
        return seconds;
    }
    // Planned on path time alone, then in the field: the robots' flights and field times given.
    [[nodiscard]] Plan onPaths() const { return makePlanner(MlctPlanner::plannerName)->plan(problem, {}); }
    [[nodiscard]] Plan flown() {
        PlanningProblem flying = problem;
        flying.robotFlights = flights;
        flying.fieldSeconds = [this](const Plan& plan) { return inTheField(plan); };
        Plan plan = makePlanner(MlctPlanner::plannerName)->plan(flying, {});
        violations = test::checkAllInvariants(flying, plan);
        return plan;
    }

    PlanningProblem problem;
    std::vector<FlightLimits> flights;
    std::vector<std::string> violations;
};

} // namespace

class TripWeightingTest : public QObject {
    Q_OBJECT
  private slots:
    // Work 100 m from the launch point, out and back at 1 m/s: 200 s of each flight's 900 s of work go on the
    // trip, so a second of work there takes (1000 + 300) / 700 s in the field; beyond one flight's reach, the
    // weight of a flight working a twentieth of its time.
    void weightsFollowTheWayOutAndBack() {
        const PlanningProblem problem = test::uniformProblem(50, 2, 10.0, {}, {});
        const CellGraph cells = test::cellPerPixelGraph(problem);
        const MapPoint launch = test::pixelCentre(problem.grid, 0, 0);
        const std::vector<float> weights = TripWeighting::weightsOf(cells, {launch}, {aircraft(1.0)});
        QCOMPARE(weights.size(), cells.size());
        int checked = 0;
        for (std::size_t id = 0; id < cells.size(); ++id) {
            const Cell cell = cells.cell(static_cast<int>(id));
            const double metres = std::hypot(cell.centreX() - launch.x, cell.centreY() - launch.y);
            const double expected = metres < 427.5 ? 1300.0 / (900.0 - 2.0 * metres) : 1300.0 / 45.0;
            QVERIFY2(std::abs(weights[id] - expected) <= 1e-5 * expected,
                     qPrintable(QString("%1 m: %2 against %3").arg(metres).arg(weights[id]).arg(expected)));
            checked += std::abs(metres - 100.0) < 1e-9 ? 1 : 0;
        }
        QCOMPARE(checked, 1);
        QVERIFY(std::abs(weights.front() - 1300.0F / 900.0F) < 1e-5F); // at the launch point: its climbs
        QVERIFY(std::abs(weights.back() - 1300.0F / 45.0F) < 1e-5F);   // 490 m out: beyond its reach
    }

    // A rover works in one go: the cells it launches nearest weigh 1, the aircraft's by their trips; with no
    // robot making trips there are no weights, and a division shares out the cells as they are.
    void cellsNearestARoverWeighOne() {
        const PlanningProblem problem = test::uniformProblem(40, 2, 10.0, {}, {});
        const CellGraph cells = test::cellPerPixelGraph(problem);
        const MapPoint west = test::pixelCentre(problem.grid, 0, 0);
        const MapPoint east = test::pixelCentre(problem.grid, 39, 0);
        const std::vector<float> weights =
            TripWeighting::weightsOf(cells, {west, east}, {aircraft(1.0), FlightLimits{}});
        for (std::size_t id = 0; id < cells.size(); ++id) {
            const Cell cell = cells.cell(static_cast<int>(id));
            const bool roverSide = cell.centreX() > (west.x + east.x) / 2.0;
            QVERIFY(roverSide ? weights[id] == 1.0F : weights[id] > 1.0F);
        }
        // A robot past the end of the flights works in one go, as the problem says of robotFlights.
        QCOMPARE(TripWeighting::weightsOf(cells, {west, east}, {aircraft(1.0)}), weights);
        QVERIFY(TripWeighting::weightsOf(cells, {west, east}, {FlightLimits{}, FlightLimits{}}).empty());
        const TripWeighting none(cells, {west, east}, {FlightLimits{}, FlightLimits{}});
        QVERIFY(!none.weighs());
        QCOMPARE(&none.divided(cells), &cells);
        const TripWeighting some(cells, {west, east}, {aircraft(1.0), FlightLimits{}});
        QVERIFY(some.weighs());
        QVERIFY(some.divided(cells).cell(0).coverSeconds() > cells.cell(0).coverSeconds());
    }

    // Two aircraft from the west end of the field flying out at 1.2 m/s: balanced on path time, the one
    // working the east end spends much of each flight on the way there and comes home 1.43 times as late as
    // the other. Weighing the cells by their trips gives it less path, and the two come home within 5 % of
    // each other, the last 17 % sooner.
    void twoAircraftFromOneEndComeHomeTogether() {
        WestEndField field(1.2);
        const Plan onPaths = field.onPaths();
        const Plan weighed = field.flown();
        QVERIFY2(field.violations.empty(), test::describe(field.violations).c_str());
        const std::vector<double> before = field.inTheField(onPaths);
        const std::vector<double> after = field.inTheField(weighed);
        const QString figures =
            QString("%1 %2 against %3 %4").arg(after[0]).arg(after[1]).arg(before[0]).arg(before[1]);
        const auto [firstBefore, lastBefore] = std::minmax(before[0], before[1]);
        const auto [firstAfter, lastAfter] = std::minmax(after[0], after[1]);
        QVERIFY2(lastBefore > 1.3 * firstBefore, qPrintable(figures));
        QVERIFY2(lastAfter <= 1.05 * firstAfter, qPrintable(figures));
        QVERIFY2(lastAfter < 0.9 * lastBefore, qPrintable(figures));
        // The robot working far out flies less path.
        const std::size_t far = before[0] < before[1] ? 1 : 0;
        QVERIFY(weighed.paths[far].timeSeconds < onPaths.paths[far].timeSeconds);
        QCOMPARE(weighed.countedFieldPaces.size(), std::size_t{2});
        QVERIFY(onPaths.countedFieldPaces.empty());
    }

    // Flying out faster, the weights over-correct (each cell priced at its own distance, while a flight flies
    // out to where its work begins): at 1.5 m/s the last robot came home at 28 707 s against 27 582 s
    // balanced on path time. A division on the paths weighed by the paces flown is tried too, so the last
    // robot is never home later than balanced on path time.
    void neverHomeLaterThanBalancedOnPaths_data() {
        QTest::addColumn<double>("tripSpeed");
        QTest::newRow("1.5 m/s") << 1.5;
        QTest::newRow("2 m/s") << 2.0;
        QTest::newRow("3 m/s") << 3.0;
    }
    void neverHomeLaterThanBalancedOnPaths() {
        QFETCH(double, tripSpeed);
        WestEndField field(tripSpeed);
        const std::vector<double> before = field.inTheField(field.onPaths());
        const std::vector<double> after = field.inTheField(field.flown());
        QVERIFY2(field.violations.empty(), test::describe(field.violations).c_str());
        const QString figures =
            QString("%1 %2 against %3 %4").arg(after[0]).arg(after[1]).arg(before[0]).arg(before[1]);
        QVERIFY2(std::max(after[0], after[1]) <= std::max(before[0], before[1]), qPrintable(figures));
    }
};

QTEST_GUILESS_MAIN(TripWeightingTest)
#include "test_trip_weighting.moc"
