// Paths whose straight runs are merged measure, time and export as the paths they were made from, hold a
// small part of their waypoints, and give every walked waypoint back.
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>

using namespace mcpp;

namespace {

// Uniform cells with obstacles, and cells of three sizes and speeds.
std::vector<PlanningProblem> problems() {
    return {test::obstacleGridProblem(60, 4, 11), test::randomProblem(test::multiCoverSpec(64, 5))};
}

bool relativelyClose(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), 1.0);
}

// `part` is `whole` with some waypoints left out, the first and last kept.
bool isSubsequence(const std::vector<Waypoint>& part, const std::vector<Waypoint>& whole) {
    std::size_t at = 0;
    for (const Waypoint& waypoint : whole)
        if (at < part.size() && part[at].x == waypoint.x && part[at].y == waypoint.y &&
            part[at].cell == waypoint.cell)
            ++at;
    return at == part.size() && part.front().x == whole.front().x && part.front().y == whole.front().y &&
           part.back().x == whole.back().x && part.back().y == whole.back().y;
}

} // namespace

class TestStraightRunMerging : public QObject {
    Q_OBJECT

  private slots:
    // Merged, a path keeps its turning points, speed changes and steps between sizes: length, time, turns
    // and connector time come out of what is left as out of the whole, and measurePath leaves its
    // measures (repeated visits among them) as they were.
    void mergedPathsMeasureAsTheWhole() {
        for (const PlanningProblem& problem : problems()) {
            const Plan plan = MlctPlanner{}.plan(problem, {});
            for (const CoveragePath& whole : plan.paths) {
                CoveragePath merged = whole;
                mergeStraightRuns(merged, plan.cells);
                QVERIFY(merged.runsMerged());
                QCOMPARE(merged.walkedWaypoints, whole.waypoints.size());
                QCOMPARE(merged.runFollows.size(), merged.waypoints.size());
                QVERIFY(merged.waypoints.size() * 2 < whole.waypoints.size());
                QVERIFY(isSubsequence(merged.waypoints, whole.waypoints));
                QVERIFY(relativelyClose(pathLengthMetres(merged.waypoints), whole.lengthMetres));
                QCOMPARE(countTurns(merged.waypoints), whole.turns);
                const PathSeconds seconds = pathSeconds(merged.waypoints, plan.cells);
                QVERIFY(relativelyClose(seconds.total, whole.timeSeconds));
                QVERIFY(relativelyClose(seconds.turning, whole.turnSeconds));
                QVERIFY(
                    relativelyClose(connectorSeconds(merged.waypoints, plan.cells), whole.connectorSeconds));
                CoveragePath measured = merged;
                measurePath(measured, plan.cells);
                QCOMPARE(measured.repeatedSubCellVisits, whole.repeatedSubCellVisits);
                QCOMPARE(measured.lengthMetres, whole.lengthMetres);
                QCOMPARE(measured.timeSeconds, whole.timeSeconds);
            }
        }
    }

    // Every walked waypoint comes back: on its sub-cell's centre as walked (the same bits), in its cell, at
    // its speed.
    void walkedWaypointsComeBack() {
        for (const PlanningProblem& problem : problems()) {
            const Plan plan = MlctPlanner{}.plan(problem, {});
            for (const CoveragePath& whole : plan.paths) {
                CoveragePath merged = whole;
                mergeStraightRuns(merged, plan.cells);
                const std::vector<Waypoint> walked = walkedWaypoints(merged, plan.cells);
                QCOMPARE(walked.size(), whole.waypoints.size());
                for (std::size_t i = 0; i < walked.size(); ++i) {
                    const Waypoint& expected = whole.waypoints[i];
                    QVERIFY2(walked[i].x == expected.x && walked[i].y == expected.y,
                             qPrintable(QString("waypoint %1").arg(i)));
                    QCOMPARE(walked[i].cell, expected.cell);
                    QCOMPARE(walked[i].speedMetresPerSecond, expected.speedMetresPerSecond);
                }
                QCOMPARE(walkedWaypoints(whole, plan.cells).size(), whole.waypoints.size()); // as it is
            }
        }
    }

    // A path with pauses (numbered by waypoint) and a path already merged stay as they are.
    void pausesKeepThePathWhole() {
        const PlanningProblem problem = problems().front();
        const Plan plan = MlctPlanner{}.plan(problem, {});
        CoveragePath paused = plan.paths.front();
        paused.pauses.push_back({paused.waypoints.size() / 2, 60.0});
        mergeStraightRuns(paused, plan.cells);
        QVERIFY(!paused.runsMerged());
        QCOMPARE(paused.waypoints.size(), plan.paths.front().waypoints.size());
        CoveragePath twice = plan.paths.front();
        mergeStraightRuns(twice, plan.cells);
        const std::size_t once = twice.waypoints.size();
        mergeStraightRuns(twice, plan.cells);
        QCOMPARE(twice.waypoints.size(), once);
        QCOMPARE(twice.walkedWaypoints, plan.paths.front().waypoints.size());
    }

    // Walking trees on a map at or above the coverage's threshold measures each path as walked, then
    // merges its runs; below it, the paths are only timed and hold every waypoint.
    void coverageMergesFromItsThreshold() {
        const PlanningProblem problem = problems().back();
        const Plan plan = MlctPlanner{}.plan(problem, {});
        const ProgressReporter progress;
        const std::vector<CoveragePath> whole =
            SpanningTreeCoverage(true).timedPlan(plan.cells, plan.regions, problem.starts, progress);
        const std::vector<CoveragePath> merged =
            SpanningTreeCoverage(true, plan.cells.size())
                .timedPlan(plan.cells, plan.regions, problem.starts, progress);
        QCOMPARE(merged.size(), whole.size());
        for (std::size_t robot = 0; robot < whole.size(); ++robot) {
            QVERIFY(!whole[robot].runsMerged());
            QVERIFY(merged[robot].runsMerged());
            QVERIFY(merged[robot].waypoints.size() * 2 < whole[robot].waypoints.size());
            const std::vector<Waypoint> walked = walkedWaypoints(merged[robot], plan.cells);
            QCOMPARE(walked.size(), whole[robot].waypoints.size());
            for (std::size_t i = 0; i < walked.size(); ++i)
                QVERIFY(walked[i].x == whole[robot].waypoints[i].x &&
                        walked[i].y == whole[robot].waypoints[i].y);
            // Measured from every waypoint before the merge: as the metrics stage measures a whole path.
            CoveragePath measured = whole[robot];
            measurePath(measured, plan.cells);
            QCOMPARE(merged[robot].walkedWaypoints, measured.waypoints.size());
            QCOMPARE(merged[robot].lengthMetres, measured.lengthMetres);
            QCOMPARE(merged[robot].timeSeconds, measured.timeSeconds);
            QCOMPARE(merged[robot].turns, measured.turns);
            QCOMPARE(merged[robot].repeatedSubCellVisits, measured.repeatedSubCellVisits);
            QCOMPARE(merged[robot].turnSeconds, measured.turnSeconds);
            QCOMPARE(merged[robot].connectorSeconds, measured.connectorSeconds);
            QVERIFY(measured.connectorSeconds != 0.0); // cells of three sizes: the steps between them count
        }
        const std::vector<CoveragePath> below =
            SpanningTreeCoverage(true, plan.cells.size() + 1)
                .timedPlan(plan.cells, plan.regions, problem.starts, progress);
        for (const CoveragePath& path : below)
            QVERIFY(!path.runsMerged());
    }
};

QTEST_APPLESS_MAIN(TestStraightRunMerging)
#include "test_straight_run_merging.moc"
