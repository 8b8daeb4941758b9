#include "core/allocation/RegionExpansion.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/ReallocationSimulation.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/SpeedSchedule.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/model/TimelineText.hpp"
#include "core/planners/MdstcPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace mcpp;

namespace {

Plan planMdstc(PlanningProblem problem, const std::vector<SpeedEvent>& events) {
    problem.planner = defaultPlannerChoice(MdstcPlanner::plannerName);
    problem.events = events;
    return makePlanner(MdstcPlanner::plannerName)->plan(problem, {});
}

std::string violationsOf(const PlanningProblem& problem, const Plan& plan) {
    return test::describe(test::checkAllInvariants(
        problem, plan, makePlanner(MdstcPlanner::plannerName)->description().promises));
}

bool hasIssue(const Plan& plan, const std::string& code) {
    return std::any_of(plan.issues.begin(), plan.issues.end(),
                       [&](const PlanIssue& issue) { return issue.code == code; });
}

const TimelineLayer& timelineOf(const Plan& plan) {
    const TimelineLayer* timeline = timelineLayerOf(plan);
    if (timeline == nullptr)
        throw std::runtime_error("the plan has no timeline");
    return *timeline;
}

std::string plannerError(const PlanningProblem& problem, const std::vector<SpeedEvent>& events) {
    try {
        static_cast<void>(planMdstc(problem, events));
    } catch (const PlanningError& error) {
        return error.what();
    }
    return {};
}

} // namespace

// MDSTC on the DARP / DMSTC grids (10 m cells of one land cover at 1 m/s, 15 % obstacles).
class MdstcTest : public QObject {
    Q_OBJECT

  private slots:
    // Robot 0 at half speed from 100 s and stopped at 300 s: 150 s of full-speed driving take 100 + 50 / 0.5
    // s; 250 s never end, unless it starts again at 500 s at twice the speed (500 + 50 / 2).
    void aScheduleTimesDrivingThroughItsEvents() {
        const std::vector<SpeedEvent> events{{100.0, 0, 0.5}, {300.0, 0, 0.0}, {50.0, 1, 0.1}};
        const SpeedSchedule schedule(events, 0);
        QCOMPARE(schedule.factorAt(99.0), 1.0);
        QCOMPARE(schedule.factorAt(100.0), 0.5);
        QCOMPARE(schedule.finishTime(0.0, 50.0), 50.0);
        QCOMPARE(schedule.finishTime(0.0, 150.0), 200.0);
        QVERIFY(std::isinf(schedule.finishTime(0.0, 250.0)));
        QVERIFY(schedule.stoppedFrom(300.0));
        QVERIFY(!schedule.stoppedFrom(299.0));
        std::vector<SpeedEvent> resumed = events;
        resumed.push_back({500.0, 0, 2.0});
        const SpeedSchedule again(resumed, 0);
        QCOMPARE(again.finishTime(0.0, 250.0), 525.0);
        QVERIFY(!again.stoppedFrom(300.0));
    }

    // Taking turns from opposite corners of an open 10 x 10 map, two regions split it evenly: each in one
    // piece, every cell claimed.
    void regionsGrowInTurns() {
        PlanningProblem problem = test::uniformProblem(10, 10, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 9, 9)};
        const Plan plan = planMdstc(problem, {});
        const std::vector<int> cells{plan.cells.cellAt(problem.starts[0]),
                                     plan.cells.cellAt(problem.starts[1])};
        const std::vector<int> owner = expandRegions(plan.cells, cells);
        const auto first = std::count(owner.begin(), owner.end(), 0);
        const auto second = std::count(owner.begin(), owner.end(), 1);
        QCOMPARE(first + second, 100);
        QVERIFY2(std::abs(first - second) <= 2, qPrintable(QString("%1 against %2").arg(first).arg(second)));
    }

    // Twenty robots at random cells of a 49 x 49 grid grow uneven regions, which are then evened out: a
    // request to stop reaches that evening-out (on a large map it takes long), and without one the
    // regions come out with each start in its robot's region and every cell reachable from a start claimed.
    void theFirstDivisionStopsWhenCancelled() {
        const PlanningProblem problem = test::obstacleGridProblem(49, 20, 21);
        const CellGraph cells = test::cellPerPixelGraph(problem);
        std::vector<int> startCells;
        for (const MapPoint& start : problem.starts)
            startCells.push_back(cells.cellAt(start));
        const std::atomic<bool> cancelled{true};
        const ProgressReporter stopping([](std::string_view, double) {}, &cancelled);
        bool stopped = false;
        try {
            (void)ReallocationSimulation::firstDivision(cells, startCells, stopping);
        } catch (const PlanningError& error) {
            stopped = error.kind() == PlanningError::Kind::Cancelled;
        }
        QVERIFY(stopped);
        const RegionAllocation division = ReallocationSimulation::firstDivision(cells, startCells, {});
        QCOMPARE(division.robotOfCell.size(), cells.size());
        for (std::size_t robot = 0; robot < startCells.size(); ++robot)
            QCOMPARE(division.robotOfCell[static_cast<std::size_t>(startCells[robot])],
                     static_cast<int>(robot));
        std::vector<int> reachable = startCells;
        std::vector<bool> seen(cells.size(), false);
        for (const int start : startCells)
            seen[static_cast<std::size_t>(start)] = true;
        for (std::size_t head = 0; head < reachable.size(); ++head) {
            QVERIFY(division.robotOfCell[static_cast<std::size_t>(reachable[head])] >= 0);
            for (const int next : cells.neighbours(reachable[head]))
                if (!seen[static_cast<std::size_t>(next)]) {
                    seen[static_cast<std::size_t>(next)] = true;
                    reachable.push_back(next);
                }
        }
        QVERIFY(reachable.size() > cells.size() / 2);
    }

    // Without events, the plan holds the shared invariants (every free sub-cell passed, times as measured),
    // the real times are the measured ones and its makespan is within 3 % of MCPP-MLCT's static plan.
    void withoutEventsItMatchesTheStaticPlan_data() {
        QTest::addColumn<int>("size");
        QTest::addColumn<int>("robots");
        QTest::newRow("49 x 49, 2 robots") << 49 << 2;
        QTest::newRow("49 x 49, 8 robots") << 49 << 8;
        QTest::newRow("49 x 49, 20 robots") << 49 << 20;
        QTest::newRow("100 x 100, 4 robots") << 100 << 4;
    }
    void withoutEventsItMatchesTheStaticPlan() {
        QFETCH(int, size);
        QFETCH(int, robots);
        const PlanningProblem problem = test::obstacleGridProblem(size, robots, 2020);
        const Plan plan = planMdstc(problem, {});
        QVERIFY2(violationsOf(problem, plan).empty(), violationsOf(problem, plan).c_str());
        const TimelineLayer& timeline = timelineOf(plan);
        for (const RobotTimeline& robot : timeline.robots()) {
            const CoveragePath& path = plan.paths[static_cast<std::size_t>(robot.robot)];
            QCOMPARE(robot.secondsAtWaypoint.size(), path.waypoints.size());
            const std::vector<double> reached = cumulativeSeconds(path, plan.cells);
            for (std::size_t i = 0; i < path.waypoints.size(); ++i)
                QVERIFY(std::abs(robot.secondsAtWaypoint[i] - reached[i]) <= 1e-6 * (1.0 + path.timeSeconds));
        }
        const double ratio = timeline.summary().makespanSeconds / timeline.summary().staticMakespanSeconds;
        qInfo("%d x %d, %d robots: MDSTC %.0f s, static %.0f s, ratio to static %.4f, to bound %.4f", size,
              size, robots, timeline.summary().makespanSeconds, timeline.summary().staticMakespanSeconds,
              ratio, plan.metrics.ratio);
        QVERIFY2(ratio <= 1.03, qPrintable(QString::number(ratio)));
    }

    // On a map of three fields of view (5, 10 and 20 m) MDSTC drives the quadtree's cells of several sizes,
    // as the static plan does; on the uniform grid of the smallest it would cover the open land four times
    // over.
    void onCellsOfSeveralSizesItMatchesTheStaticPlan_data() {
        QTest::addColumn<int>("size");
        QTest::addColumn<int>("robots");
        QTest::newRow("128 x 128, 2 robots") << 128 << 2;
        QTest::newRow("128 x 128, 8 robots") << 128 << 8;
        QTest::newRow("256 x 256, 16 robots") << 256 << 16;
    }
    void onCellsOfSeveralSizesItMatchesTheStaticPlan() {
        QFETCH(int, size);
        QFETCH(int, robots);
        const PlanningProblem problem = test::randomProblem(test::multiCoverSpec(size, robots));
        const Plan plan = planMdstc(problem, {});
        QVERIFY2(violationsOf(problem, plan).empty(), violationsOf(problem, plan).c_str());
        int largest = 1;
        for (const Cell& cell : plan.cells.cells())
            largest = std::max(largest, int{cell.span});
        QVERIFY(largest >= 4);
        const TimelineLayer::Summary& summary = timelineOf(plan).summary();
        const double ratio = summary.makespanSeconds / summary.staticMakespanSeconds;
        PlanningProblem onGrid = problem;
        onGrid.planner = defaultPlannerChoice(MdstcPlanner::plannerName);
        onGrid.planner.parameters.set("quadtree_cells", false);
        onGrid.planner.parameters.set("compare_static", false);
        const Plan gridPlan = makePlanner(MdstcPlanner::plannerName)->plan(onGrid, {});
        qInfo("%d x %d, %d robots: MDSTC %.0f s, static %.0f s, ratio to static %.4f, to bound %.4f; on the "
              "uniform grid %.0f s",
              size, size, robots, summary.makespanSeconds, summary.staticMakespanSeconds, ratio,
              plan.metrics.ratio, timelineOf(gridPlan).summary().makespanSeconds);
        QVERIFY2(ratio <= 1.03, qPrintable(QString::number(ratio)));
        QVERIFY(timelineOf(gridPlan).summary().makespanSeconds > summary.makespanSeconds);
    }

    // Robot 0 drops to half speed a quarter of the way through: the others take over cells nobody has
    // entered, and the mission ends before the static plan's under the same event.
    void aSlowRobotIsHelpedByTheOthers_data() {
        QTest::addColumn<int>("size");
        QTest::addColumn<int>("robots");
        QTest::newRow("49 x 49, 4 robots") << 49 << 4;
        QTest::newRow("49 x 49, 8 robots") << 49 << 8;
        QTest::newRow("100 x 100, 8 robots") << 100 << 8;
    }
    void aSlowRobotIsHelpedByTheOthers() {
        QFETCH(int, size);
        QFETCH(int, robots);
        const PlanningProblem problem = test::obstacleGridProblem(size, robots, 2020);
        const double quarter = timelineOf(planMdstc(problem, {})).summary().makespanSeconds / 4.0;
        const Plan plan = planMdstc(problem, {{quarter, 0, 0.5}});
        QVERIFY2(violationsOf(problem, plan).empty(), violationsOf(problem, plan).c_str());
        const TimelineLayer& timeline = timelineOf(plan);
        const TimelineLayer::Summary& summary = timeline.summary();
        qInfo("%d x %d, %d robots, robot 0 at half speed from %.0f s: MDSTC %.0f s, static %.0f s (%.3f)",
              size, size, robots, quarter, summary.makespanSeconds, summary.staticMakespanSeconds,
              summary.makespanSeconds / summary.staticMakespanSeconds);
        QVERIFY(summary.makespanSeconds < summary.staticMakespanSeconds);
        std::size_t takenOver = 0;
        for (const RobotTimeline& robot : timeline.robots()) {
            QVERIFY(std::is_sorted(robot.secondsAtWaypoint.begin(), robot.secondsAtWaypoint.end()));
            QCOMPARE(robot.completionSeconds, robot.secondsAtWaypoint.back());
            if (robot.robot != 0)
                takenOver += robot.cellsTakenOver.size();
        }
        QVERIFY(takenOver > 0);
        // Robot 0's part after the event took twice its measured time.
        const RobotTimeline& slow = timeline.robots().front();
        const CoveragePath& path = plan.paths.front();
        const double nominalAfter = path.timeSeconds - quarter;
        QVERIFY(std::abs(slow.completionSeconds - (quarter + 2.0 * nominalAfter)) <= 1e-6 * path.timeSeconds);
    }

    // Robot 1 stops for good at a quarter: the others cover all it left, its path ends where it stopped, and
    // the static plan never finishes.
    void aStoppedRobotsWorkIsTakenOver() {
        const PlanningProblem problem = test::obstacleGridProblem(49, 5, 2020);
        const double quarter = timelineOf(planMdstc(problem, {})).summary().makespanSeconds / 4.0;
        const Plan plan = planMdstc(problem, {{quarter, 1, 0.0}});
        QVERIFY2(violationsOf(problem, plan).empty(), violationsOf(problem, plan).c_str());
        QVERIFY(!hasIssue(plan, "left-uncovered"));
        const TimelineLayer& timeline = timelineOf(plan);
        const RobotTimeline& stopped = timeline.robots()[1];
        QVERIFY(stopped.stopped);
        QVERIFY(stopped.completionSeconds <= quarter);
        QVERIFY(std::isinf(timeline.summary().staticMakespanSeconds));
        QVERIFY(std::isinf(stopped.staticCompletionSeconds));
        QVERIFY(std::isfinite(timeline.summary().makespanSeconds));
    }

    // Robot 1 pauses from a quarter to half way: the others take its free cells as for a stop (nobody
    // knows it will start again), it finishes what it had begun once it does, gets cells again, and the
    // mission ends before the static plan's under the same pause.
    void aPausedRobotIsNotAStoppedOne() {
        const PlanningProblem problem = test::obstacleGridProblem(49, 4, 2020);
        const double quarter = timelineOf(planMdstc(problem, {})).summary().makespanSeconds / 4.0;
        const Plan plan = planMdstc(problem, {{quarter, 1, 0.0}, {2.0 * quarter, 1, 1.0}});
        QVERIFY2(violationsOf(problem, plan).empty(), violationsOf(problem, plan).c_str());
        const TimelineLayer& timeline = timelineOf(plan);
        const RobotTimeline& paused = timeline.robots()[1];
        QVERIFY(!paused.stopped);
        QVERIFY(paused.completionSeconds > 2.0 * quarter);
        QVERIFY(std::isfinite(timeline.summary().staticMakespanSeconds));
        QVERIFY(timeline.summary().makespanSeconds < timeline.summary().staticMakespanSeconds);
        QVERIFY(!hasIssue(plan, "left-uncovered"));
    }

    // Events that cannot happen are refused, naming the event, the field and the value.
    void impossibleEventsAreRefused_data() {
        QTest::addColumn<double>("time");
        QTest::addColumn<int>("robot");
        QTest::addColumn<double>("factor");
        QTest::addColumn<QString>("expected");
        QTest::newRow("before the start")
            << -5.0 << 0 << 0.5 << "event 1 time_s: must be 0 s or later, got -5 s";
        QTest::newRow("no such robot")
            << 10.0 << 3 << 0.5 << "event 1 robot: robot 3 does not exist: the 3 robots are numbered 0 to 2";
        QTest::newRow("negative factor") << 10.0 << 0 << -0.5 << "event 1 speed_factor: must be from 0";
        QTest::newRow("not a number") << 10.0 << 0 << std::nan("") << "speed_factor";
    }
    void impossibleEventsAreRefused() {
        QFETCH(double, time);
        QFETCH(int, robot);
        QFETCH(double, factor);
        QFETCH(QString, expected);
        const PlanningProblem problem = test::obstacleGridProblem(20, 3, 2020);
        const std::string message = plannerError(problem, {{time, robot, factor}});
        QVERIFY2(QString::fromStdString(message).contains(expected), message.c_str());
    }

    // The one line the batch summary and the window show: saved, longer, or never done.
    void theTimelineIsSaidInOneLine() {
        TimelineLayer::Summary summary;
        summary.makespanSeconds = 3600.0;
        summary.staticPlanner = "mcpp-mlct";
        summary.staticMakespanSeconds = 3000.0;
        QCOMPARE(QString::fromStdString(timelineSentence(summary)),
                 QString("without events: done in 1 h; the static mcpp-mlct plan: 50 min (re-allocating "
                         "takes 20% longer)"));
        summary.staticMakespanSeconds = 1000.0;
        QVERIFY(QString::fromStdString(timelineSentence(summary))
                    .endsWith("(re-allocating takes 3.6 x as long)"));
        summary.events = {{60.0, 0, 0.5}};
        summary.staticMakespanSeconds = 7200.0;
        QVERIFY(QString::fromStdString(timelineSentence(summary)).endsWith("2 h (50% saved)"));
        summary.staticMakespanSeconds = std::numeric_limits<double>::infinity();
        QVERIFY(QString::fromStdString(timelineSentence(summary)).contains("1 event: done in 1 h"));
        QVERIFY(QString::fromStdString(timelineSentence(summary))
                    .endsWith("never done (a robot stops with work left)"));
    }

    // A planner that plans without events says it left them out.
    void otherPlannersSayTheyIgnoreEvents() {
        PlanningProblem problem = test::obstacleGridProblem(20, 2, 2020);
        problem.events = {{10.0, 0, 0.5}};
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        QVERIFY(hasIssue(plan, "events-ignored"));
        QVERIFY(timelineLayerOf(plan) == nullptr);
    }

    // A planner without batteries says it left the robots' chargers out; one that flies on them does not.
    void plannersWithoutBatteriesSayTheyIgnoreChargers() {
        PlanningProblem problem = test::obstacleGridProblem(20, 2, 2020);
        problem.chargers = {problem.starts[0], std::nullopt};
        QVERIFY(hasIssue(makePlanner("mcpp-mlct")->plan(problem, {}), "chargers-ignored"));
        QVERIFY(!hasIssue(makePlanner("wavefront-battery")->plan(problem, {}), "chargers-ignored"));
        problem.chargers.clear();
        QVERIFY(!hasIssue(makePlanner("mcpp-mlct")->plan(problem, {}), "chargers-ignored"));
    }
};

QTEST_GUILESS_MAIN(MdstcTest)
#include "test_mdstc.moc"
