#include "core/planners/MlctPlanner.hpp"
#include "core/planners/WorkByDistance.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace mcpp;

namespace {

// A plan of one robot over 20 x 20 pixels of 10 m grass, its turns priced at 2 s a quarter turn.
Plan grassPlan() {
    PlanningProblem problem = test::uniformProblem(20, 20, 10.0, {}, {});
    problem.starts = {test::pixelCentre(problem.grid, 0, 0)};
    problem.planner.parameters.set("turn_s", 2.0);
    return MlctPlanner{}.plan(problem, {});
}

// How far the square of `cell` lies from `point`, worked out from its sides.
double gapFrom(const MapPoint& point, const Cell& cell) {
    const double dx = std::max({cell.minX - point.x, 0.0, point.x - cell.maxX()});
    const double dy = std::max({cell.minY - point.y, 0.0, point.y - cell.maxY()});
    return std::hypot(dx, dy);
}

} // namespace

class WorkByDistanceTest : public QObject {
    Q_OBJECT
  private slots:
    // Each step holds the work of the cells at least that far from the start, in 512 even steps up to the
    // farthest; the first step all of it.
    void stepsHoldTheWorkAtLeastSoFar() {
        const Plan plan = grassPlan();
        const MapPoint start{plan.paths[0].waypoints.front().x, plan.paths[0].waypoints.front().y};
        const auto travel = [&plan](int id) { return plan.cells.cell(id).travelSeconds(); };
        const WorkByDistance far(plan.cells, {{start, 0.0}}, travel, {});
        const std::vector<double>& beyond = far.secondsBeyond();
        QCOMPARE(beyond.size(), std::size_t{513});
        double farthest = 0.0;
        double total = 0.0;
        for (int id = 0; id < static_cast<int>(plan.cells.size()); ++id) {
            farthest = std::max(farthest, gapFrom(start, plan.cells.cell(id)));
            total += travel(id);
        }
        QVERIFY(std::abs(far.stepMetres() * 512 - farthest) < 1e-9 * farthest);
        QVERIFY(std::abs(beyond[0] - total) < 1e-9 * total);
        for (const std::size_t step :
             {std::size_t{1}, std::size_t{100}, std::size_t{300}, std::size_t{512}}) {
            const double metres = static_cast<double>(step) * far.stepMetres();
            double expected = 0.0;
            for (int id = 0; id < static_cast<int>(plan.cells.size()); ++id)
                if (gapFrom(start, plan.cells.cell(id)) >= metres * (1.0 + 1e-12))
                    expected += travel(id);
            // A cell exactly on a step's edge may fall either side of it in floating point.
            QVERIFY2(beyond[step] >= expected - 1e-9 * total && beyond[step] <= beyond[step - 1],
                     qPrintable(QString("step %1: %2 against %3").arg(step).arg(beyond[step]).arg(expected)));
        }
        QVERIFY(beyond[512] > 0.0); // the farthest cell itself
    }

    // A path's turns count where they are made, in all as the path measured them, and never more.
    void turnsCountAtTheirCornersUpToThePathsFigure() {
        const Plan plan = grassPlan();
        const CoveragePath& path = plan.paths[0];
        QVERIFY(path.turnSeconds > 0.0);
        const MapPoint start{path.waypoints.front().x, path.waypoints.front().y};
        const auto none = [](int) { return 0.0; };
        const auto anywhere = [](int) { return 1e-9; }; // so that the steps reach the farthest cell
        const WorkByDistance withTurns(plan.cells, {{start, 0.0}}, anywhere, {{&path, 0.5}});
        const WorkByDistance without(plan.cells, {{start, 0.0}}, anywhere, {});
        const double turns = withTurns.secondsBeyond()[0] - without.secondsBeyond()[0];
        QVERIFY2(std::abs(turns - 0.5 * path.turnSeconds) < 1e-6 * path.turnSeconds,
                 qPrintable(QString("%1 against %2").arg(turns).arg(0.5 * path.turnSeconds)));
        // Turns lie all over the map: some far out, none beyond the farthest step.
        QVERIFY(withTurns.secondsBeyond()[256] > without.secondsBeyond()[256]);
        // A path that says it turned for less is taken at its word.
        CoveragePath understated = path;
        understated.turnSeconds = path.turnSeconds / 4.0;
        const WorkByDistance scaled(plan.cells, {{start, 0.0}}, anywhere, {{&understated, 1.0}});
        QVERIFY(std::abs(scaled.secondsBeyond()[0] - without.secondsBeyond()[0] - understated.turnSeconds) <
                1e-6 * path.turnSeconds);
        // No work, no steps.
        QVERIFY(WorkByDistance(plan.cells, {{start, 0.0}}, none, {{&path, 1.0}}).secondsBeyond().empty());
    }
};

QTEST_APPLESS_MAIN(WorkByDistanceTest)
#include "test_work_by_distance.moc"
