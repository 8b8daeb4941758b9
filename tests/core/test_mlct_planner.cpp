#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/StartPointCheck.hpp"
#include "core/planners/ClosedInStart.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>
#include <tuple>

using namespace mcpp;

namespace {

PlanningProblem lakeProblem() {
    std::vector<bool> blocked(10 * 10, false);
    for (int row = 3; row < 6; ++row)
        for (int column = 3; column < 6; ++column)
            blocked[static_cast<std::size_t>(row * 10 + column)] = true;
    auto problem = test::uniformProblem(10, 10, 10.0, blocked, {});
    problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 9, 9)};
    return problem;
}

void expectError(const PlanningProblem& problem, PlanningError::Kind kind, const std::string& fragment) {
    try {
        (void)MlctPlanner{}.plan(problem, {});
        QFAIL(("expected an error containing: " + fragment).c_str());
    } catch (const PlanningError& error) {
        QVERIFY2(error.kind() == kind, error.what());
        QVERIFY2(std::string(error.what()).find(fragment) != std::string::npos, error.what());
    }
}

} // namespace

class MlctPlannerTest : public QObject {
    Q_OBJECT
  private slots:
    // Robot 1 is out in the field three times as long as its path takes (a drone between flights), robot 2
    // as long: planned again on those paces, the two come home together, robot 1 on a third of robot 2's
    // path. Balanced on path time alone, robot 1 was out twice as long as now.
    void timeInTheFieldIsEvenedOutWhereItIsMeasured() {
        auto problem = test::uniformProblem(30, 30, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 29, 29)};
        const auto threeTimesForRobot1 = [](const Plan& plan) {
            return std::vector<double>{3.0 * plan.paths[0].timeSeconds, plan.paths[1].timeSeconds};
        };
        const Plan onPaths = MlctPlanner{}.plan(problem, {});
        problem.fieldSeconds = threeTimesForRobot1;
        const Plan inTheField = MlctPlanner{}.plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, inTheField);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        const std::vector<double> before = threeTimesForRobot1(onPaths);
        const std::vector<double> after = threeTimesForRobot1(inTheField);
        QVERIFY2(
            std::max(after[0], after[1]) < 0.6 * std::max(before[0], before[1]),
            qPrintable(
                QString("%1 %2 against %3 %4").arg(after[0]).arg(after[1]).arg(before[0]).arg(before[1])));
        QVERIFY2(std::max(after[0], after[1]) <= 1.05 * std::min(after[0], after[1]),
                 qPrintable(QString("%1 %2").arg(after[0]).arg(after[1])));
        QVERIFY(inTheField.paths[0].timeSeconds < 0.4 * inTheField.paths[1].timeSeconds);
        const auto hasIssue = [&](const std::string& code) {
            return std::any_of(inTheField.issues.begin(), inTheField.issues.end(),
                               [&](const PlanIssue& issue) { return issue.code == code; });
        };
        QVERIFY(hasIssue("field-time-balance"));
        QVERIFY(!hasIssue("uneven-plan")); // the paths differ by design
        // The first plan, planned and dropped, is timed with the one kept.
        const auto rounds = std::find_if(
            inTheField.metrics.stageMilliseconds.begin(), inTheField.metrics.stageMilliseconds.end(),
            [](const auto& stage) { return stage.first == "field time rounds"; });
        QVERIFY(rounds != inTheField.metrics.stageMilliseconds.end());
        QVERIFY(rounds->second > 0.0);
        // The plan kept, a later round's, copied the first round's cells instead of building them again:
        // the same cells as a plan built on its own.
        QCOMPARE(inTheField.metrics.stageMilliseconds.front().first, std::string("cells of the first round"));
        QCOMPARE(inTheField.cells.size(), onPaths.cells.size());
        for (int id = 0; id < static_cast<int>(onPaths.cells.size()); ++id) {
            const Cell& kept = inTheField.cells.cell(id);
            const Cell& built = onPaths.cells.cell(id);
            QCOMPARE(
                std::tuple(kept.column, kept.row, kept.span, kept.freeSubCells, kept.turnSecondsPer90Degrees),
                std::tuple(built.column, built.row, built.span, built.freeSubCells,
                           built.turnSecondsPer90Degrees));
        }
    }

    // A robot whose pace in the field grows with its share (farther out, each flight spends more of itself
    // on the way there and back): a whole step to the pace measured on one plan overshoots on the next.
    // Half steps from the division on the paths bring the two home together all the same.
    void aPaceGrowingWithTheShareIsEvenedOutInSteps() {
        auto problem = test::uniformProblem(30, 30, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 29, 29)};
        const Plan onPaths = MlctPlanner{}.plan(problem, {});
        const double half = onPaths.paths[0].timeSeconds;
        const auto fartherDearer = [half](const Plan& plan) {
            const double path = plan.paths[0].timeSeconds;
            return std::vector<double>{path * std::pow(path / half, 1.0) * 3.0, plan.paths[1].timeSeconds};
        };
        problem.fieldSeconds = fartherDearer;
        const Plan inTheField = MlctPlanner{}.plan(problem, {});
        const auto violations = test::checkAllInvariants(problem, inTheField);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        const std::vector<double> after = fartherDearer(inTheField);
        const std::vector<double> before = fartherDearer(onPaths);
        QVERIFY(std::max(after[0], after[1]) < 0.5 * std::max(before[0], before[1]));
        QCOMPARE(inTheField.metrics.fieldMakespanSeconds, std::max(after[0], after[1]));
        QVERIFY2(std::max(after[0], after[1]) <= 1.03 * std::min(after[0], after[1]),
                 qPrintable(QString("%1 %2").arg(after[0]).arg(after[1])));
    }

    void plansAroundALake() {
        const auto problem = lakeProblem();
        const Plan plan = MlctPlanner{}.plan(problem, {});
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(),
                 qPrintable(QString::fromStdString(test::describe(test::checkAllInvariants(problem, plan)))));
        QCOMPARE(plan.planner, std::string("mcpp-mlct"));
        QCOMPARE(plan.metrics.robots.size(), std::size_t{2});
        QCOMPARE(plan.metrics.robots[0].cells + plan.metrics.robots[1].cells, 91);
        QCOMPARE(plan.metrics.coveredFraction, 1.0);
        QCOMPARE(plan.metrics.unreachableAreaSquareMetres, 0.0);
        QVERIFY(plan.metrics.ratio >= 1.0 && plan.metrics.ratio < 1.03);
        // Trees are walked into waypoints once the division is settled, after the turn balance.
        std::vector<std::string> stages;
        for (const auto& [stage, milliseconds] : plan.metrics.stageMilliseconds)
            stages.push_back(stage);
        QCOMPARE(stages, (std::vector<std::string>{"quadtree", "topology", "allocation", "straight borders",
                                                   "paths", "turn balance", "waypoints", "path balance",
                                                   "turn search", "metrics"}));
    }

    // The last search for fewer turns never makes a path slower: robot by robot, no path takes longer than
    // without it, and on a benchmark grid the plan turns less (49 x 49 with 8 robots: 1 650 turns against
    // 1 674), also where turns are free and only their count can gain.
    void turnSearchOnlyQuickens_data() {
        QTest::addColumn<bool>("freeTurns");
        QTest::newRow("turns timed") << false;
        QTest::newRow("turns free") << true;
    }
    void turnSearchOnlyQuickens() {
        QFETCH(bool, freeTurns);
        PlanningProblem problem = test::obstacleGridProblem(49, 8, 2020);
        if (freeTurns)
            problem.planner.parameters.set("turn_s", 0.0);
        problem.planner.parameters.set("turn_search_rounds", 0);
        const Plan without = MlctPlanner{}.plan(problem, {});
        problem.planner.parameters.set("turn_search_rounds", 4);
        const Plan with = MlctPlanner{}.plan(problem, {});
        QVERIFY2(test::checkAllInvariants(problem, with).empty(),
                 qPrintable(QString::fromStdString(test::describe(test::checkAllInvariants(problem, with)))));
        QCOMPARE(with.paths.size(), without.paths.size());
        int turnsWithout = 0;
        int turnsWith = 0;
        for (std::size_t robot = 0; robot < with.paths.size(); ++robot) {
            QVERIFY(with.paths[robot].timeSeconds <= without.paths[robot].timeSeconds * (1.0 + 1e-9));
            turnsWithout += without.paths[robot].turns;
            turnsWith += with.paths[robot].turns;
        }
        QVERIFY2(turnsWith < turnsWithout,
                 qPrintable(QString("%1 against %2").arg(turnsWith).arg(turnsWithout)));
        QVERIFY(with.metrics.makespanSeconds <= without.metrics.makespanSeconds * (1.0 + 1e-9));
    }

    // Regions grown on pieces of one whole-map tree turn less than regions grown cell by cell, at as even a
    // split: over three 100 x 100 grids with 8 robots the plans turn less in total, and each stays within
    // 1 % of its lower bound. By default regions grow cell by cell, compact.
    void treePiecesTurnLess() {
        int turnsByCell = 0;
        int turnsOnPieces = 0;
        for (std::uint32_t seed : {2020U, 7U, 99U}) {
            PlanningProblem problem = test::obstacleGridProblem(100, 8, seed);
            const Plan byDefault = MlctPlanner{}.plan(problem, {});
            problem.planner.parameters.set("tree_piece_share", 0.0);
            const Plan byCell = MlctPlanner{}.plan(problem, {});
            QCOMPARE(byDefault.regions.robotOfCell, byCell.regions.robotOfCell);
            problem.planner.parameters.set("tree_piece_share", 3.0);
            const Plan onPieces = MlctPlanner{}.plan(problem, {});
            QVERIFY2(test::checkAllInvariants(problem, onPieces).empty(),
                     qPrintable(QString::fromStdString(
                         test::describe(test::checkAllInvariants(problem, onPieces)))));
            QVERIFY(onPieces.regions.robotOfCell != byCell.regions.robotOfCell);
            QVERIFY2(onPieces.metrics.ratio <= 1.01, qPrintable(QString::number(onPieces.metrics.ratio)));
            QCOMPARE(onPieces.metrics.coveredFraction, byCell.metrics.coveredFraction);
            for (const CoveragePath& path : byCell.paths)
                turnsByCell += path.turns;
            for (const CoveragePath& path : onPieces.paths)
                turnsOnPieces += path.turns;
        }
        QVERIFY2(turnsOnPieces < turnsByCell,
                 qPrintable(QString("%1 against %2").arg(turnsOnPieces).arg(turnsByCell)));
    }

    void startOnObstacleIsNamed() {
        auto problem = lakeProblem();
        problem.starts[1] = test::pixelCentre(problem.grid, 4, 4);
        expectError(problem, PlanningError::Kind::StartOnObstacle, "robot 2 start (500045");
        expectError(problem, PlanningError::Kind::StartOnObstacle, "class 99 (water)");
    }

    void startOutsideIsNamed() {
        auto problem = lakeProblem();
        problem.starts[0] = {0.0, 0.0};
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "robot 1 start (0, 0) is outside the raster");
        problem = lakeProblem();
        problem.grid.outside.assign(100, 0);
        problem.grid.outside[99] = 1;
        problem.starts[1] = test::pixelCentre(problem.grid, 9, 9);
        expectError(problem, PlanningError::Kind::StartOutsideArea, "nodata");
    }

    // A start on the raster but off the task area says why: nodata, outside the area of interest, or in a
    // no-go zone.
    void startOffTheTaskAreaSaysWhy() {
        auto problem = lakeProblem();
        problem.grid.outside.assign(problem.grid.values.size(), 0);
        problem.grid.outside[problem.grid.index(0, 0)] = ClassGrid::outsideArea;
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "is not in the task area: it lies outside the area of interest");
        problem.grid.outside[problem.grid.index(0, 0)] = ClassGrid::inNoGoZone;
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "is not in the task area: it lies in a no-go zone");
        problem.grid.outside[problem.grid.index(0, 0)] = ClassGrid::outsideNodata;
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "is not in the task area: the raster has no land cover there (nodata)");
    }

    // A start just off the task area (the nodata rim of a warped raster) says where the nearest land a robot
    // can start on lies: here 3 pixels of nodata east and south, and water east of them.
    void startOffTheTaskAreaNamesTheNearestLand() {
        auto problem = lakeProblem();
        problem.grid.outside.assign(problem.grid.values.size(), 0);
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < 3; ++column)
                problem.grid.outside[problem.grid.index(column, row)] = ClassGrid::outsideNodata;
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "(nodata); the nearest land of the task area a robot can cross is 30 m east, at (500035, "
                    "3999995)");
        problem.grid.values[problem.grid.index(3, 0)] = problem.grid.valueAt(4, 4); // water
        expectError(
            problem, PlanningError::Kind::StartOutsideArea,
            "(nodata); the nearest land of the task area a robot can cross is 30 m south, at (500005, "
            "3999965)");

        // Pixels three times as tall as wide: land one row north (30 m) does not hide land three columns
        // west, nearer (25.5 m from a point at the west edge of its pixel).
        PlanningProblem tall = test::uniformProblem(10, 10, 10.0, std::vector<bool>(100, false), {});
        tall.grid.pixelHeight = 30.0;
        tall.grid.outside.assign(tall.grid.values.size(), ClassGrid::outsideNodata);
        tall.grid.outside[tall.grid.index(5, 4)] = 0;
        tall.grid.outside[tall.grid.index(2, 5)] = 0;
        const MapPoint point{tall.grid.originX + 50.5, tall.grid.originY - 5.5 * 30.0};
        const auto problemThere = startPointProblem(tall.grid, tall.classes, point);
        QVERIFY(problemThere.has_value());
        const std::string refusal = startRefusal(tall.grid, tall.classes, point, *problemThere);
        QVERIFY2(refusal.find("can cross is 25.5 m west, at (") != std::string::npos, refusal.c_str());
        // The planner's refusal says it; the problem's detail, which notes of take-offs repeat, does not.
        QVERIFY(problemThere->detail.find("nearest") == std::string::npos);
    }

    // The raster spans x 500000 to 500100, y 3999900 to 4000000: how far off and which way (the compass
    // point nearest the way from the raster's nearest point), to the centimetre.
    void startOutsideSaysHowFarAndWhichWay() {
        auto problem = lakeProblem();
        problem.starts[0] = {500150.504, 4000230.25};
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "robot 1 start (500150.5, 4000230.25) is outside the raster, 236 m north of it (x "
                    "500000.00 to 500100.00, y 3999900.00 to 4000000.00)");
        problem.starts[0] = {500050.0, 3999000.0};
        expectError(problem, PlanningError::Kind::StartOutsideArea,
                    "is outside the raster, 900 m south of it");
        problem.starts[0] = {499990.0, 3999950.0};
        expectError(problem, PlanningError::Kind::StartOutsideArea, "is outside the raster, 10 m west of it");
        problem.starts[0] = {500100.0, 3999950.0}; // the east edge belongs to no pixel
        expectError(problem, PlanningError::Kind::StartOutsideArea, "is outside the raster, on its far edge");
        // A grid turned from true north (a Lambert grid far from its central meridian, true north 18 degrees
        // clockwise of the grid's): a point due east in truth lies south-east on the grid, and is said east.
        problem.grid.trueNorthRadians = -18.0 * std::acos(-1.0) / 180.0;
        problem.starts[0] = {500966.0,
                             3999400.0}; // 1 km from the corner, 30 degrees south of the grid's east
        expectError(problem, PlanningError::Kind::StartOutsideArea, " east of it (x");
        problem.grid.trueNorthRadians = 0.0;
        expectError(problem, PlanningError::Kind::StartOutsideArea, " south-east of it (x");
    }

    void twoRobotsInOneCellAreRefused() {
        auto problem = lakeProblem();
        problem.starts.push_back(problem.starts[0]);
        expectError(problem, PlanningError::Kind::StartsShareCell, "robot 3 start");
    }

    void nanAndEmptyInputsAreRefused() {
        auto problem = lakeProblem();
        problem.starts[0].x = std::nan("");
        expectError(problem, PlanningError::Kind::InvalidParameter, "robot 1 start (nan");
        problem = lakeProblem();
        problem.starts.clear();
        expectError(problem, PlanningError::Kind::InvalidParameter, "no robots");
        problem = lakeProblem();
        problem.starts.assign(150, problem.starts[0]);
        expectError(problem, PlanningError::Kind::TooManyRobots, "150 robots but only 91");
        problem.starts.assign(mostRobots + 1, problem.starts[0]); // more than region labels can number
        expectError(problem, PlanningError::Kind::TooManyRobots,
                    "32768 robots: one plan takes at most 32767");
    }

    void snappingMovesABadStartWithAWarning() {
        auto problem = lakeProblem();
        problem.starts[1] = test::pixelCentre(problem.grid, 4, 4);
        problem.planner.parameters.set("snap_starts_to_free_cells", true);
        const Plan plan = MlctPlanner{}.plan(problem, {});
        QCOMPARE(plan.warnings().size(), std::size_t{1});
        QCOMPARE(plan.issues.front().code, std::string("start-moved"));
        // How far, in metres, and where: the cell the robot's path now starts in.
        const MapPoint given = problem.starts[1];
        const Waypoint& moved = plan.paths[1].waypoints.front();
        const Cell& cell = plan.cells.cell(moved.cell);
        const std::string expected =
            "moved " + formatDistance(std::hypot(cell.centreX() - given.x, cell.centreY() - given.y)) +
            " to the nearest free cell's centre";
        QVERIFY2(plan.warnings()[0].find(expected) != std::string::npos, plan.warnings()[0].c_str());
        QVERIFY(test::checkRegions(plan).empty());
    }

    // Robot 1 starts in a corner whose two neighbours are the other robots' starts: its region is its start
    // cell alone, and the plan says so, where a balanced one says nothing.
    void robotWalledInByOtherStartsIsNamed() {
        auto problem = test::uniformProblem(20, 20, 10.0, std::vector<bool>(20 * 20, false), {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 1, 0),
                          test::pixelCentre(problem.grid, 0, 1)};
        const Plan plan = MlctPlanner{}.plan(problem, {});
        QVERIFY(plan.metrics.ratio > 1.4);
        const auto uneven = std::find_if(plan.issues.begin(), plan.issues.end(),
                                         [](const PlanIssue& issue) { return issue.code == "uneven-plan"; });
        QVERIFY(uneven != plan.issues.end());
        QCOMPARE(uneven->severity, IssueSeverity::Warning);
        QVERIFY2(uneven->message.rfind("robot 1 covers less than half of a fair share", 0) == 0,
                 uneven->message.c_str());
        // Only its start cell lies behind the others' starts, and the warning says so.
        QVERIFY2(uneven->message.find(
                     "robot 1's start is closed in by the starts of robots 2 and 3, so its region "
                     "can hold no more than " +
                     formatArea(plan.cells.cell(plan.regions.startCell[0]).passableAreaSquareMetres) + ";") !=
                     std::string::npos,
                 uneven->message.c_str());
        const auto closed = closedInStart(plan, 0, 0.5 * plan.metrics.lowerBoundSeconds);
        QVERIFY(closed.has_value());
        QCOMPARE(closed->closedBy, (std::vector<int>{1, 2}));
        QVERIFY(!closedInStart(plan, 1, 0.5 * plan.metrics.lowerBoundSeconds).has_value());
        // The advice it gives holds: MSTC's balanced pieces need no start inside, and even the plan out.
        QVERIFY2(
            uneven->message.find("or plan with MSTC and Balanced pieces on (planner mstc, balanced=true)") !=
                std::string::npos,
            uneven->message.c_str());
        auto advised = problem;
        advised.planner = defaultPlannerChoice("mstc");
        advised.planner.parameters.set("balanced", true);
        const Plan followed = makePlanner("mstc")->plan(advised, {});
        QVERIFY2(followed.metrics.ratio < 1.1, std::to_string(followed.metrics.ratio).c_str());
        QVERIFY(std::none_of(followed.issues.begin(), followed.issues.end(),
                             [](const PlanIssue& issue) { return issue.code == "uneven-plan"; }));
        // A fleet of its own speeds: MSTC would divide the work as if all drove alike, so it is not offered;
        // the walled-in robot, at its own speed, is still named.
        auto ownSpeeds = problem;
        ownSpeeds.robotSpeeds = {0.5, 2.0, 1.0};
        const Plan mixed = MlctPlanner{}.plan(ownSpeeds, {});
        const auto mixedUneven =
            std::find_if(mixed.issues.begin(), mixed.issues.end(),
                         [](const PlanIssue& issue) { return issue.code == "uneven-plan"; });
        QVERIFY(mixedUneven != mixed.issues.end());
        QVERIFY2(mixedUneven->message.find("robot 1's start is closed in by the starts of robots 2 and 3") !=
                     std::string::npos,
                 mixedUneven->message.c_str());
        QVERIFY2(mixedUneven->message.find("MSTC") == std::string::npos, mixedUneven->message.c_str());
        const Plan balanced = MlctPlanner{}.plan(lakeProblem(), {});
        QVERIFY(std::none_of(balanced.issues.begin(), balanced.issues.end(),
                             [](const PlanIssue& issue) { return issue.code == "uneven-plan"; }));
        // A fourth robot walled into a pocket of its own: the bound is then one part's share, and the plan
        // names the pocket (confined-robot) instead.
        std::vector<bool> blocked(20 * 20, false);
        for (int row = 14; row < 20; ++row)
            blocked[static_cast<std::size_t>(row * 20 + 14)] = true;
        for (int column = 14; column < 20; ++column)
            blocked[static_cast<std::size_t>(14 * 20 + column)] = true;
        auto split = test::uniformProblem(20, 20, 10.0, blocked, {});
        split.starts = problem.starts;
        split.starts.push_back(test::pixelCentre(split.grid, 18, 18));
        const Plan pocket = MlctPlanner{}.plan(split, {});
        QVERIFY(!pocket.metrics.confinedRobots.empty());
        QVERIFY(pocket.metrics.ratio > 1.05);
        QVERIFY(std::none_of(pocket.issues.begin(), pocket.issues.end(),
                             [](const PlanIssue& issue) { return issue.code == "uneven-plan"; }));
    }

    // A fast robot behind a wall whose only gap holds another robot's start: its 80 cells are more than half
    // of the bound in cells, yet at twice the speed it covers them in less than half of the bound. Judged at
    // its own pace it is closed in, and the warning names it.
    void fastRobotClosedInIsJudgedAtItsOwnPace() {
        constexpr int side = 20;
        std::vector<bool> blocked(side * side, false);
        for (int row = 1; row < side; ++row)
            blocked[static_cast<std::size_t>(row * side + 4)] = true; // a wall at column 4, open at row 0
        auto problem = test::uniformProblem(side, side, 10.0, blocked, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 10), test::pixelCentre(problem.grid, 4, 0),
                          test::pixelCentre(problem.grid, 12, 10)};
        problem.robotSpeeds = {2.0, 1.0, 1.0};
        const Plan plan = MlctPlanner{}.plan(problem, {});
        const double bound = plan.metrics.lowerBoundSeconds;
        const double behindTheWall = 80.0 * plan.cells.cell(plan.regions.startCell[0]).coverSeconds();
        // The case this test is about: more than half the bound at one pace, less than it at two.
        QVERIFY2(behindTheWall > 0.5 * bound && behindTheWall < bound,
                 (std::to_string(behindTheWall) + " against a bound of " + std::to_string(bound)).c_str());
        QVERIFY(!closedInStart(plan, 0, 0.5 * bound).has_value());
        const auto uneven = std::find_if(plan.issues.begin(), plan.issues.end(),
                                         [](const PlanIssue& issue) { return issue.code == "uneven-plan"; });
        QVERIFY(uneven != plan.issues.end());
        QVERIFY2(
            uneven->message.find("robot 1's start is closed in by the start of robot 2, so its region can "
                                 "hold no more than " +
                                 formatArea(80.0 * 100.0)) != std::string::npos,
            uneven->message.c_str());
    }

    // Starts on every cell of a corner block: the robots inside it are walled in by the block's others. Three
    // are described and the rest counted, so that the advice after them is still read.
    void manyClosedInStartsAreCounted_data() {
        QTest::addColumn<int>("block");
        QTest::addColumn<QString>("tail");
        // A block of 3 x 3 closes in the 2 x 2 at its corner: four robots, one more than described.
        QTest::newRow("3 x 3 block") << 3 << "the start of one more robot is closed in too; ";
        // A block of 4 x 4 closes in the 3 x 3 at its corner: nine robots, six more than described.
        QTest::newRow("4 x 4 block") << 4 << "the starts of 6 more robots are closed in too; ";
    }

    void manyClosedInStartsAreCounted() {
        QFETCH(int, block);
        QFETCH(QString, tail);
        auto problem = test::uniformProblem(20, 20, 10.0, std::vector<bool>(20 * 20, false), {});
        for (int row = 0; row < block; ++row)
            for (int column = 0; column < block; ++column)
                problem.starts.push_back(test::pixelCentre(problem.grid, column, row));
        const Plan plan = MlctPlanner{}.plan(problem, {});
        const auto uneven = std::find_if(plan.issues.begin(), plan.issues.end(),
                                         [](const PlanIssue& issue) { return issue.code == "uneven-plan"; });
        QVERIFY(uneven != plan.issues.end());
        const std::string& message = uneven->message;
        std::size_t described = 0;
        for (std::size_t at = message.find("'s start is closed in by"); at != std::string::npos;
             at = message.find("'s start is closed in by", at + 1))
            ++described;
        QCOMPARE(described, std::size_t{3});
        const std::size_t counted = message.find(tail.toStdString());
        QVERIFY2(counted != std::string::npos, message.c_str());
        // The count comes after the three described and before the advice.
        QVERIFY(counted > message.rfind("'s start is closed in by"));
        QVERIFY2(message.find("starts close together", counted) != std::string::npos, message.c_str());
        int closedIn = 0;
        for (int robot = 0; robot < block * block; ++robot)
            if (closedInStart(plan, robot, 0.5 * plan.metrics.lowerBoundSeconds))
                ++closedIn;
        QCOMPARE(closedIn, (block - 1) * (block - 1));
    }

    void reportsProgressAndHonoursCancel() {
        const auto problem = lakeProblem();
        std::vector<std::string> stages;
        ProgressReporter reporter([&](std::string_view stage, double) {
            if (stages.empty() || stages.back() != stage)
                stages.emplace_back(stage);
        });
        (void)MlctPlanner{}.plan(problem, reporter);
        QCOMPARE(stages, (std::vector<std::string>{"quadtree", "topology", "allocation", "paths",
                                                   "turn balance", "waypoints", "done"}));
        std::atomic<bool> cancel{true};
        try {
            (void)MlctPlanner{}.plan(problem, ProgressReporter({}, &cancel));
            QFAIL("a cancelled plan must stop");
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::Cancelled);
        }
    }

    void sameInputSamePlan() {
        test::RandomMapSpec spec;
        spec.columns = 48;
        spec.rows = 40;
        spec.landCovers = 3;
        spec.obstacleFraction = 0.08;
        spec.robots = 5;
        spec.seed = 5;
        const auto problem = test::randomProblem(spec);
        const Plan first = MlctPlanner{}.plan(problem, {});
        const Plan second = MlctPlanner{}.plan(problem, {});
        QCOMPARE(first.regions.robotOfCell, second.regions.robotOfCell);
        for (std::size_t robot = 0; robot < first.paths.size(); ++robot) {
            QCOMPARE(first.paths[robot].waypoints.size(), second.paths[robot].waypoints.size());
            QCOMPARE(first.paths[robot].lengthMetres, second.paths[robot].lengthMetres);
        }
    }

    void plannerRegistry() {
        QVERIFY(makePlanner("mcpp-mlct") != nullptr);
        QVERIFY(makePlanner("no-such-planner") == nullptr);
        QVERIFY(!availablePlanners().empty());
    }
};

QTEST_APPLESS_MAIN(MlctPlannerTest)
#include "test_mlct_planner.moc"
