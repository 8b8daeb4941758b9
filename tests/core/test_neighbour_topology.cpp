#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
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
};

QTEST_APPLESS_MAIN(NeighbourTopologyTest)
#include "test_neighbour_topology.moc"
