#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>

using namespace mcpp;

// 200 random maps with fixed seeds: 1-4 land covers, 0-30% obstacles, 1-32 robots. Every plan must hold
// every invariant of spec section 7.
class RandomMapsTest : public QObject {
    Q_OBJECT
  private slots:
    void everyPlanHoldsTheInvariants_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed = 1; seed <= 200; ++seed)
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }

    void everyPlanHoldsTheInvariants() {
        QFETCH(unsigned, seed);
        test::RandomMapSpec spec;
        spec.seed = seed;
        spec.landCovers = 1 + static_cast<int>(seed % 4);
        spec.obstacleFraction = 0.30 * static_cast<double>((seed * 7) % 11) / 10.0;
        spec.robots = 1 + static_cast<int>((seed * 13) % 32);
        spec.columns = 24 + static_cast<int>((seed * 5) % 40);
        spec.rows = 24 + static_cast<int>((seed * 3) % 33);
        auto problem = test::randomProblem(spec);
        problem.planner.parameters.set("closed_tour", seed % 5 != 0);
        Plan plan;
        try {
            plan = MlctPlanner{}.plan(problem, {});
        } catch (const std::exception& error) {
            QFAIL(error.what());
        }
        auto violations = test::checkAllInvariants(problem, plan);
        const auto tiling = test::checkQuadTreeTiling(
            problem, QuadTreeBuilder{}.build(problem.grid, problem.classes, DecompositionOptions{}));
        violations.insert(violations.end(), tiling.begin(), tiling.end());
        QVERIFY2(violations.empty(), qPrintable(QString::fromStdString(test::describe(violations))));
        QVERIFY(plan.metrics.ratio >= 0.9);
        QVERIFY(plan.metrics.coveredFraction > 0.0 && plan.metrics.coveredFraction <= 1.0 + 1e-9);
    }
};

QTEST_APPLESS_MAIN(RandomMapsTest)
#include "test_random_maps.moc"
