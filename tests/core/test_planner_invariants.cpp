#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <map>
#include <set>
#include <string>

using namespace mcpp;

namespace {

// The same 200 random maps (fixed seeds) for every planner: 1-4 land covers, 0-30% obstacles, 1-32 robots
// (one for single-robot planners), closed and open tours; on every third map a pixel is a sub-cell, so
// cells are partly blocked.
PlanningProblem randomMap(unsigned seed, bool singleRobot) {
    test::RandomMapSpec spec;
    spec.seed = seed;
    spec.landCovers = 1 + static_cast<int>(seed % 4);
    spec.obstacleFraction = 0.30 * static_cast<double>((seed * 7) % 11) / 10.0;
    spec.robots = singleRobot ? 1 : 1 + static_cast<int>((seed * 13) % 32);
    spec.columns = 24 + static_cast<int>((seed * 5) % 40);
    spec.rows = 24 + static_cast<int>((seed * 3) % 33);
    if (seed % 3 == 0) {
        spec.fovPixels = 1.0;
        spec.columns *= 2;
        spec.rows *= 2;
    }
    return test::randomProblem(spec);
}

// The centre of the first obstacle pixel (in reading order), if the map has one.
std::optional<MapPoint> firstObstacle(const PlanningProblem& problem) {
    const ClassGrid& grid = problem.grid;
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            const LandCoverClass* landCover = problem.classes.find(grid.valueAt(column, row));
            if (!grid.isOutside(column, row) && landCover != nullptr && !landCover->isTraversable())
                return MapPoint{grid.originX + (column + 0.5) * grid.pixelWidth,
                                grid.originY - (row + 0.5) * grid.pixelHeight};
        }
    return std::nullopt;
}

} // namespace

// Every registered planner holds the invariants of spec section 7 on every map, as far as it promises them
// (PlannerPromises); repeated coverage is recounted from the paths and must match what the plan reports.
class PlannerInvariantsTest : public QObject {
    Q_OBJECT

  private slots:
    void everyPlannerHoldsTheInvariants_data() {
        QTest::addColumn<QString>("planner");
        QTest::addColumn<unsigned>("seed");
        for (const PlannerDescription& planner : plannerDescriptions())
            for (unsigned seed = 1; seed <= 200; ++seed)
                QTest::newRow(
                    qPrintable(QString("%1 seed %2").arg(QString::fromStdString(planner.name)).arg(seed)))
                    << QString::fromStdString(planner.name) << seed;
    }

    void everyPlannerHoldsTheInvariants() {
        QFETCH(QString, planner);
        QFETCH(unsigned, seed);
        const auto made = makePlanner(planner.toStdString());
        QVERIFY(made != nullptr);
        const PlannerDescription description = made->description();
        PlanningProblem problem = randomMap(seed, description.singleRobot);
        problem.planner = defaultPlannerChoice(description.name);
        if (problem.planner.parameters.has("closed_tour"))
            problem.planner.parameters.set("closed_tour", seed % 5 != 0);
        // Turns free, at a fixed price, or priced from the speed.
        if (seed % 3 == 1)
            problem.planner.parameters.set("turn_s", seed % 2 == 0 ? 0.0 : 2.5);
        // Batteries that last, that force many sorties, and that leave far cells out of range.
        if (problem.planner.parameters.has("battery_s"))
            problem.planner.parameters.set("battery_s",
                                           seed % 4 == 0 ? 1e6 : (seed % 4 == 1 ? 1200.0 : 300.0));
        if (problem.planner.parameters.has("balanced"))
            problem.planner.parameters.set("balanced", seed % 2 == 0);
        // A mixed fleet: the first robot at its own speed (an aircraft's cruise speed), the others at the
        // class table's; every robot at its own on some maps.
        if (seed % 7 == 3)
            problem.robotSpeeds = {3.5};
        if (seed % 14 == 10)
            problem.robotSpeeds.assign(problem.starts.size(), 2.0);
        // An aircraft standing on an obstacle takes off there and flies to the nearest free cell (on
        // batteries, sorties start from the start's cell: no take-off there).
        if (seed % 9 == 4 && !description.fliesOnBatteries())
            if (const auto obstacle = firstObstacle(problem)) {
                problem.flyingRobots.assign(problem.starts.size(), true);
                problem.starts.front() = *obstacle;
            }
        Plan plan;
        try {
            plan = made->plan(problem, {});
        } catch (const std::exception& error) {
            QFAIL(error.what());
        }
        QCOMPARE(plan.planner, description.name);
        auto violations = test::checkAllInvariants(problem, plan, description.promises);
        if (description.name == MlctPlanner::plannerName) {
            const auto tiling = test::checkQuadTreeTiling(
                problem, QuadTreeBuilder{}.build(problem.grid, problem.classes, DecompositionOptions{}));
            violations.insert(violations.end(), tiling.begin(), tiling.end());
        }
        QVERIFY2(violations.empty(), qPrintable(QString::fromStdString(test::describe(violations))));
        // A closed tour passes every sub-cell and comes back: no region is covered faster than its cost. An
        // open path saves its last steps, so only closed tours are held to the bound.
        const bool closed = !problem.planner.parameters.has("closed_tour") ||
                            problem.planner.parameters.boolean("closed_tour");
        if (closed && description.promises.pathsCoverOwnRegion && description.promises.passesEverySubCell)
            QVERIFY2(plan.metrics.ratio >= 1.0 - 1e-9, qPrintable(QString::number(plan.metrics.ratio)));
        QVERIFY(plan.metrics.ratio > 0.0);
        QVERIFY(plan.metrics.coveredFraction > 0.0 && plan.metrics.coveredFraction <= 1.0 + 1e-9);
        QVERIFY(plan.metrics.repeatedFraction >= 0.0);
    }

    // Planners compared side by side show their parameters by label: one label must mean one setting,
    // whichever planner declares it, and a planner's labels must tell its own settings apart.
    void oneLabelNamesOneParameter() {
        std::map<std::string, std::string> keyOfLabel;
        for (const PlannerDescription& planner : plannerDescriptions()) {
            std::set<std::string> labels;
            for (const ParameterSpec& spec : planner.parameters) {
                QVERIFY2(labels.insert(spec.label).second, (planner.name + ": " + spec.label).c_str());
                const auto [named, fresh] = keyOfLabel.emplace(spec.label, spec.key);
                QVERIFY2(fresh || named->second == spec.key,
                         (spec.label + " names " + named->second + " and " + spec.key).c_str());
            }
        }
    }
};

QTEST_APPLESS_MAIN(PlannerInvariantsTest)
#include "test_planner_invariants.moc"
