#include "core/allocation/CellBlocks.hpp"
#include "core/allocation/CellFigures.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
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
