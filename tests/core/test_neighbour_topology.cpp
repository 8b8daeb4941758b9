#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <random>
#include <set>

using namespace mcpp;

namespace {

// Two squares share a border of positive length: one's edge lies on the other's, with overlapping spans.
bool shareBorder(const QuadCell& a, const QuadCell& b) {
    const double tolerance = 1e-9;
    const double overlapX = std::min(a.maxX(), b.maxX()) - std::max(a.minX, b.minX);
    const double overlapY = std::min(a.maxY(), b.maxY()) - std::max(a.minY, b.minY);
    const bool touchX = std::abs(a.maxX() - b.minX) < tolerance || std::abs(b.maxX() - a.minX) < tolerance;
    const bool touchY = std::abs(a.maxY() - b.minY) < tolerance || std::abs(b.maxY() - a.minY) < tolerance;
    return (touchX && overlapY > tolerance) || (touchY && overlapX > tolerance);
}

// A map of one to four land covers and up to 19 % obstacles, without robots, drawn from the seed.
PlanningProblem randomMap(std::uint32_t seed, int columns, int rows) {
    test::RandomMapSpec spec;
    spec.columns = columns;
    spec.rows = rows;
    spec.landCovers = 1 + static_cast<int>(seed % 4);
    spec.obstacleFraction = 0.01 * (seed % 20);
    spec.seed = seed;
    spec.robots = 0;
    return test::randomProblem(spec);
}

} // namespace

class NeighbourTopologyTest : public QObject {
    Q_OBJECT
  private slots:
    void sameLevelGridHasFourNeighbours() {
        auto problem = test::uniformProblem(3, 3, 10.0, {}, {});
        const QuadTree tree = QuadTreeBuilder{}.build(problem.grid, problem.classes, {});
        const NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
        QCOMPARE(topology.cellCount(), std::size_t{9});
        QCOMPARE(topology.pairCount(), std::size_t{12});
        const MapPoint middle = test::pixelCentre(problem.grid, 1, 1);
        const int leaf = tree.leafAt(middle.x, middle.y);
        QVERIFY(leaf >= 0);
        const int centre = tree.cells[static_cast<std::size_t>(leaf)].activeIndex;
        QCOMPARE(topology.of(centre).size(), std::size_t{4});
    }

    // Against a brute-force geometric search on mixed-level trees with obstacles.
    void matchesBruteForceOnRandomMaps() {
        for (std::uint32_t seed = 1; seed <= 30; ++seed) {
            const auto problem =
                randomMap(seed, 24 + static_cast<int>(seed % 7), 20 + static_cast<int>(seed % 5));
            const QuadTree tree = QuadTreeBuilder{}.build(problem.grid, problem.classes, {});
            const NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
            for (std::size_t a = 0; a < tree.activeCount(); ++a) {
                std::set<int> expected;
                for (std::size_t b = 0; b < tree.activeCount(); ++b)
                    if (a != b &&
                        shareBorder(tree.active(static_cast<int>(a)), tree.active(static_cast<int>(b))))
                        expected.insert(static_cast<int>(b));
                const auto list = topology.of(static_cast<int>(a));
                const std::set<int> found(list.begin(), list.end());
                QVERIFY2(found == expected,
                         qPrintable(QString("seed %1 cell %2: %3 neighbours found, %4 expected")
                                        .arg(seed)
                                        .arg(a)
                                        .arg(found.size())
                                        .arg(expected.size())));
                QCOMPARE(list.size(), found.size());
            }
        }
    }

    // A graph keeps 32 bytes a cell and works each square out from the frame again: on mixed-level trees
    // the squares are those the quadtree made, bit for bit (walks compare points exactly), and the other
    // fields are those of the leaf.
    void cellsComeBackWithTheTreesSquares() {
        int deepest = 0;
        for (std::uint32_t seed = 1; seed <= 12; ++seed) {
            const auto problem =
                randomMap(seed, 30 + static_cast<int>(seed % 5), 26 + static_cast<int>(seed % 3));
            QuadTree tree = QuadTreeBuilder{}.build(problem.grid, problem.classes, {});
            std::vector<QuadCell> leaves;
            for (std::size_t active = 0; active < tree.activeCount(); ++active)
                leaves.push_back(tree.active(static_cast<int>(active)));
            NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
            const CellGraph graph = cellGraphOfQuadTree(std::move(tree), std::move(topology));
            QCOMPARE(graph.size(), leaves.size());
            for (std::size_t id = 0; id < graph.size(); ++id) {
                const Cell cell = graph.cell(static_cast<int>(id));
                const QuadCell& leaf = leaves[id];
                deepest = std::max(deepest, int{leaf.level});
                QVERIFY2(cell.minX == leaf.minX && cell.minY == leaf.minY && cell.size == leaf.size,
                         qPrintable(QString("seed %1 cell %2: (%3, %4, %5) against the tree's (%6, %7, %8)")
                                        .arg(seed)
                                        .arg(id)
                                        .arg(cell.minX, 0, 'g', 17)
                                        .arg(cell.minY, 0, 'g', 17)
                                        .arg(cell.size, 0, 'g', 17)
                                        .arg(leaf.minX, 0, 'g', 17)
                                        .arg(leaf.minY, 0, 'g', 17)
                                        .arg(leaf.size, 0, 'g', 17)));
                QCOMPARE(int{cell.level}, int{leaf.level});
                QCOMPARE(cell.classValue, leaf.classValue);
                QCOMPARE(cell.speedMetresPerSecond, static_cast<float>(leaf.speedMetresPerSecond));
                const Cell again = graph.cells()[id];
                QCOMPARE(again.minX, cell.minX);
                QCOMPARE(again.row, cell.row);
            }
        }
        QVERIFY(deepest >= 3); // children of children were worked out, not only top cells
    }

    // Squares are worked out level by level: a frame of more levels than a quadtree has is refused, not
    // shifted past the width of an int.
    void framesOfTooManyLevelsAreRefused() {
        GridFrame frame;
        frame.columns = 1;
        frame.rows = 1;
        frame.levels = mostQuadTreeLevels + 1;
        const std::vector<CellRecord> one(1);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellGraph(frame, one, NeighbourTopology({0, 0}, {})));
        frame.levels = mostQuadTreeLevels;
        QCOMPARE(CellGraph(frame, one, NeighbourTopology({0, 0}, {})).size(), std::size_t{1});
    }

    // The graph's point lookup, which keeps only cell ids per cell size, finds every cell of mixed-level
    // graphs from any of its sub-cell centres; a bottom cell that no cell covers (an obstacle) and points
    // beyond the grid find none.
    void everyCellIsFoundByItsPoints() {
        int spansSeen = 0;
        int holesSeen = 0;
        for (std::uint32_t seed = 1; seed <= 12; ++seed) {
            const auto problem =
                randomMap(seed, 30 + static_cast<int>(seed % 5), 26 + static_cast<int>(seed % 3));
            QuadTree tree = QuadTreeBuilder{}.build(problem.grid, problem.classes, {});
            NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
            const CellGraph graph = cellGraphOfQuadTree(std::move(tree), std::move(topology));
            std::set<int> spans;
            for (std::size_t id = 0; id < graph.size(); ++id) {
                const Cell& cell = graph.cell(static_cast<int>(id));
                spans.insert(cell.span);
                QCOMPARE(graph.cellAt({cell.centreX(), cell.centreY()}), static_cast<int>(id));
                for (const SubCell subCell : subCellsCounterClockwise)
                    QCOMPARE(graph.cellAt(cell.subCellCentre(subCell)), static_cast<int>(id));
            }
            spansSeen = std::max(spansSeen, static_cast<int>(spans.size()));
            const GridFrame& frame = graph.frame();
            // Every bottom cell of the grid, by its centre: its cell, or none where no cell covers it.
            std::vector<int> owner(static_cast<std::size_t>(frame.columns) * frame.rows, -1);
            for (std::size_t id = 0; id < graph.size(); ++id) {
                const Cell& cell = graph.cell(static_cast<int>(id));
                for (int row = cell.row; row < cell.row + cell.span; ++row)
                    for (int column = cell.column; column < cell.column + cell.span; ++column)
                        owner[static_cast<std::size_t>(row) * frame.columns + column] = static_cast<int>(id);
            }
            for (int row = 0; row < frame.rows; ++row)
                for (int column = 0; column < frame.columns; ++column) {
                    const int expected = owner[static_cast<std::size_t>(row) * frame.columns + column];
                    holesSeen += expected < 0 ? 1 : 0;
                    const MapPoint centre{frame.originX + (column + 0.5) * frame.bottomCellSize,
                                          frame.originY - (row + 0.5) * frame.bottomCellSize};
                    QCOMPARE(graph.cellAt(centre), expected);
                }
            const double east = frame.originX + frame.columns * frame.bottomCellSize;
            const double south = frame.originY - frame.rows * frame.bottomCellSize;
            QCOMPARE(graph.cellAt({east + 1.0, frame.originY - 1.0}), -1);
            QCOMPARE(graph.cellAt({frame.originX + 1.0, south - 1.0}), -1);
            QCOMPARE(graph.cellAt({frame.originX - 1.0, frame.originY - 1.0}), -1);
            QCOMPARE(graph.cellAt({frame.originX + 1.0, frame.originY + 1.0}), -1);
            QCOMPARE(graph.cellAt({std::nan(""), frame.originY - 1.0}), -1);
        }
        QVERIFY(spansSeen >= 3); // cells of three sizes at least, so every size's list is searched
        QVERIFY(holesSeen > 0);  // and searches that find nothing
    }

    // A grid's graph keeps no neighbour lists and finds each cell's neighbours on the grid: the same ids,
    // in the same order, as the lists of the one-level quadtree's builder, on grids with holes of every
    // shape; every place finds its cell or none; a graph of the same cells with other figures keeps them.
    void aGridFindsTheNeighboursItsListsWouldHold() {
        std::size_t holes = 0;
        for (std::uint32_t seed = 1; seed <= 8; ++seed) {
            std::mt19937 random(seed);
            OneLevelQuadTree grid;
            grid.frame.originX = 600000.0;
            grid.frame.originY = 5200000.0;
            grid.frame.bottomCellSize = 20.0;
            grid.frame.columns = 61 + static_cast<int>(seed); // rows of 62-69 places: words end mid-row
            grid.frame.rows = 17 + static_cast<int>(seed % 4);
            grid.frame.levels = 1;
            for (int row = 0; row < grid.frame.rows; ++row)
                for (int column = 0; column < grid.frame.columns; ++column) {
                    if (random() % (2 + seed % 5) == 0) {
                        ++holes;
                        continue;
                    }
                    CellRecord cell;
                    cell.column = column;
                    cell.row = row;
                    cell.classValue = static_cast<int>(random() % 3);
                    cell.speedMetresPerSecond = 1.0F;
                    grid.cells.push_back(cell);
                }
            const NeighbourTopology lists = NeighbourTopologyBuilder{}.build(grid);
            const CellGraph graph = CellGraph::ofGrid(grid.frame, grid.cells);
            QVERIFY(graph.hasOneCellSize());
            QCOMPARE(graph.neighbourLists().offsets(), lists.offsets());
            QCOMPARE(graph.neighbourLists().neighbours(), lists.neighbours());
            std::vector<CellRecord> faster = grid.cells;
            for (CellRecord& cell : faster)
                cell.speedMetresPerSecond = 3.0F;
            const CellGraph repriced(graph, faster);
            for (std::size_t id = 0; id < graph.size(); ++id) {
                const auto expected = lists.of(static_cast<int>(id));
                const NeighbourList found = graph.neighbours(static_cast<int>(id));
                QVERIFY(std::equal(found.begin(), found.end(), expected.begin(), expected.end()));
                const NeighbourList kept = repriced.neighbours(static_cast<int>(id));
                QVERIFY(std::equal(kept.begin(), kept.end(), expected.begin(), expected.end()));
                for (const int neighbour : expected)
                    QVERIFY(graph.areNeighbours(static_cast<int>(id), neighbour));
                QVERIFY(!graph.areNeighbours(static_cast<int>(id), static_cast<int>(id)));
                QCOMPARE(repriced.record(static_cast<int>(id)).speedMetresPerSecond, 3.0F);
            }
            std::vector<int> owner(static_cast<std::size_t>(grid.frame.columns) * grid.frame.rows, -1);
            for (std::size_t id = 0; id < grid.cells.size(); ++id)
                owner[static_cast<std::size_t>(grid.cells[id].row) * grid.frame.columns +
                      grid.cells[id].column] = static_cast<int>(id);
            for (int row = 0; row < grid.frame.rows; ++row)
                for (int column = 0; column < grid.frame.columns; ++column) {
                    const MapPoint centre{grid.frame.originX + (column + 0.5) * grid.frame.bottomCellSize,
                                          grid.frame.originY - (row + 0.5) * grid.frame.bottomCellSize};
                    QCOMPARE(graph.cellAt(centre),
                             owner[static_cast<std::size_t>(row) * grid.frame.columns + column]);
                }
            QCOMPARE(graph.cellAt({grid.frame.originX - 1.0, grid.frame.originY - 1.0}), -1);
            QCOMPARE(graph.cellAt({grid.frame.originX + 1.0, grid.frame.originY + 1.0}), -1);
        }
        QVERIFY(holes > 100);
    }

    // Only a grid's cells listed row by row, each once, make a grid's graph.
    void aGridOfCellsOutOfOrderIsRefused() {
        GridFrame frame;
        frame.columns = 4;
        frame.rows = 3;
        frame.levels = 1;
        CellRecord first;
        first.column = 2;
        first.row = 1;
        CellRecord second = first;
        second.column = 1; // west of the first, listed after it
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellGraph::ofGrid(frame, {first, second}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellGraph::ofGrid(frame, {first, first}));
        CellRecord outside = first;
        outside.column = 4;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellGraph::ofGrid(frame, {outside}));
        CellRecord larger = first;
        larger.span = 2;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellGraph::ofGrid(frame, {larger}));
        second.column = 3;
        QCOMPARE(CellGraph::ofGrid(frame, {first, second}).neighbours(0).size(), std::size_t{1});
        frame.levels = 2;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CellGraph::ofGrid(frame, {first, second}));
    }

    // A large grid's graph finds neighbours on the grid instead of keeping lists: the regions and paths
    // planned on it are those planned on the lists, point for point.
    void regionsAndPathsAreTheSameWithoutLists() {
        for (std::uint32_t seed = 1; seed <= 3; ++seed) {
            test::RandomMapSpec spec;
            spec.columns = 64;
            spec.rows = 48;
            spec.obstacleFraction = 0.12;
            spec.robots = 3 + static_cast<int>(seed);
            spec.seed = seed;
            const PlanningProblem problem = test::randomProblem(spec);
            const auto graphOf = [&](std::size_t fewestCellsWithoutLists) {
                return cellGraphOfLeaves(QuadTreeBuilder{}.buildLeaves(problem.grid, problem.classes, {}),
                                         fewestCellsWithoutLists);
            };
            const CellGraph withLists = graphOf(fewestCellsForGridNeighbours);
            const CellGraph withoutLists = graphOf(0);
            QVERIFY(withLists.hasOneCellSize());
            QVERIFY(withLists.size() > 1000);
            QCOMPARE(withoutLists.neighbourLists().neighbours(), withLists.neighbourLists().neighbours());
            std::vector<int> startCells;
            for (const MapPoint& start : problem.starts)
                startCells.push_back(withLists.cellAt(start));
            const AzimuthTrendAllocator allocator;
            const RegionAllocation regions = allocator.allocate(withLists, startCells, {});
            QCOMPARE(allocator.allocate(withoutLists, startCells, {}).robotOfCell, regions.robotOfCell);
            const SpanningTreeCoverage coverage;
            const auto paths = coverage.plan(withLists, regions, problem.starts, {});
            const auto pathsWithoutLists = coverage.plan(withoutLists, regions, problem.starts, {});
            QCOMPARE(pathsWithoutLists.size(), paths.size());
            for (std::size_t robot = 0; robot < paths.size(); ++robot) {
                QVERIFY(paths[robot].waypoints.size() > 10);
                QCOMPARE(pathsWithoutLists[robot].waypoints.size(), paths[robot].waypoints.size());
                for (std::size_t at = 0; at < paths[robot].waypoints.size(); ++at) {
                    QCOMPARE(pathsWithoutLists[robot].waypoints[at].x, paths[robot].waypoints[at].x);
                    QCOMPARE(pathsWithoutLists[robot].waypoints[at].y, paths[robot].waypoints[at].y);
                }
                QCOMPARE(pathsWithoutLists[robot].turns, paths[robot].turns);
            }
        }
    }
};

QTEST_APPLESS_MAIN(NeighbourTopologyTest)
#include "test_neighbour_topology.moc"
