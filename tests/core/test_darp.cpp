#include "core/allocation/StartComponents.hpp"
#include "core/planners/PlanMetricsCalculator.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>

using namespace mcpp;

namespace {

Plan planWithDarp(PlanningProblem& problem) {
    problem.planner = defaultPlannerChoice("darp");
    return makePlanner("darp")->plan(problem, {});
}

QString violations(const PlanningProblem& problem, const Plan& plan) {
    return QString::fromStdString(test::describe(test::checkAllInvariants(problem, plan)));
}

int cellsOf(const Plan& plan, int robot) {
    return static_cast<int>(
        std::count(plan.regions.robotOfCell.begin(), plan.regions.robotOfCell.end(), robot));
}

bool hasIssue(const Plan& plan, const std::string& code) {
    return std::any_of(plan.issues.begin(), plan.issues.end(),
                       [&](const PlanIssue& issue) { return issue.code == code; });
}

std::vector<std::string> rowsOf(int count, const std::string& row) {
    return std::vector<std::string>(static_cast<std::size_t>(count), row);
}

} // namespace

// DARP on maps whose fair division is known by hand. Pixels are sub-cells, cells 2 x 2 pixels; a grass cell
// takes 4 s to cover, a mud cell 8 s.
class DarpTest : public QObject {
    Q_OBJECT

  private slots:
    // Twenty cells in a row, a robot at each end: ten each, two straight tours, makespan at the lower bound.
    void corridorSplitsInHalves() {
        PlanningProblem problem =
            test::drawnProblem(rowsOf(2, std::string(40, '.')), {{0.5, 0.5}, {39.5, 0.5}});
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(cellsOf(plan, 0), 10);
        QCOMPARE(cellsOf(plan, 1), 10);
        QCOMPARE(plan.metrics.ratio, 1.0);
        QVERIFY(!hasIssue(plan, "not-converged"));
    }

    // A U of 36 cells, a robot at the top of each arm: 18 each, each region in one piece round the bend.
    void uShapeSplitsAtTheBottom() {
        std::vector<std::string> rows = rowsOf(12, "....####....");
        for (const std::string& row : rowsOf(4, "............"))
            rows.push_back(row);
        PlanningProblem problem = test::drawnProblem(rows, {{0.5, 0.5}, {11.5, 0.5}});
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(plan.cells.size(), std::size_t{36});
        QCOMPARE(cellsOf(plan, 0), 18);
        QCOMPARE(cellsOf(plan, 1), 18);
    }

    // A river: two robots share the west bank (24 cells), one has the east bank (16 cells) to itself. Each
    // bank is divided on its own; nothing crosses the water.
    void riverBanksAreDividedApart() {
        PlanningProblem problem =
            test::drawnProblem(rowsOf(8, "............####........"), {{0.5, 0.5}, {11.5, 7.5}, {23.5, 0.5}});
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(cellsOf(plan, 0), 12);
        QCOMPARE(cellsOf(plan, 1), 12);
        QCOMPARE(cellsOf(plan, 2), 16);
        QVERIFY(!hasIssue(plan, "not-converged"));
    }

    // A robot walled into a pocket of 8 cells can cover only those; the other two share the 48 cells
    // beyond the wall. No plan beats 24 cells (96 s) for the pair, so that is the lower bound, not the
    // whole map's 56 cells over three robots, and the walled-in robot is named with its pocket's area.
    void walledInRobotBoundsByItsPart() {
        PlanningProblem problem = test::drawnProblem(rowsOf(8, "....##........................"),
                                                     {{0.5, 0.5}, {6.5, 0.5}, {29.5, 7.5}});
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(cellsOf(plan, 0), 8);
        const double travelSeconds = plan.cells.cell(0).travelSeconds();
        const double pairTurnSeconds = plan.paths[1].turnSeconds + plan.paths[2].turnSeconds;
        QVERIFY(pairTurnSeconds > 0.0);
        QCOMPARE(plan.metrics.lowerBoundSeconds, (48.0 * travelSeconds + pairTurnSeconds) / 2.0);
        QVERIFY2(plan.metrics.ratio <= 1.05, qPrintable(QString::number(plan.metrics.ratio))); // 1.6 before
        QCOMPARE(plan.metrics.confinedRobots.size(), std::size_t{1});
        QCOMPARE(plan.metrics.confinedRobots[0].robot, 0);
        QCOMPARE(plan.metrics.confinedRobots[0].pocketAreaSquareMetres,
                 8.0 * plan.cells.cell(0).passableAreaSquareMetres);
        QVERIFY(hasIssue(plan, "confined-robot"));
        // Its 8 cells are under half of an even share (56 / 3): a warning, with the share.
        const auto confined =
            std::find_if(plan.issues.begin(), plan.issues.end(),
                         [](const PlanIssue& issue) { return issue.code == "confined-robot"; });
        QVERIFY(confined->severity == IssueSeverity::Warning);
        QVERIFY2(confined->message.find(" of an even share of the land) and can cover only that part") !=
                     std::string::npos,
                 confined->message.c_str());
        // Without the wall nobody is confined and the bound is the whole map's over three robots.
        PlanningProblem open =
            test::drawnProblem(rowsOf(8, std::string(30, '.')), {{0.5, 0.5}, {6.5, 0.5}, {29.5, 7.5}});
        const Plan openPlan = planWithDarp(open);
        QVERIFY(openPlan.metrics.confinedRobots.empty());
        double openTurnSeconds = 0.0;
        for (const CoveragePath& path : openPlan.paths)
            openTurnSeconds += path.turnSeconds;
        QCOMPARE(openPlan.metrics.lowerBoundSeconds, (60.0 * travelSeconds + openTurnSeconds) / 3.0);
        QVERIFY(!hasIssue(openPlan, "confined-robot"));
        QCOMPARE(openPlan.metrics.sharedPartsRatio, 0.0); // one part: the ratio says it all
        QCOMPARE(plan.metrics.sharedPartsRatio, 0.0); // the pair's part, not the lone robot, sets the bound
    }

    // A robot walled into a large pocket of its own sets the bound (44 cells alone against 12 for two), so
    // every plan's ratio is about 1; the pair's balance is given apart, against their part's own bound.
    void loneRobotsBoundLeavesTheOthersBalanceApart() {
        PlanningProblem problem = test::drawnProblem(rowsOf(8, "......................##......"),
                                                     {{0.5, 0.5}, {24.5, 0.5}, {29.5, 7.5}});
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(cellsOf(plan, 0), 44);
        const double travelSeconds = plan.cells.cell(0).travelSeconds();
        QVERIFY(
            std::abs(plan.metrics.lowerBoundSeconds - (44.0 * travelSeconds + plan.paths[0].turnSeconds)) <=
            1e-9 * plan.metrics.lowerBoundSeconds);
        const double pairBound =
            (12.0 * travelSeconds + plan.paths[1].turnSeconds + plan.paths[2].turnSeconds) / 2.0;
        const double pairLongest = std::max(plan.paths[1].timeSeconds, plan.paths[2].timeSeconds);
        QVERIFY2(std::abs(plan.metrics.sharedPartsRatio - pairLongest / pairBound) <= 1e-9,
                 qPrintable(QString::number(plan.metrics.sharedPartsRatio)));
        QVERIFY(plan.metrics.sharedPartsRatio >= 1.0 - 1e-9);
        // One of the pair slower by a third of its part's bound: the ratio, the lone robot's, does not see
        // it.
        Plan slower = plan;
        slower.paths[1].timeSeconds = pairBound * 4.0 / 3.0;
        PlanMetricsCalculator{}.compute(slower);
        QCOMPARE(slower.metrics.ratio, plan.metrics.ratio);
        QVERIFY(std::abs(slower.metrics.sharedPartsRatio - 4.0 / 3.0) <= 1e-9);
        QVERIFY(slower.metrics.boundSetByLoneRobots());
    }

    // Regions that do not touch can still share one connected part: with the cells between two regions
    // left to nobody, the regions no longer link every robot, yet the part holds all three robots and none
    // is confined; walled off, one is.
    void regionsApartShareTheirPart() {
        const std::vector<MapPoint> starts{{0.5, 0.5}, {14.5, 0.5}, {29.5, 0.5}};
        PlanningProblem problem = test::drawnProblem(rowsOf(2, std::string(30, '.')), starts);
        Plan plan = planWithDarp(problem);
        QVERIFY(plan.metrics.confinedRobots.empty());
        QVERIFY(regionsLinkEveryRobot(plan.cells, plan.regions)); // 0 touches 1, 1 touches 2
        // A robot without cells links nothing.
        RegionAllocation withoutRobot2 = plan.regions;
        std::replace(withoutRobot2.robotOfCell.begin(), withoutRobot2.robotOfCell.end(), 2, 1);
        QVERIFY(!regionsLinkEveryRobot(plan.cells, withoutRobot2));
        std::vector<int>& owner = plan.regions.robotOfCell;
        std::vector<int> border;
        for (int cell = 0; cell < static_cast<int>(plan.cells.size()); ++cell)
            for (const int neighbour : plan.cells.neighbours(cell))
                if (owner[static_cast<std::size_t>(cell)] == 0 &&
                    owner[static_cast<std::size_t>(neighbour)] == 1)
                    border.push_back(cell);
        QVERIFY(!border.empty());
        for (const int cell : border)
            owner[static_cast<std::size_t>(cell)] = -1;
        QVERIFY(!regionsLinkEveryRobot(plan.cells, plan.regions));
        PlanMetricsCalculator{}.compute(plan);
        QVERIFY(plan.metrics.confinedRobots.empty());
        // Obstacles across the corridor wall robot 0 in.
        PlanningProblem walled = test::drawnProblem(rowsOf(2, "......##......................"), starts);
        const Plan walledPlan = planWithDarp(walled);
        QVERIFY(!regionsLinkEveryRobot(walledPlan.cells, walledPlan.regions));
        QCOMPARE(walledPlan.metrics.confinedRobots.size(), std::size_t{1});
        QCOMPARE(walledPlan.metrics.confinedRobots[0].robot, 0);
    }

    // Half the corridor is mud: DARP balances time, so the robot on the mud side gets fewer cells, and the
    // two regions' cover times differ by at most one mud cell.
    void mudCostsTimeNotArea() {
        PlanningProblem problem = test::drawnProblem(rowsOf(2, std::string(20, 'm') + std::string(20, '.')),
                                                     {{0.5, 0.5}, {39.5, 0.5}});
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QVERIFY2(
            cellsOf(plan, 0) < cellsOf(plan, 1),
            qPrintable(
                QString("%1 mud-side cells, %2 grass-side").arg(cellsOf(plan, 0)).arg(cellsOf(plan, 1))));
        const auto& cost = plan.regions.costSeconds;
        QVERIFY2(std::abs(cost[0] - cost[1]) <= 8.0 + 1e-9,
                 qPrintable(QString("%1 s vs %2 s").arg(cost[0]).arg(cost[1])));
    }

    // Eight robots on an open field of 400 cells: every region within one cell of the fair share.
    void openFieldIsBalancedToACell() {
        std::vector<MapPoint> starts;
        for (int robot = 0; robot < 8; ++robot)
            starts.push_back({0.5 + 5.0 * robot, robot % 2 == 0 ? 0.5 : 39.5});
        PlanningProblem problem = test::drawnProblem(rowsOf(40, std::string(40, '.')), starts);
        const Plan plan = planWithDarp(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        for (int robot = 0; robot < 8; ++robot)
            QVERIFY2(std::abs(cellsOf(plan, robot) - 50) <= 1,
                     qPrintable(QString("robot %1 has %2 cells").arg(robot).arg(cellsOf(plan, robot))));
        QVERIFY(!hasIssue(plan, "not-converged"));
    }

    // Stopped after a single round of correction factors, with the starts bunched in a corner, the border
    // exchange still brings 100 cells to 33, 33 and 34.
    void oneRoundThenTheBorderExchangeBalances() {
        PlanningProblem problem =
            test::drawnProblem(rowsOf(20, std::string(20, '.')), {{0.5, 0.5}, {2.5, 0.5}, {4.5, 0.5}});
        problem.planner = defaultPlannerChoice("darp");
        problem.planner.parameters.set("max_iterations", 1);
        const Plan plan = makePlanner("darp")->plan(problem, {});
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        for (int robot = 0; robot < 3; ++robot)
            QVERIFY2(cellsOf(plan, robot) == 33 || cellsOf(plan, robot) == 34,
                     qPrintable(QString("robot %1 has %2 cells").arg(robot).arg(cellsOf(plan, robot))));
    }
};

QTEST_APPLESS_MAIN(DarpTest)
#include "test_darp.moc"
