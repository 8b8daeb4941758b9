#include "core/coverage/PathMeasurement.hpp"
#include "core/model/FlightLimits.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlanMetricsCalculator.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "core/planners/UnevenField.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>

using namespace mcpp;

namespace {

// Flights of 1000 s, of which 100 s climb and descend, 300 s on the ground between two.
constexpr FlightLimits drone{1000.0, 100.0, 300.0};

// Two robots in opposite corners of 30 x 30 cells of grass; each robot's time in the field is what its limits
// make of its path.
PlanningProblem fleetProblem(const std::vector<FlightLimits>& limits) {
    PlanningProblem problem = test::uniformProblem(30, 30, 10.0, {}, {});
    problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 29, 29)};
    problem.robotFlights = limits;
    problem.fieldSeconds = [limits](const Plan& plan) {
        std::vector<double> seconds;
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot)
            seconds.push_back(limits[robot].leastFieldSecondsFor(plan.paths[robot].timeSeconds));
        return seconds;
    };
    return problem;
}

// Flies a robot's path from `home` as the waypoint files split it: each flight climbs, flies straight out at
// the trip speed to where the last one stopped, works on along the path while it can still come straight back
// within its flight time, and lands at home; turnarounds between flights. Its time in the field.
double flownFieldSeconds(const CoveragePath& path, const CellGraph& cells, const FlightLimits& limits) {
    const std::vector<double> reached = cumulativeSeconds(path, cells);
    const Waypoint& home = path.waypoints.front();
    const auto trip = [&](std::size_t point) {
        return std::hypot(path.waypoints[point].x - home.x, path.waypoints[point].y - home.y) /
               limits.tripMetresPerSecond;
    };
    double field = 0.0;
    std::size_t from = 0;
    while (from + 1 < path.waypoints.size()) {
        std::size_t to = from + 1;
        const auto flight = [&](std::size_t last) {
            return limits.climbAndDescentSeconds + trip(from) + reached[last] - reached[from] + trip(last);
        };
        while (to + 1 < path.waypoints.size() && flight(to + 1) <= limits.flightSeconds)
            ++to;
        field += (field > 0.0 ? limits.turnaroundSeconds : 0.0) + flight(to);
        from = to;
    }
    return field;
}

// The drone as the bound counts its flights on `plan`: each may skip a U-turn at the map's dearest price
// where it ends.
FlightLimits asBounded(const FlightLimits& limits, const Plan& plan) {
    double dearest = 0.0;
    for (int id = 0; id < static_cast<int>(plan.cells.size()); ++id)
        dearest = std::max(dearest, static_cast<double>(plan.cells.cell(id).turnSecondsPer90Degrees));
    FlightLimits bounded = limits;
    bounded.climbAndDescentSeconds -= 2.0 * dearest * limits.fastestPace;
    return bounded;
}

} // namespace

class FieldTimeBoundTest : public QObject {
    Q_OBJECT
  private slots:
    // 2000 s of path: three flights (900 + 900 + 200 s of work), three climbs and descents, two turnarounds.
    void aPathIsFlownInFullFlights() {
        QCOMPARE(drone.leastFieldSecondsFor(2000.0), 2000.0 + 3 * 100.0 + 2 * 300.0);
        QCOMPARE(drone.leastFieldSecondsFor(900.0), 1000.0); // one full flight, no turnaround
        QCOMPARE(drone.leastFieldSecondsFor(0.0), 0.0);
        QCOMPARE(drone.mostPathSecondsWithin(2900.0), 2000.0);
        QCOMPARE(drone.mostPathSecondsWithin(1000.0), 900.0);
        QCOMPARE(drone.mostPathSecondsWithin(1200.0), 900.0); // on the ground, turning around
        QCOMPARE(drone.mostPathSecondsWithin(1350.0), 900.0); // climbing again
        QCOMPARE(drone.mostPathSecondsWithin(50.0), 0.0);
        // Without a flight time a robot works its path in one go.
        const FlightLimits rover;
        QVERIFY(!rover.splitsPaths());
        QCOMPARE(rover.leastFieldSecondsFor(5000.0), 5000.0);
        QCOMPARE(rover.mostPathSecondsWithin(5000.0), 5000.0);
    }

    // Where the files may fly a cell faster than planned (speeds rounded up, held within a tolerance), a
    // second of path takes as little as the fastest pace: 2000 s of path at half pace are two flights.
    void aFasterPaceNeedsFewerFlights() {
        FlightLimits quick = drone;
        quick.fastestPace = 0.5;
        QCOMPARE(quick.leastFieldSecondsFor(2000.0), 1000.0 + 2 * 100.0 + 300.0);
        QCOMPARE(quick.mostPathSecondsWithin(1500.0), 2000.0);
        FlightLimits quickRover;
        quickRover.fastestPace = 0.5;
        QCOMPARE(quickRover.mostPathSecondsWithin(1000.0), 2000.0);
    }

    // The two inverse each other: the least field time for a path flies that path and no more.
    void theTwoMeasuresAgree() {
        for (double path = 10.0; path < 10000.0; path += 137.0) {
            const double field = drone.leastFieldSecondsFor(path);
            QVERIFY2(std::abs(drone.mostPathSecondsWithin(field) - path) < 1e-9 * field,
                     qPrintable(QString("%1 s of path in %2 s").arg(path).arg(field)));
            QVERIFY(drone.mostPathSecondsWithin(field - 1.0) < path);
        }
    }

    // Two drones alike: no plan brings the last home before either flies half the work no plan avoids, and
    // the plan's own times in the field are what the problem measures.
    void twoDronesShareTheWorkInFullFlights() {
        const PlanningProblem problem = fleetProblem({drone, drone});
        const Plan plan = MlctPlanner{}.plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, plan);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        const PlanMetrics& metrics = plan.metrics;
        const FlightLimits bounded = asBounded(drone, plan);
        QVERIFY(bounded.climbAndDescentSeconds < drone.climbAndDescentSeconds); // turns cost time here
        const double expected = bounded.leastFieldSecondsFor(metrics.lowerBoundSeconds);
        QVERIFY2(std::abs(metrics.fieldLowerBoundSeconds - expected) <= 1e-6 * expected,
                 qPrintable(QString("%1 against %2").arg(metrics.fieldLowerBoundSeconds).arg(expected)));
        const std::vector<double> field = problem.fieldSeconds(plan);
        QCOMPARE(metrics.robots[0].fieldSeconds, field[0]);
        QCOMPARE(metrics.robots[1].fieldSeconds, field[1]);
        QCOMPARE(metrics.fieldMakespanSeconds, std::max(field[0], field[1]));
        QCOMPARE(metrics.fieldSpread(), std::max(field[0], field[1]) / std::min(field[0], field[1]));
        QVERIFY(metrics.fieldMakespanSeconds >= metrics.fieldLowerBoundSeconds);
    }

    // A flight that works farther than d from the start flies 2 d of its time on the way out and back.
    void workFarOutLosesTheTripsFromEveryFlight() {
        FlightLimits flown = drone;
        flown.tripMetresPerSecond = 10.0;
        QVERIFY(flown.makesTrips());
        QCOMPARE(flown.mostPathSecondsBeyond(2300.0, 0.0), 2 * 900.0);    // two full flights
        QCOMPARE(flown.mostPathSecondsBeyond(2300.0, 2000.0), 2 * 500.0); // 400 s of trips a flight
        QCOMPARE(flown.mostPathSecondsBeyond(2300.0, 4500.0), 0.0);       // out of reach
        // Without a trip speed the trips are not counted.
        QVERIFY(!drone.makesTrips());
        QCOMPARE(drone.mostPathSecondsBeyond(2300.0, 2000.0), drone.mostPathSecondsWithin(2300.0));
    }

    // Drones starting at a corner or an edge fly out to most of their work: their trips raise the bound in
    // the field, and no flying of the plan within its flights beats it.
    void tripsOutToTheWorkRaiseTheBound() {
        FlightLimits flown = drone;
        flown.tripMetresPerSecond = 1.0; // reaches 450 m; the map's far corner lies 420 m away
        // Start pixels (column, row): a corner, two at a corner, an edge, the middle and the far corner.
        const std::vector<std::vector<std::pair<int, int>>> fleets = {
            {{0, 0}}, {{0, 0}, {1, 0}}, {{0, 15}}, {{15, 15}, {29, 29}}};
        for (const auto& pixels : fleets) {
            PlanningProblem problem = test::uniformProblem(30, 30, 10.0, {}, {});
            for (const auto& [column, row] : pixels)
                problem.starts.push_back(test::pixelCentre(problem.grid, column, row));
            const std::vector<MapPoint>& starts = problem.starts;
            problem.robotFlights.assign(starts.size(), flown);
            problem.fieldSeconds = [flown](const Plan& plan) {
                std::vector<double> seconds;
                for (const CoveragePath& path : plan.paths)
                    seconds.push_back(flownFieldSeconds(path, plan.cells, flown));
                return seconds;
            };
            const Plan plan = MlctPlanner{}.plan(problem, {});
            const double flownMakespan = plan.metrics.fieldMakespanSeconds;
            Plan withoutTrips = plan;
            PlanMetricsCalculator{std::vector<FlightLimits>(starts.size(), drone)}.compute(withoutTrips);
            const double bound = plan.metrics.fieldLowerBoundSeconds;
            const double tripless = withoutTrips.metrics.fieldLowerBoundSeconds;
            const QString figures = QString("%1 starts: bound %2 s, without trips %3 s, flown %4 s")
                                        .arg(starts.size())
                                        .arg(bound)
                                        .arg(tripless)
                                        .arg(flownMakespan);
            QVERIFY2(bound >= tripless && bound <= flownMakespan, qPrintable(figures));
            // From the corner most of the map lies hundreds of metres out: minutes of trips a flight.
            if (pixels.front() == std::make_pair(0, 0))
                QVERIFY2(bound > 1.05 * tripless, qPrintable(figures));
        }
    }

    // A drone beside a rover: the bound is the time T in which the rover's T and the drone's flights within T
    // do the work together, so the rover, which never stops, is given more of it than the drone.
    void aRoverAndADroneShareTheWorkByWhatEachDoesInTime() {
        const PlanningProblem problem = fleetProblem({FlightLimits{}, drone});
        const Plan plan = MlctPlanner{}.plan(problem, {});
        const PlanMetrics& metrics = plan.metrics;
        const double bound = metrics.fieldLowerBoundSeconds;
        const double work = 2.0 * metrics.lowerBoundSeconds;
        const FlightLimits bounded = asBounded(drone, plan);
        QVERIFY2(std::abs(bound + bounded.mostPathSecondsWithin(bound) - work) <= 1e-6 * work,
                 qPrintable(QString("%1 s: %2 of %3")
                                .arg(bound)
                                .arg(bound + bounded.mostPathSecondsWithin(bound))
                                .arg(work)));
        QVERIFY(bound > metrics.lowerBoundSeconds); // the drone's climbs and turnarounds cost the fleet
        QVERIFY(metrics.fieldMakespanSeconds >= bound);
        // Planned in the field, the two come home within a few per cent of each other.
        QVERIFY2(metrics.fieldSpread() < 1.1, qPrintable(QString::number(metrics.fieldSpread())));
    }

    // A planner that times every robot at the class table's speeds (own speeds ignored, as a detection plan
    // does) has paths the waypoint files do not fly: no figures in the field beside them.
    void pathsNotTimedAtOwnSpeedsHaveNoFieldFigures() {
        PlanningProblem problem = fleetProblem({drone, drone});
        problem.robotSpeeds = {0.0, 3.0};
        problem.planner = defaultPlannerChoice("cppied");
        // The mission's note that each robot is timed at its own speed goes: here it is not.
        problem.notes.push_back({IssueSeverity::Information, "cruise-speeds-differ", "each at its own"});
        const Plan plan = makePlanner("cppied")->plan(problem, {});
        QVERIFY(std::any_of(plan.issues.begin(), plan.issues.end(),
                            [](const PlanIssue& issue) { return issue.code == "own-speeds-ignored"; }));
        QVERIFY(std::none_of(plan.issues.begin(), plan.issues.end(),
                             [](const PlanIssue& issue) { return issue.code == "cruise-speeds-differ"; }));
        QCOMPARE(plan.metrics.fieldLowerBoundSeconds, 0.0);
        QCOMPARE(plan.metrics.fieldMakespanSeconds, 0.0);
        QVERIFY(plan.metrics.ownSpeedsIgnored); // a comparison sets it after plans keeping them
        // Timed at its own speed, as MCPP-MLCT plans it, the same fleet has them.
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const Plan timed = MlctPlanner{}.plan(problem, {});
        QVERIFY(!timed.metrics.ownSpeedsIgnored);
        QVERIFY(timed.metrics.fieldLowerBoundSeconds > 0.0);
        QVERIFY(timed.metrics.fieldMakespanSeconds >= timed.metrics.fieldLowerBoundSeconds);
    }

    // A planner that plays its robots' missions through (MDSTC) with no events to play has its paths as
    // the waypoint files fly them: timed in the field as the others, so that a comparison ranks it by when
    // its last robot is home too.
    void aSimulatedPlanWithoutEventsIsTimedInTheField() {
        PlanningProblem problem = fleetProblem({drone, drone});
        problem.planner = defaultPlannerChoice("mdstc");
        const Plan plan = makePlanner("mdstc")->plan(problem, {});
        QVERIFY(plan.metrics.fieldLowerBoundSeconds > 0.0);
        QVERIFY(plan.metrics.fieldMakespanSeconds >= plan.metrics.fieldLowerBoundSeconds);
        QVERIFY(plan.metrics.fieldMakespanSeconds >
                plan.metrics.makespanSeconds); // turnarounds between flights
    }

    // Without flights there is no time in the field to speak of.
    void robotsWithoutFlightsHaveNoFieldFigures() {
        PlanningProblem problem = fleetProblem({FlightLimits{}, FlightLimits{}});
        problem.robotFlights.clear();
        problem.fieldSeconds = nullptr;
        const Plan plan = MlctPlanner{}.plan(problem, {});
        QCOMPARE(plan.metrics.fieldLowerBoundSeconds, 0.0);
        QCOMPARE(plan.metrics.fieldMakespanSeconds, 0.0);
        QCOMPARE(plan.metrics.fieldSpread(), 0.0);
    }

    // Robots coming home a quarter or more apart are warned of, the last and the first named with their
    // times; a planner that evens out paths only is told of one that evens out time in the field.
    void robotsHomeFarApartAreWarnedOf() {
        Plan plan;
        plan.metrics.robots.resize(3);
        for (int robot = 0; robot < 3; ++robot)
            plan.metrics.robots[static_cast<std::size_t>(robot)].robot = robot;
        plan.metrics.robots[0].fieldSeconds = 7200.0;
        plan.metrics.robots[1].fieldSeconds = 3600.0;
        plan.metrics.robots[2].fieldSeconds = 5000.0;
        const PlannerDescription mlct = *findPlannerDescription("mcpp-mlct");
        const std::string said = unevenFieldMessage(plan, mlct);
        QVERIFY2(said.find("robot 1 comes home after 2 h in the field, 2 times as long as robot 2 (1 h)") ==
                     0,
                 said.c_str());
        const PlannerDescription darp = *findPlannerDescription("darp");
        const std::string toldOfOthers = unevenFieldMessage(plan, darp);
        QVERIFY2(toldOfOthers.find("plan with MCPP-MLCT (mcpp-mlct), which evens out time in the field") !=
                     std::string::npos,
                 toldOfOthers.c_str());
        plan.metrics.robots[0].fieldSeconds = 4400.0; // 1.22 x the first: within a quarter
        plan.metrics.robots[2].fieldSeconds = 4000.0;
        QVERIFY(unevenFieldMessage(plan, mlct).empty());
        plan.metrics.robots[0].fieldSeconds = 7200.0;
        plan.metrics.confinedRobots.push_back({});
        QVERIFY(unevenFieldMessage(plan, mlct).empty()); // a pocket sets it
        plan.metrics.confinedRobots.clear();
        for (RobotMetrics& robot : plan.metrics.robots)
            robot.fieldSeconds = 0.0; // not measured
        QVERIFY(unevenFieldMessage(plan, mlct).empty());
    }
};

QTEST_APPLESS_MAIN(FieldTimeBoundTest)
#include "test_field_time_bound.moc"
