#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>

using namespace mcpp;

namespace {

// turnSearchRounds: the last search for fewer turns (turn_search_rounds), which both planners run after
// their own steps; 0 compares the reduction alone.
Plan planWith(const std::string& planner, PlanningProblem problem, int turnSearchRounds = 0) {
    problem.planner = defaultPlannerChoice(planner);
    problem.planner.parameters.set("turn_search_rounds", turnSearchRounds);
    return makePlanner(planner)->plan(problem, {});
}

int totalTurns(const Plan& plan) {
    int turns = 0;
    for (const CoveragePath& path : plan.paths)
        turns += path.turns;
    return turns;
}

const PlanIssue* issue(const Plan& plan, const std::string& code) {
    const auto found = std::find_if(plan.issues.begin(), plan.issues.end(),
                                    [&](const PlanIssue& each) { return each.code == code; });
    return found == plan.issues.end() ? nullptr : &*found;
}

} // namespace

// DARP with turn reduction against plain DARP on the same maps.
class DarpTurnsTest : public QObject {
    Q_OBJECT

  private slots:
    // Same regions to start from, so no robot turns more than under DARP, the longest path is no longer,
    // and the plan says how many cells moved and what the turns came to.
    void neverTurnsMoreThanDarp_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed = 1; seed <= 30; ++seed)
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }

    void neverTurnsMoreThanDarp() {
        QFETCH(unsigned, seed);
        test::RandomMapSpec spec;
        spec.seed = seed;
        spec.columns = 30 + static_cast<int>(seed % 20);
        spec.rows = 30;
        spec.landCovers = 1 + static_cast<int>(seed % 3);
        spec.obstacleFraction = 0.1;
        spec.robots = 2 + static_cast<int>(seed % 7);
        const PlanningProblem problem = test::randomProblem(spec);
        const Plan darp = planWith("darp", problem);
        const Plan reduced = planWith("darp-turns", problem);
        for (std::size_t robot = 0; robot < darp.paths.size(); ++robot)
            QVERIFY2(reduced.paths[robot].turns <= darp.paths[robot].turns,
                     qPrintable(QString("robot %1: %2 turns, %3 under DARP")
                                    .arg(robot)
                                    .arg(reduced.paths[robot].turns)
                                    .arg(darp.paths[robot].turns)));
        QVERIFY(reduced.metrics.makespanSeconds <= darp.metrics.makespanSeconds + 1e-6);
        const PlanIssue* reported = issue(reduced, "turns-reduced");
        QVERIFY(reported != nullptr);
        QCOMPARE(reported->severity, IssueSeverity::Information);
        const std::string expected = std::to_string(totalTurns(darp)) + " turns before, " +
                                     std::to_string(totalTurns(reduced)) + " after";
        QVERIFY2(reported->message.find(expected) != std::string::npos, reported->message.c_str());
    }

    // Over those maps the reduction finds something to do: fewer turns in all.
    void savesTurnsOverall() {
        int darpTurns = 0;
        int reducedTurns = 0;
        for (unsigned seed = 1; seed <= 10; ++seed) {
            test::RandomMapSpec spec;
            spec.seed = seed;
            spec.columns = 40;
            spec.rows = 40;
            spec.obstacleFraction = 0.1;
            spec.robots = 6;
            const PlanningProblem problem = test::randomProblem(spec);
            darpTurns += totalTurns(planWith("darp", problem));
            reducedTurns += totalTurns(planWith("darp-turns", problem));
        }
        QVERIFY2(reducedTurns < darpTurns, qPrintable(QString("%1 vs %2").arg(reducedTurns).arg(darpTurns)));
    }

    // No rounds, no change: the plan is DARP's, the last search for fewer turns included.
    void zeroRoundsIsDarp() {
        test::RandomMapSpec spec;
        spec.robots = 4;
        spec.obstacleFraction = 0.1;
        PlanningProblem problem = test::randomProblem(spec);
        problem.planner = defaultPlannerChoice("darp-turns");
        problem.planner.parameters.set("turn_reduction_rounds", 0);
        const Plan reduced = makePlanner("darp-turns")->plan(problem, {});
        const Plan darp = planWith("darp", problem, reduced.parameters.integer("turn_search_rounds"));
        QCOMPARE(reduced.regions.robotOfCell, darp.regions.robotOfCell);
        QCOMPARE(totalTurns(reduced), totalTurns(darp));
    }
};

QTEST_APPLESS_MAIN(DarpTurnsTest)
#include "test_darp_turns.moc"
