#include "core/model/PlanningError.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>

using namespace mcpp;

namespace {

PlanningProblem drawnMap(const std::vector<std::string>& rows, MapPoint start) {
    return test::drawnProblem(rows, {start});
}

Plan planWith(const std::string& planner, PlanningProblem& problem) {
    problem.planner = defaultPlannerChoice(planner);
    return makePlanner(planner)->plan(problem, {});
}

QString violations(const PlanningProblem& problem, const Plan& plan) {
    return QString::fromStdString(test::describe(test::checkAllInvariants(problem, plan)));
}

} // namespace

// Spiral-STC and Full Spiral-STC on maps whose answers are known by hand.
class SpiralStcTest : public QObject {
    Q_OBJECT

  private slots:
    // A corridor one mega-cell wide and six long: the tour runs down one side and back the other, every
    // sub-cell once, 24 steps of one swath.
    void corridorIsOneLoop() {
        for (const std::string planner : {"spiral-stc", "full-spiral-stc"}) {
            PlanningProblem problem = drawnMap({"............", "............"}, {0.5, 0.5});
            const Plan plan = planWith(planner, problem);
            QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
            const CoveragePath& path = plan.paths.front();
            QCOMPARE(plan.cells.size(), std::size_t{6});
            QCOMPARE(path.lengthMetres, 24.0);
            QCOMPARE(path.repeatedSubCellVisits, 0);
            QCOMPARE(path.turns, 3); // south, east along the south side, north, west back to the start
            QCOMPARE(plan.metrics.ratio, 1.0);
        }
    }

    // One water pixel in a 4 x 4 block of mega-cells: Spiral-STC drops the mega-cell it touches, Full
    // Spiral-STC keeps the cell's three free sub-cells and covers them.
    void fullSpiralCoversNextToAnObstacle() {
        const std::vector<std::string> rows{"........", "........", "........", ".....#..",
                                            "........", "........", "........", "........"};
        PlanningProblem spiralProblem = drawnMap(rows, {0.5, 0.5});
        const Plan spiral = planWith("spiral-stc", spiralProblem);
        PlanningProblem fullProblem = drawnMap(rows, {0.5, 0.5});
        const Plan full = planWith("full-spiral-stc", fullProblem);
        QVERIFY2(test::checkAllInvariants(spiralProblem, spiral).empty(),
                 qPrintable(violations(spiralProblem, spiral)));
        QVERIFY2(test::checkAllInvariants(fullProblem, full).empty(),
                 qPrintable(violations(fullProblem, full)));
        QCOMPARE(spiral.cells.size(), std::size_t{15});
        QCOMPARE(full.cells.size(), std::size_t{16});
        QCOMPARE(spiral.metrics.coveredAreaSquareMetres, 60.0);
        QCOMPARE(full.metrics.coveredAreaSquareMetres, 63.0);
        QCOMPARE(full.metrics.passableAreaSquareMetres, 63.0);
        QCOMPARE(full.metrics.coveredFraction, 1.0);
        QVERIFY(spiral.metrics.coveredFraction < 1.0);
    }

    // Two mega-cells side by side whose facing south-side sub-cells are not both free: the only way across is
    // through the north pair, a single-sided edge, so the robot comes back the way it went.
    void singleSidedEdgeRepeatsCoverage() {
        PlanningProblem problem = drawnMap({"....", ".#.."}, {0.5, 0.5});
        const Plan plan = planWith("full-spiral-stc", problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(plan.cells.size(), std::size_t{2});
        QCOMPARE(plan.cells.cell(0).freeSubCellCount(), 3);
        QVERIFY(plan.paths.front().repeatedSubCellVisits > 0);
        QVERIFY(plan.metrics.repeatedFraction > 0.0);
        // Spiral-STC leaves the partly blocked mega-cell out altogether.
        PlanningProblem spiralProblem = drawnMap({"....", ".#.."}, {3.5, 0.5});
        QCOMPARE(planWith("spiral-stc", spiralProblem).cells.size(), std::size_t{1});
    }

    // A river splits the map: the robot covers its own bank and the other is reported unreachable.
    void riverLeavesTheFarBankUnreachable() {
        PlanningProblem problem =
            drawnMap({"....##....", "....##....", "....##....", "....##...."}, {0.5, 0.5});
        const Plan plan = planWith("spiral-stc", problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(plan.metrics.coveredAreaSquareMetres, 16.0);
        QCOMPARE(plan.metrics.unreachableAreaSquareMetres, 16.0);
        QCOMPARE(plan.issues.size(), std::size_t{1});
        QCOMPARE(plan.issues.front().code, std::string("unreachable-area"));
        // Said why, and where: the far bank's cells (2 x 2 m) span x 6 to 10 and y -4 to 0.
        const std::string& message = plan.issues.front().message;
        QVERIFY2(message.find("16 m2 of passable land cannot be reached by any robot: impassable land or the "
                              "area's edge cuts it off from every start (it lies round (") == 0,
                 message.c_str());
        QVERIFY2(message.find("); a robot started there would cover it") != std::string::npos,
                 message.c_str());
    }

    void severalStartsAreRefusedNamingTheOtherPlanners() {
        for (const std::string planner : {"spiral-stc", "full-spiral-stc"}) {
            PlanningProblem problem = drawnMap({"........", "........"}, {0.5, 0.5});
            problem.starts.push_back({problem.grid.originX + 6.5, problem.grid.originY - 0.5});
            try {
                (void)planWith(planner, problem);
                QFAIL("two starts for a one-robot planner must be refused");
            } catch (const PlanningError& error) {
                const std::string message = error.what();
                QVERIFY2(message.find(planner + " plans for one robot, but 2 starts were given") !=
                             std::string::npos,
                         error.what());
                QVERIFY2(message.find("mcpp-mlct") != std::string::npos, error.what());
            }
        }
    }

    // A start in a mega-cell Spiral-STC leaves out is refused with the reason.
    void startInADroppedMegaCellIsNamed() {
        PlanningProblem problem = drawnMap({"....", ".#.."}, {0.5, 0.5});
        try {
            (void)planWith("spiral-stc", problem);
            QFAIL("the start's mega-cell touches water");
        } catch (const PlanningError& error) {
            QCOMPARE(error.robot(), 0);
            QVERIFY2(std::string(error.what()).find("touch") != std::string::npos, error.what());
        }
    }
};

QTEST_APPLESS_MAIN(SpiralStcTest)
#include "test_spiral_stc.moc"
