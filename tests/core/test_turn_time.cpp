// What turns cost: the turn time model, path times with turns on hand-made paths, the parameter that sets
// it, and plans whose costs, times and bounds count turns (or, at 0, do not).
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/TurnCalibration.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

using namespace mcpp;

Q_DECLARE_METATYPE(std::vector<mcpp::Waypoint>)

namespace {

// One 100 m cell whose turns cost `turnSeconds` per 90 degrees.
CellGraph oneCell(double turnSeconds) {
    GridFrame frame;
    frame.originX = 0.0;
    frame.originY = 100.0;
    frame.bottomCellSize = 100.0;
    frame.columns = 1;
    frame.rows = 1;
    Cell cell;
    cell.size = 100.0;
    cell.speedMetresPerSecond = 2.0;
    cell.turnSecondsPer90Degrees = static_cast<float>(turnSeconds);
    return CellGraph(frame, {cell}, NeighbourTopology({0, 0}, {}));
}

// A row of three 10 m cells, each of its column's speed, turn time and sub-cells; neighbours in the row.
CellGraph threeCellRow(const std::vector<Cell>& figures) {
    GridFrame frame;
    frame.originY = 10.0;
    frame.bottomCellSize = 10.0;
    frame.columns = 3;
    frame.rows = 1;
    std::vector<Cell> cells = figures;
    for (int column = 0; column < 3; ++column) {
        Cell& cell = cells[static_cast<std::size_t>(column)];
        cell.column = column;
        cell.minX = 10.0 * column;
        cell.size = 10.0;
    }
    return CellGraph(frame, cells, NeighbourTopology({0, 1, 3, 4}, {1, 0, 2, 1}));
}

// A path through the cell at 2 m/s, or in no cell where `inCell` is false.
std::vector<Waypoint> pathOf(std::initializer_list<MapPoint> points, bool inCell = true) {
    std::vector<Waypoint> waypoints;
    for (const MapPoint point : points)
        waypoints.push_back({point.x, point.y, inCell ? 0 : -1, 2.0F});
    return waypoints;
}

Plan planned(PlanningProblem problem, const ParameterValue& turnSeconds) {
    problem.planner = defaultPlannerChoice(MlctPlanner::plannerName);
    problem.planner.parameters.set("turn_s", turnSeconds);
    return makePlanner(MlctPlanner::plannerName)->plan(problem, {});
}

// Whether two numbers have the same bits (QCOMPARE on doubles allows a relative error).
bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

class TurnTimeTest : public QObject {
    Q_OBJECT

  private slots:
    // Steps along an axis take a shortcut past the square root and the divisions; lengths, directions and
    // times must keep every bit of the plain formulas, or plans would change with it.
    void stepShortcutsKeepTheBits() {
        std::mt19937 random(20261126);
        std::uniform_real_distribution<double> metres(-5000.0, 5000.0);
        std::uniform_real_distribution<double> speed(0.1, 30.0);
        int axisSteps = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            double dx = metres(random);
            double dy = metres(random);
            if (trial % 4 == 1)
                dx = trial % 8 == 1 ? 0.0 : -0.0;
            if (trial % 4 == 2)
                dy = 0.0;
            if (trial % 97 == 0)
                dx *= 1e-12; // tiny steps too
            axisSteps += dx == 0.0 || dy == 0.0 ? 1 : 0;
            const double length = std::sqrt(dx * dx + dy * dy);
            const Step step = stepOf(dx, dy);
            QVERIFY2(sameBits(step.length, length), qPrintable(QString("%1 %2").arg(dx).arg(dy)));
            QVERIFY(sameBits(step.x, dx / length));
            QVERIFY(sameBits(step.y, dy / length));
            const double from = speed(random);
            const double to = trial % 3 == 0 ? speed(random) : from;
            QVERIFY(sameBits(travelSeconds(length, from, to), length / 2.0 / from + length / 2.0 / to));
        }
        QVERIFY(axisSteps > 9000); // the shortcut was taken
        QCOMPARE(stepOf(0.0, 0.0).length, 0.0);
    }

    void automaticTurnTimeIsSpeedOverAcceleration() {
        TurnTimeModel model;
        QCOMPARE(model.secondsPer90Degrees(3.0), 3.0); // 1 m/s2 by default
        model.accelerationMetresPerSecondSquared = 2.5;
        QCOMPARE(model.secondsPer90Degrees(15.0), 6.0);
        QCOMPARE(model.secondsPer90Degrees(0.0), 0.0);
        model.fixedSecondsPer90Degrees = 4.0;
        QCOMPARE(model.secondsPer90Degrees(15.0), 4.0);
        model.fixedSecondsPer90Degrees = 0.0;
        QCOMPARE(model.secondsPer90Degrees(15.0), 0.0);
    }

    // time = length / speed + quarter turns x turn_s, whatever the path's shape.
    void pathTimeIsTravelPlusTurns_data() {
        QTest::addColumn<std::vector<Waypoint>>("waypoints");
        QTest::addColumn<double>("length");
        QTest::addColumn<double>("quarterTurns");
        QTest::newRow("square tour") << pathOf({{10, 10}, {30, 10}, {30, 30}, {10, 30}, {10, 10}}) << 80.0
                                     << 3.0;
        QTest::newRow("straight with a middle point")
            << pathOf({{10, 10}, {20, 10}, {40, 10}}) << 30.0 << 0.0;
        QTest::newRow("U-turn counts two quarters") << pathOf({{10, 10}, {30, 10}, {10, 10}}) << 40.0 << 2.0;
        QTest::newRow("45-degree bend counts half")
            << pathOf({{10, 10}, {20, 10}, {30, 20}}) << 10.0 + std::hypot(10.0, 10.0) << 0.5;
        QTest::newRow("repeated point turns once")
            << pathOf({{10, 10}, {20, 10}, {20, 10}, {20, 30}}) << 30.0 << 1.0;
        QTest::newRow("boustrophedon")
            << pathOf({{10, 10}, {50, 10}, {50, 20}, {10, 20}, {10, 30}, {50, 30}}) << 140.0 << 4.0;
    }
    void pathTimeIsTravelPlusTurns() {
        QFETCH(std::vector<Waypoint>, waypoints);
        QFETCH(double, length);
        QFETCH(double, quarterTurns);
        const double turnSeconds = 2.5;
        const CellGraph graph = oneCell(turnSeconds);
        CoveragePath path;
        path.waypoints = waypoints;
        path.closed = false;
        measurePath(path, graph);
        QCOMPARE(path.lengthMetres, length);
        QCOMPARE(path.turnSeconds, quarterTurns * turnSeconds);
        QCOMPARE(path.timeSeconds, length / 2.0 + quarterTurns * turnSeconds);
        QCOMPARE(cumulativeSeconds(path, graph).back(), path.timeSeconds);
        // With free turns the same path takes its travel time only.
        measurePath(path, oneCell(0.0));
        QCOMPARE(path.timeSeconds, length / 2.0);
        QCOMPARE(path.turnSeconds, 0.0);
    }

    // The turn is paid at the corner: points after it are reached that much later, points before it not.
    void cumulativeTimesPayTheTurnAtTheCorner() {
        CoveragePath path;
        path.waypoints = pathOf({{10, 10}, {30, 10}, {30, 30}});
        const CellGraph graph = oneCell(4.0);
        const PathSeconds seconds = pathSeconds(path.waypoints, graph);
        const std::vector<double> reached = cumulativeSeconds(path, graph);
        QCOMPARE(reached[0], 0.0);
        QCOMPARE(reached[1], 10.0);
        QCOMPARE(reached[2], 24.0);
        QCOMPARE(seconds.total, 24.0);
        QCOMPARE(seconds.turning, 4.0);
    }

    // Times asked at some waypoints only are those of every waypoint's, pauses before each included.
    void cumulativeTimesAtSomeWaypointsAreTheSame() {
        CoveragePath path;
        path.waypoints = pathOf({{10, 10}, {30, 10}, {30, 30}, {30, 50}, {10, 50}, {10, 30}});
        path.pauses = {{1, 7.0}, {3, 0.5}, {3, 2.0}};
        const CellGraph graph = oneCell(4.0);
        const std::vector<double> every = cumulativeSeconds(path, graph);
        const std::vector<std::size_t> indices{0, 1, 2, 3, 5};
        const std::vector<double> some = cumulativeSecondsAt(path, graph, indices);
        QCOMPARE(some.size(), indices.size());
        for (std::size_t k = 0; k < indices.size(); ++k)
            QCOMPARE(some[k], every[indices[k]]);
        QCOMPARE(some[1], 10.0);              // the pause at waypoint 1 delays only what comes after it
        QCOMPARE(some[2], 10.0 + 14.0 + 7.0); // the corner's 4 s, 10 m at 2 m/s and that pause
        QVERIFY(cumulativeSecondsAt(path, graph, {}).empty());
    }

    // A sortie that begins at a corner pays the turn there: sorties laid end to end take the path's time,
    // each the difference of the cumulative times at its ends.
    void sortiesPayTheTurnWhereTheyBegin() {
        CoveragePath path;
        path.waypoints = pathOf({{10, 10}, {30, 10}, {30, 30}, {30, 50}, {10, 50}, {10, 30}});
        const CellGraph graph = oneCell(4.0);
        const std::vector<double> reached = cumulativeSeconds(path, graph);
        const std::vector<Sortie> sorties{{0, 1}, {1, 3}, {3, 5}};
        double total = 0.0;
        for (const Sortie& sortie : sorties) {
            const double seconds = sortieSeconds(path, sortie, graph);
            QCOMPARE(seconds, reached[sortie.lastWaypoint] - reached[sortie.firstWaypoint]);
            total += seconds;
        }
        // 100 m at 2 m/s and three corners of 4 s: the one at (30, 10) opens the second sortie.
        QCOMPARE(sortieSeconds(path, sorties[1], graph), 24.0);
        QCOMPARE(total, pathSeconds(path.waypoints, graph).total);
        QCOMPARE(total, 62.0);
        QCOMPARE(longestSortieSeconds(path, sorties, graph), 28.0); // two corners in the last
    }

    void pointsInNoCellTurnForFree() {
        const std::vector<Waypoint> waypoints = pathOf({{10, 10}, {30, 10}, {30, 30}}, false);
        QCOMPARE(pathSeconds(waypoints, oneCell(4.0)).turning, 0.0);
    }

    void turnSecondsParameterTakesAuto() {
        const ParameterSpec spec = TurnTimeModel::turnSecondsParameter();
        QVERIFY(spec.isAutomatic(spec.defaultValue));
        std::string error;
        const auto automatic = spec.parse("Auto", &error);
        QVERIFY(automatic.has_value());
        QVERIFY(spec.isAutomatic(*automatic));
        QCOMPARE(spec.format(*automatic), std::string("auto"));
        const auto fixed = spec.parse("2.5", &error);
        QVERIFY(fixed.has_value());
        QCOMPARE(std::get<double>(*fixed), 2.5);
        QCOMPARE(spec.format(*fixed), std::string("2.5"));
        QVERIFY(!spec.parse("-1", &error).has_value()); // a number is a number, never the automatic value
        QVERIFY(!spec.parse("-0.5", &error).has_value());
        QCOMPARE(error, std::string("expected auto or a number from 0 to 600 s, got -0.5"));
        QVERIFY(!spec.parse("fast", &error).has_value());
        QVERIFY(spec.problemWith(ParameterValue(-2.0)).has_value());
        QVERIFY(spec.problemWith(ParameterValue(-1)).has_value());
        const ParameterValues values = [] {
            ParameterValues given;
            given.set("turn_s", 3.0);
            given.set("turn_acceleration", 2.0);
            return given;
        }();
        QCOMPARE(TurnTimeModel::from(values).secondsPer90Degrees(10.0), 3.0);
        QVERIFY(TurnTimeModel::from({}).fixedSecondsPer90Degrees < 0.0);
    }

    // Every planner declares the turn parameters, so the command line, missions and the panel offer them.
    void everyPlannerDeclaresTheTurnParameters() {
        for (const PlannerDescription& planner : plannerDescriptions()) {
            QVERIFY2(findParameter(planner.parameters, "turn_s") != nullptr, planner.name.c_str());
            QVERIFY2(findParameter(planner.parameters, "turn_acceleration") != nullptr, planner.name.c_str());
        }
    }

    // At turn_s 0 a plan is timed as travel alone: cells cost their travel, paths take length / speed and
    // the bound is the cells' travel over the robots. With a turn time each of them counts turns.
    void zeroTurnTimeKeepsTravelTimes() {
        PlanningProblem problem = test::uniformProblem(24, 16, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 2, 2), test::pixelCentre(problem.grid, 20, 13)};
        const Plan free = planned(problem, 0.0);
        QVERIFY(test::checkAllInvariants(problem, free).empty());
        double travel = 0.0;
        for (const Cell& cell : free.cells.cells()) {
            QCOMPARE(cell.coverSeconds(), cell.travelSeconds());
            travel += cell.travelSeconds();
        }
        for (const CoveragePath& path : free.paths) {
            QCOMPARE(path.turnSeconds, 0.0);
            QVERIFY(path.turns > 0);
            QCOMPARE(path.timeSeconds, path.lengthMetres / 1.0); // the uniform map's speed is 1 m/s
        }
        QCOMPARE(free.metrics.lowerBoundSeconds, travel / 2.0);

        const Plan turning = planned(problem, 3.0);
        const auto violations = test::checkAllInvariants(problem, turning);
        QVERIFY2(violations.empty(), test::describe(violations).c_str());
        double turnSeconds = 0.0;
        for (const CoveragePath& path : turning.paths) {
            // Grid paths turn by quarter turns only.
            QCOMPARE(path.turnSeconds, 3.0 * path.turns);
            QCOMPARE(path.timeSeconds, path.lengthMetres / 1.0 + 3.0 * path.turns);
            turnSeconds += path.turnSeconds;
        }
        for (const Cell& cell : turning.cells.cells())
            QCOMPARE(cell.coverSeconds(), cell.travelSeconds() + double(cell.expectedTurnsPerSubCell) *
                                                                     cell.freeSubCellCount() * 3.0);
        QCOMPARE(turning.metrics.lowerBoundSeconds, (travel + turnSeconds) / 2.0);
        QVERIFY(turning.metrics.ratio >= 1.0);
    }

    // Each region's cells take the turns per sub-cell its robot's path made; cells of no region keep theirs.
    void calibrationGivesEachRegionItsPathsTurnRate() {
        std::vector<Cell> cells(3);
        for (Cell& cell : cells) {
            cell.speedMetresPerSecond = 1.0;
            cell.turnSecondsPer90Degrees = 2.0F;
        }
        cells[1].freeSubCells = 0b0011; // two free sub-cells
        CellGraph graph = threeCellRow(cells);
        RegionAllocation regions;
        regions.robotOfCell = {0, 0, -1};
        regions.startCell = {0};
        const std::vector<double> turning{9.0}; // 4.5 quarter turns over 6 sub-cells priced 2 s each
        QVERIFY(calibrateTurnRates(graph, regions, turning));
        QCOMPARE(graph.cell(0).expectedTurnsPerSubCell, 0.75F);
        QCOMPARE(graph.cell(1).expectedTurnsPerSubCell, 0.75F);
        QCOMPARE(graph.cell(2).expectedTurnsPerSubCell, 0.2F);
        QCOMPARE(graph.cell(1).coverSeconds(), 10.0 + 0.75 * 2 * 2.0);
        // Free turns leave nothing to calibrate.
        graph.applyTurnTime(TurnTimeModel{0.0, 1.0});
        QVERIFY(!calibrateTurnRates(graph, regions, turning));
        QCOMPARE(graph.cell(0).expectedTurnsPerSubCell, 0.75F);
    }

    // A graph keeps its turn figures beside its cells: given cell by cell, or worked out from each cell's
    // speed by a model; a copy priced at other speeds keeps the turn times of the speeds before.
    void turnFiguresStayWithTheirCells() {
        std::vector<Cell> cells(3);
        for (std::size_t column = 0; column < 3; ++column)
            cells[column].speedMetresPerSecond = 1.5F + static_cast<float>(column);
        cells[1].turnSecondsPer90Degrees = 2.0F;
        cells[2].expectedTurnsPerSubCell = 0.5F;
        CellGraph graph = threeCellRow(cells);
        QCOMPARE(graph.cell(0).turnSecondsPer90Degrees, 0.0F);
        QCOMPARE(graph.cell(1).turnSecondsPer90Degrees, 2.0F);
        QCOMPARE(graph.turnSeconds(1), 2.0F);
        QCOMPARE(graph.cell(0).expectedTurnsPerSubCell, defaultExpectedTurnsPerSubCell);
        QCOMPARE(graph.cell(2).expectedTurnsPerSubCell, 0.5F);

        graph.applyTurnTime(TurnTimeModel{automaticParameterValue, 2.0});
        for (int id = 0; id < 3; ++id)
            QCOMPARE(graph.cell(id).turnSecondsPer90Degrees, (1.5F + static_cast<float>(id)) / 2.0F);
        graph.setExpectedTurns({0.25F});
        QCOMPARE(graph.cell(0).expectedTurnsPerSubCell, 0.25F);
        QCOMPARE(graph.cell(1).expectedTurnsPerSubCell, defaultExpectedTurnsPerSubCell);
        QCOMPARE(graph.cell(2).expectedTurnsPerSubCell, 0.5F);

        std::vector<CellRecord> slower = graph.records();
        for (CellRecord& record : slower)
            record.speedMetresPerSecond /= 4.0F;
        const CellGraph priced(graph, std::move(slower));
        for (int id = 0; id < 3; ++id) {
            QCOMPARE(priced.cell(id).speedMetresPerSecond, graph.cell(id).speedMetresPerSecond / 4.0F);
            QCOMPARE(priced.cell(id).turnSecondsPer90Degrees, graph.cell(id).turnSecondsPer90Degrees);
            QCOMPARE(priced.cell(id).expectedTurnsPerSubCell, graph.cell(id).expectedTurnsPerSubCell);
        }
        // The same speeds keep following the model.
        const CellGraph same(graph, graph.records());
        QVERIFY(same.turnFigures().followSpeeds());
        QVERIFY(!priced.turnFigures().followSpeeds());

        CellGraph apart(graph.frame(), graph.records(), NeighbourTopology({0, 0, 0, 0}, {}));
        QCOMPARE(apart.cell(2).turnSecondsPer90Degrees, 0.0F);
        apart.setTurnFigures(graph.turnFigures());
        QCOMPARE(apart.cell(2).turnSecondsPer90Degrees, 1.75F);
        QCOMPARE(apart.cell(2).expectedTurnsPerSubCell, 0.5F);
    }

    // The automatic turn time follows the land cover's speed: a turn on a fast class costs more.
    void automaticTurnTimeFollowsTheCellsSpeed() {
        const PlanningProblem problem = test::drawnProblem(
            {"........mmmmmmmm", "........mmmmmmmm", "........mmmmmmmm", "........mmmmmmmm"}, {{0.5, 0.5}});
        const Plan plan = planned(problem, automaticParameterValue);
        bool sawGrass = false;
        bool sawMud = false;
        for (const Cell& cell : plan.cells.cells()) {
            QCOMPARE(double(cell.turnSecondsPer90Degrees), cell.speedMetresPerSecond / 1.0);
            sawGrass = sawGrass || cell.speedMetresPerSecond == 1.0;
            sawMud = sawMud || cell.speedMetresPerSecond == 0.5;
        }
        QVERIFY(sawGrass && sawMud);
        QVERIFY(test::checkAllInvariants(problem, plan).empty());
    }
};

QTEST_GUILESS_MAIN(TurnTimeTest)
#include "test_turn_time.moc"
