// Steps between cells of different sizes: what a side of a large cell costs the walk with which of its
// smaller neighbours joined, what the measured path spends on them, the turn-minimising tree weighing
// them, and candidate walks timed as paths are.
#include "core/coverage/CellIndexScope.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/RegionAdjacency.hpp"
#include "core/coverage/SizeChangeConnectors.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/coverage/TurnMinimisingTree.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>

using namespace mcpp;

namespace {

// A 20 m cell (id 0, x 0-20, y 0-20) and two 10 m cells on its east side: id 1 south (y 0-10), id 2 north
// (y 10-20). Speeds: the large cell's `largeSpeed`, the small ones' `smallSpeed`; turns cost 1 s.
CellGraph largeCellAndTwoHalves(double largeSpeed, double smallSpeed) {
    GridFrame frame;
    frame.originX = 0.0;
    frame.originY = 20.0;
    frame.bottomCellSize = 10.0;
    frame.columns = 3;
    frame.rows = 2;
    frame.levels = 2;
    Cell large;
    large.span = 2;
    large.size = 20.0;
    large.speedMetresPerSecond = largeSpeed;
    large.turnSecondsPer90Degrees = 1.0F;
    large.passableAreaSquareMetres = 400.0;
    Cell south = large;
    south.column = 2;
    south.row = 1;
    south.span = 1;
    south.level = 2;
    south.minX = 20.0;
    south.size = 10.0;
    south.speedMetresPerSecond = smallSpeed;
    south.passableAreaSquareMetres = 100.0;
    Cell north = south;
    north.row = 0;
    north.minY = 10.0;
    return CellGraph(frame, {large, south, north}, NeighbourTopology({0, 2, 4, 6}, {1, 2, 0, 2, 0, 1}));
}

// A region's adjacency and connector model, its cells indexed for as long as it lives.
struct RegionConnectors {
    RegionConnectors(const CellGraph& graph, std::vector<int> regionCells)
        : cells(std::move(regionCells)), index(graph.size(), -1), local(index, cells),
          adjacency(graph, cells, local), connectors(graph, cells, adjacency) {}

    std::vector<int> cells;
    std::vector<int> index;
    CellIndexScope local;
    RegionAdjacency adjacency;
    SizeChangeConnectors connectors;
};

// The region's edge joining two of its nodes.
int edgeBetween(const RegionAdjacency& adjacency, int a, int b) {
    const auto& edges = adjacency.edges();
    for (std::size_t edge = 0; edge < edges.size(); ++edge)
        if ((edges[edge].first == a && edges[edge].second == b) ||
            (edges[edge].first == b && edges[edge].second == a))
            return static_cast<int>(edge);
    return -1;
}

// Going north along the large cell's east side: from its south-east sub-cell (15, 5) to its north-east one
// (15, 15); the small cells are entered at their south-west sub-cell and left from their north-west one.
const double shortStep = std::hypot(7.5, 2.5);    // to the sub-cell beside the corner
const double diagonalStep = std::hypot(7.5, 7.5); // to the sub-cell across the side

// A step between the large cell (2 m/s) and a small one (1 m/s), half at each speed, less the quarter of
// each cell's side their travel counts: 5 m at 2 m/s and 2.5 m at 1 m/s.
double beyondTravel(double step) {
    return step / 2.0 / 2.0 + step / 2.0 / 1.0 - 5.0 / 2.0 - 2.5 / 1.0;
}

// A random map of three fields of view (5, 10 and 20 m), 48 x 40 pixels, three robots.
test::RandomMapSpec multiSizeSpec(int seed) {
    test::RandomMapSpec spec;
    spec.columns = 48;
    spec.rows = 40;
    spec.seed = static_cast<unsigned>(seed);
    spec.landCovers = 3;
    spec.obstacleFraction = 0.04;
    spec.robots = 3;
    return spec;
}

std::vector<int> cellsOf(const Plan& plan, int robot) {
    return cellsByRobot(plan.regions)[static_cast<std::size_t>(robot)];
}

// sideSeconds over every side of every cell of a tree.
double sidesOf(const CellGraph& graph, const SpanningTree& tree) {
    std::vector<int> cells;
    for (int node = 0; node < static_cast<int>(tree.size()); ++node)
        cells.push_back(tree.cellOf(node));
    const RegionConnectors region(graph, cells);
    const RegionAdjacency& adjacency = region.adjacency;
    const SizeChangeConnectors& connectors = region.connectors;
    std::vector<char> inTree(adjacency.edges().size(), 0);
    for (std::size_t edge = 0; edge < inTree.size(); ++edge) {
        const auto& e = adjacency.edges()[edge];
        inTree[edge] = tree.parent(e.first) == e.second || tree.parent(e.second) == e.first ? 1 : 0;
    }
    double seconds = 0.0;
    for (int node = 0; node < static_cast<int>(cells.size()); ++node)
        for (const CellSide side : {CellSide::East, CellSide::North, CellSide::West, CellSide::South})
            seconds += connectors.sideSeconds(node, side, inTree);
    return seconds;
}

} // namespace

class SizeChangeConnectorsTest : public QObject {
    Q_OBJECT

  private slots:
    // With one of the two halves joined the way back to the large cell runs across its side; with both,
    // each step leans by a quarter of the small cell only.
    void aSideCostsWhatItsJoinedNeighboursMakeTheWalkSlant() {
        const CellGraph graph = largeCellAndTwoHalves(2.0, 1.0);
        const RegionConnectors region(graph, {0, 1, 2});
        const RegionAdjacency& adjacency = region.adjacency;
        const SizeChangeConnectors& connectors = region.connectors;
        const int toSouth = edgeBetween(adjacency, 0, 1);
        const int toNorth = edgeBetween(adjacency, 0, 2);
        const int between = edgeBetween(adjacency, 1, 2);
        QVERIFY(toSouth >= 0 && toNorth >= 0 && between >= 0);
        QCOMPARE(connectors.largerEnd(toSouth), 0);
        QCOMPARE(connectors.largerEnd(toNorth), 0);
        QCOMPARE(connectors.largerEnd(between), -1);

        std::vector<char> inTree(adjacency.edges().size(), 0);
        QCOMPARE(connectors.sideSeconds(0, CellSide::East, inTree), 0.0);
        inTree[static_cast<std::size_t>(toSouth)] = 1;
        const double oneJoined = beyondTravel(shortStep) + beyondTravel(diagonalStep);
        QVERIFY(std::abs(connectors.sideSeconds(0, CellSide::East, inTree) - oneJoined) < 1e-9);
        inTree[static_cast<std::size_t>(toSouth)] = 0;
        inTree[static_cast<std::size_t>(toNorth)] = 1;
        QVERIFY(std::abs(connectors.sideSeconds(0, CellSide::East, inTree) - oneJoined) < 1e-9);
        const double change = connectors.changeOnToggle(toSouth, inTree);
        QVERIFY(std::abs(change - (2.0 * beyondTravel(shortStep) - oneJoined)) < 1e-9);
        QCOMPARE(inTree[static_cast<std::size_t>(toSouth)], char(0)); // left as it was
        QCOMPARE(connectors.sideSeconds(0, CellSide::North, inTree), 0.0);
        QCOMPARE(connectors.turnSeconds(0), 1.0);
    }

    // Both trees turn as often by the count of sides, but one walks back across the large cell's side.
    void theTreeJoinsBothHalvesWhereStepsBetweenSizesCount() {
        const CellGraph graph = largeCellAndTwoHalves(1.0, 1.0);
        const RegionConnectors region(graph, {0, 1, 2});
        const RegionAdjacency& adjacency = region.adjacency;
        const SizeChangeConnectors& connectors = region.connectors;
        const auto joinsBoth = [](const std::vector<std::pair<int, int>>& edges) {
            int large = 0;
            for (const auto& [a, b] : edges)
                large += a == 0 || b == 0 ? 1 : 0;
            return large == 2;
        };
        const auto weighed = TurnMinimisingTree(adjacency, {}, &connectors).edges();
        QCOMPARE(weighed.size(), std::size_t(2));
        QVERIFY(joinsBoth(weighed));
        // By turns alone the small cells' straight run is kept and the large cell hangs from one end.
        QVERIFY(!joinsBoth(TurnMinimisingTree(adjacency, {}).edges()));
    }

    // Measured on a hand-made path: into the south half, round it, and back to the large cell's north-east
    // sub-cell; each step timed half at each end's speed, less a quarter of each cell's side at its speed.
    void aPathSpendsOnStepsBetweenSizesWhatTheirTimeExceeds() {
        const CellGraph graph = largeCellAndTwoHalves(1.0, 2.0);
        const auto at = [&](double x, double y, int cell) {
            const Cell& in = graph.cell(cell);
            return Waypoint{x, y, cell, in.speedMetresPerSecond};
        };
        CoveragePath path;
        path.closed = false;
        path.waypoints = {at(5, 15, 0),     at(5, 5, 0),      at(15, 5, 0),     at(22.5, 2.5, 1),
                          at(27.5, 2.5, 1), at(27.5, 7.5, 1), at(22.5, 7.5, 1), at(15, 15, 0)};
        measurePath(path, graph);
        const double into = std::hypot(7.5, 2.5) * (0.5 / 1.0 + 0.5 / 2.0) - 5.0 / 1.0 - 2.5 / 2.0;
        const double back = std::hypot(7.5, 7.5) * (0.5 / 2.0 + 0.5 / 1.0) - 2.5 / 2.0 - 5.0 / 1.0;
        QVERIFY(into < 0.0); // the faster small cell takes a little off the way in
        QVERIFY(std::abs(path.connectorSeconds - (into + back)) < 1e-9);
        QVERIFY(path.connectorSeconds < path.timeSeconds);

        // The same cells all of one speed: steps within a cell or between equal cells cost nothing extra.
        CoveragePath within;
        within.closed = false;
        within.waypoints = {at(22.5, 2.5, 1), at(27.5, 2.5, 1), at(27.5, 7.5, 1), at(27.5, 12.5, 2)};
        measurePath(within, graph);
        QCOMPARE(within.connectorSeconds, 0.0);
    }

    // A candidate walk's shape carries the time measurePath gives its path, so trees are chosen by it.
    void aWalkShapeIsTimedAsItsPath() {
        const Plan plan = MlctPlanner{}.plan(test::randomProblem(multiSizeSpec(3)), {});
        std::vector<int> scratch(plan.cells.size(), -1);
        TreeCircumnavigation walker(plan.cells);
        for (int robot = 0; robot < 3; ++robot) {
            const std::vector<int> cells = cellsOf(plan, robot);
            const SpanningTreeBuilder builder(plan.cells, scratch);
            const int startCell = plan.regions.startCell[static_cast<std::size_t>(robot)];
            const auto& first = plan.paths[static_cast<std::size_t>(robot)].waypoints.front();
            const MapPoint start{first.x + 0.3,
                                 first.y - 0.2}; // off the walk: the start is a point of its own
            for (int candidate = 0; candidate < 2 * builder.candidatesFor(cells); ++candidate) {
                const bool closed = candidate % 2 == 0; // a tour home and a walk that ends in the field
                const SpanningTree tree = builder.candidate(candidate / 2, cells, startCell);
                const PathShape shape = walker.walkShape(tree, start, closed);
                CoveragePath path = pathFromWalk(robot, start, walker.walk(tree, start, closed), closed);
                measurePath(path, plan.cells);
                QVERIFY(path.turnSeconds > 0.0);
                // Shape and measured path agree to rounding, in the path's whole time.
                const auto describe = [&](double fromShape, double measured, const char* what) {
                    return QString("robot %1, candidate %2 (%6): %3 s %4 against %5 s")
                        .arg(robot)
                        .arg(candidate / 2)
                        .arg(fromShape)
                        .arg(what)
                        .arg(measured)
                        .arg(closed ? "closed" : "open");
                };
                const double tolerance = 1e-9 * path.timeSeconds;
                QVERIFY2(std::abs(shape.seconds() - path.timeSeconds) < tolerance,
                         qPrintable(describe(shape.seconds(), path.timeSeconds, "in all")));
                QCOMPARE(shape.turns(), path.turns);
                QVERIFY2(std::abs(shape.turningSeconds() - path.turnSeconds) < tolerance,
                         qPrintable(describe(shape.turningSeconds(), path.turnSeconds, "turning")));
            }
        }
    }

    // On maps of three fields of view, wherever the walk needs no bridge, the sides' connector time added
    // up over the tree is what the measured walk spends on steps between sizes: the model and the walk
    // agree on every side (east, north, west and south) and both speeds of each step.
    void theSidesAddUpToTheWalksConnectorTime() {
        int compared = 0;
        for (int seed = 1; seed <= 4; ++seed) {
            const Plan plan = MlctPlanner{}.plan(test::randomProblem(multiSizeSpec(seed)), {});
            std::vector<int> scratch(plan.cells.size(), -1);
            TreeCircumnavigation walker(plan.cells);
            for (int robot = 0; robot < 3; ++robot) {
                const std::vector<int> cells = cellsOf(plan, robot);
                const int startCell = plan.regions.startCell[static_cast<std::size_t>(robot)];
                const SpanningTree tree =
                    SpanningTreeBuilder(plan.cells, scratch).fewestTurns(cells, startCell);
                const auto& first = plan.paths[static_cast<std::size_t>(robot)].waypoints.front();
                CoveragePath path = pathFromWalk(robot, {first.x, first.y},
                                                 walker.walk(tree, {first.x, first.y}, true), true);
                if (walker.bridgeVisits() > 0)
                    continue;
                measurePath(path, plan.cells);
                const double modelled = sidesOf(plan.cells, tree);
                QVERIFY2(std::abs(modelled - path.connectorSeconds) < 1e-6 * std::max(1.0, modelled),
                         qPrintable(QString("seed %1, robot %2: %3 s modelled, %4 s walked")
                                        .arg(seed)
                                        .arg(robot)
                                        .arg(modelled)
                                        .arg(path.connectorSeconds)));
                if (path.connectorSeconds != 0.0)
                    ++compared;
            }
        }
        QVERIFY(compared >= 4);
    }

    // No candidate walk is quicker than the one chosen (on these maps the turn-minimising tree's walk is
    // also the one that turns least, so turns alone would choose the same).
    void noCandidateIsQuickerThanTheChosenOne() {
        for (int seed = 1; seed <= 4; ++seed) {
            const Plan plan = MlctPlanner{}.plan(test::randomProblem(multiSizeSpec(seed)), {});
            std::vector<int> scratch(plan.cells.size(), -1);
            TreeCircumnavigation walker(plan.cells);
            const SpanningTreeCoverage coverage;
            for (int robot = 0; robot < 3; ++robot) {
                const std::vector<int> cells = cellsOf(plan, robot);
                const int startCell = plan.regions.startCell[static_cast<std::size_t>(robot)];
                const auto& first = plan.paths[static_cast<std::size_t>(robot)].waypoints.front();
                const MapPoint start{first.x, first.y};
                const PathShape best = coverage.bestTree(plan.cells, cells, startCell, start, scratch).second;
                QVERIFY(best.seconds() > 0.0);
                const SpanningTreeBuilder builder(plan.cells, scratch);
                QCOMPARE(builder.candidatesFor(cells), SpanningTreeBuilder::candidateCount);
                for (int candidate = 0; candidate < builder.candidatesFor(cells); ++candidate) {
                    const PathShape shape =
                        walker.walkShape(builder.candidate(candidate, cells, startCell), start, true);
                    QVERIFY(best.seconds() <= shape.seconds() * (1.0 + 1e-9));
                }
            }
        }
    }

    // On a map of three fields of view the paths step between sizes, each robot's figure is its path's,
    // and the lower bound counts them as it counts turns.
    void plansReportConnectorTimeAndTheBoundCountsIt() {
        const Plan plan = MlctPlanner{}.plan(test::randomProblem(test::multiCoverSpec(64, 4)), {});
        double connectors = 0.0;
        double turning = 0.0;
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot) {
            QCOMPARE(plan.metrics.robots[robot].connectorSeconds, plan.paths[robot].connectorSeconds);
            connectors += plan.paths[robot].connectorSeconds;
            turning += plan.paths[robot].turnSeconds;
        }
        QVERIFY(connectors > 0.0);
        double travel = 0.0;
        for (std::size_t cell = 0; cell < plan.cells.size(); ++cell)
            if (plan.regions.robotOfCell[cell] >= 0)
                travel += plan.cells.cell(static_cast<int>(cell)).travelSeconds();
        const double bound = (travel + turning + connectors) / static_cast<double>(plan.paths.size());
        QVERIFY(plan.metrics.confinedRobots.empty());
        QVERIFY(std::abs(plan.metrics.lowerBoundSeconds - bound) < 1e-9 * bound);
        QVERIFY(plan.metrics.ratio >= 1.0);
    }
};

QTEST_GUILESS_MAIN(SizeChangeConnectorsTest)
#include "test_size_change_connectors.moc"
