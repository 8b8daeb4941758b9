#include "core/allocation/CellBlocks.hpp"
#include "core/allocation/CellFigures.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "core/model/ParallelFor.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>
#include <map>
#include <set>
#include <utility>

using namespace mcpp;

namespace {

CellGraph quadTreeGraph(const PlanningProblem& problem) {
    const QuadTree tree = QuadTreeBuilder{}.build(problem.grid, problem.classes,
                                                  DecompositionOptions::from(problem.planner.parameters));
    return cellGraphOfQuadTree(tree, NeighbourTopologyBuilder{}.build(tree));
}

// Whether every block's cells are linked through cells of the block, the slow way.
bool blocksLinkedWithin(const CellGraph& graph, const std::vector<int>& blockOfCell) {
    std::map<int, std::ptrdiff_t> membersOf;
    for (const int block : blockOfCell)
        ++membersOf[block];
    for (std::size_t first = 0; first < graph.size(); ++first) {
        std::set<int> reached{static_cast<int>(first)};
        std::vector<int> queue{static_cast<int>(first)};
        for (std::size_t head = 0; head < queue.size(); ++head)
            for (int neighbour : graph.neighbours(queue[head]))
                if (blockOfCell[static_cast<std::size_t>(neighbour)] == blockOfCell[first] &&
                    reached.insert(neighbour).second)
                    queue.push_back(neighbour);
        if (static_cast<std::ptrdiff_t>(reached.size()) != membersOf[blockOfCell[first]])
            return false;
    }
    return true;
}

// Checks the blocks against what they say, worked out the slow way from every cell.
void checkBlocks(const CellGraph& graph, int side) {
    const CellBlocks blocks = groupIntoBlocks(graph, side);
    QCOMPARE(blocks.blockOfCell.size(), graph.size());
    const auto blockCount = blocks.figures.size();
    QCOMPARE(blocks.adjacency.cellCount(), blockCount);

    // Two cells share a block exactly when their north-west corners lie in the same square of the side.
    std::map<std::pair<int, int>, int> blockOfPlace;
    int nextNew = 0;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        const auto [entry, added] = blockOfPlace.try_emplace({cell.row / side, cell.column / side}, nextNew);
        if (added)
            ++nextNew; // numbered in the order of their first cell
        QCOMPARE(blocks.blockOfCell[id], entry->second);
    }
    QCOMPARE(static_cast<std::size_t>(nextNew), blockCount);

    const std::vector<CellFigures> cells = cellFiguresOf(graph);
    std::vector<CellFigures> sums(blockCount);
    std::set<std::pair<int, int>> touching;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const int block = blocks.blockOfCell[id];
        CellFigures& sum = sums[static_cast<std::size_t>(block)];
        sum.x += cells[id].x * cells[id].area;
        sum.y += cells[id].y * cells[id].area;
        sum.area += cells[id].area;
        sum.cost += cells[id].cost;
        for (int neighbour : graph.neighbours(static_cast<int>(id))) {
            const int other = blocks.blockOfCell[static_cast<std::size_t>(neighbour)];
            if (other != block)
                touching.insert({block, other});
        }
    }
    for (std::size_t block = 0; block < blockCount; ++block) {
        const CellFigures& figures = blocks.figures[block];
        const CellFigures& sum = sums[block];
        QVERIFY(std::abs(figures.area - sum.area) <= 1e-9 * sum.area);
        QVERIFY(std::abs(figures.cost - sum.cost) <= 1e-9 * sum.cost);
        QVERIFY(std::abs(figures.x - sum.x / sum.area) <= 1e-9 * std::abs(figures.x));
        QVERIFY(std::abs(figures.y - sum.y / sum.area) <= 1e-9 * std::abs(figures.y));
    }
    std::set<std::pair<int, int>> listed;
    for (std::size_t block = 0; block < blockCount; ++block) {
        const auto neighbours = blocks.adjacency.of(static_cast<int>(block));
        QVERIFY(std::is_sorted(neighbours.begin(), neighbours.end()));
        for (int other : neighbours)
            QVERIFY(listed.insert({static_cast<int>(block), other}).second); // each once
    }
    QCOMPARE(listed, touching);
    QCOMPARE(blocks.everyBlockConnected, blocksLinkedWithin(graph, blocks.blockOfCell));
}

} // namespace

class TestCellBlocks : public QObject {
    Q_OBJECT

  private slots:
    void blocksOfAGridWithObstacles() {
        const PlanningProblem problem = test::obstacleGridProblem(37, 3, 5);
        const CellGraph graph = test::cellPerPixelGraph(problem);
        QVERIFY(graph.size() > 900);
        for (int side : {1, 2, 4, 5})
            checkBlocks(graph, side);
    }

    void blocksOfAQuadTreeOfSeveralCellSizes() {
        test::RandomMapSpec spec;
        spec.columns = 64;
        spec.rows = 48;
        spec.landCovers = 3;
        spec.obstacleFraction = 0.05;
        spec.seed = 3;
        const CellGraph graph = quadTreeGraph(test::randomProblem(spec));
        QVERIFY(!graph.hasOneCellSize());
        for (int side : {2, 4, 8})
            checkBlocks(graph, side);
    }

    // Blocks cut off at the grid's edges are still whole; one obstacle pixel splitting a block is not.
    void blocksLinkedWithinThemselves() {
        std::vector<bool> blocked(37 * 37, false);
        const PlanningProblem open = test::uniformProblem(37, 37, 10.0, blocked, {});
        QVERIFY(groupIntoBlocks(test::cellPerPixelGraph(open), 4).everyBlockConnected);
        // A block's corner cell cut off by obstacles on its two inner sides.
        blocked[static_cast<std::size_t>(0 * 37 + 1)] = true;
        blocked[static_cast<std::size_t>(1 * 37 + 0)] = true;
        const PlanningProblem cut = test::uniformProblem(37, 37, 10.0, blocked, {});
        const CellGraph graph = test::cellPerPixelGraph(cut);
        QVERIFY(!groupIntoBlocks(graph, 4).everyBlockConnected);
        checkBlocks(graph, 4);
    }

    // More blocks than one thread takes at a time (2^15): the spans looked at side by side join into the
    // lists one thread makes, and a block cut in two in a later span is still found.
    void blocksOfALargeGridAcrossThreads() {
        constexpr int cells = 400; // 200 x 200 = 40 000 blocks of 2 x 2 cells
        std::vector<bool> blocked(static_cast<std::size_t>(cells * cells), false);
        // Block (row 190, column 100), number 38 100: its north-east and south-west cells are water, so
        // its other two meet at a corner only.
        blocked[static_cast<std::size_t>(380 * cells + 201)] = true;
        blocked[static_cast<std::size_t>(381 * cells + 200)] = true;
        const CellGraph graph =
            test::cellPerPixelGraph(test::uniformProblem(cells, cells, 10.0, blocked, {}));
        setWorkerThreads(1);
        const CellBlocks alone = groupIntoBlocks(graph, 2);
        setWorkerThreads(2);
        const CellBlocks sideBySide = groupIntoBlocks(graph, 2);
        setWorkerThreads(0);
        QCOMPARE(alone.figures.size(), std::size_t{40000});
        QVERIFY(!alone.everyBlockConnected);
        QVERIFY(!sideBySide.everyBlockConnected);
        QCOMPARE(sideBySide.blockOfCell, alone.blockOfCell);
        QCOMPARE(sideBySide.adjacency.offsets(), alone.adjacency.offsets());
        QCOMPARE(sideBySide.adjacency.neighbours(), alone.adjacency.neighbours());
        checkBlocks(graph, 2);
    }

    void blocksOfOneCellEachAreTheCells() {
        const PlanningProblem problem = test::obstacleGridProblem(12, 2, 9);
        const CellGraph graph = test::cellPerPixelGraph(problem);
        const CellBlocks blocks = groupIntoBlocks(graph, 1);
        QCOMPARE(blocks.figures.size(), graph.size());
        for (std::size_t id = 0; id < graph.size(); ++id) {
            QCOMPARE(blocks.blockOfCell[id], static_cast<int>(id));
            const auto cells = graph.neighbours(static_cast<int>(id));
            const auto linked = blocks.adjacency.of(static_cast<int>(id));
            QCOMPARE(std::set<int>(linked.begin(), linked.end()), std::set<int>(cells.begin(), cells.end()));
        }
    }
};

QTEST_GUILESS_MAIN(TestCellBlocks)
#include "test_cell_blocks.moc"
