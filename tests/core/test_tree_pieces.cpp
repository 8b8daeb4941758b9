#include "core/allocation/TreePieces.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "core/model/PlanningError.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <atomic>
#include <set>
#include <utility>

using namespace mcpp;

namespace {

// Cells reached from `first` through cells of the same piece, the slow way.
std::size_t reachedWithinPiece(const CellGraph& graph, const std::vector<int>& pieceOfCell, int first) {
    std::set<int> reached{first};
    std::vector<int> queue{first};
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int neighbour : graph.neighbours(queue[head]))
            if (pieceOfCell[static_cast<std::size_t>(neighbour)] ==
                    pieceOfCell[static_cast<std::size_t>(first)] &&
                reached.insert(neighbour).second)
                queue.push_back(neighbour);
    return reached.size();
}

// The pieces partition the map into linked pieces that touch as the adjacency says, with their costs
// summed, and no piece holds two starts.
void checkPieces(const CellGraph& graph, const CellBlocks& pieces, const std::vector<int>& starts) {
    QCOMPARE(pieces.blockOfCell.size(), graph.size());
    const std::size_t count = pieces.figures.size();
    QCOMPARE(pieces.adjacency.cellCount(), count);
    std::vector<std::size_t> members(count, 0);
    std::vector<double> costs(count, 0.0);
    std::set<std::pair<int, int>> touching;
    for (std::size_t cell = 0; cell < graph.size(); ++cell) {
        const int piece = pieces.blockOfCell[cell];
        QVERIFY(piece >= 0 && static_cast<std::size_t>(piece) < count);
        ++members[static_cast<std::size_t>(piece)];
        costs[static_cast<std::size_t>(piece)] += graph.cell(static_cast<int>(cell)).coverSeconds();
        for (int neighbour : graph.neighbours(static_cast<int>(cell)))
            if (pieces.blockOfCell[static_cast<std::size_t>(neighbour)] != piece)
                touching.insert({piece, pieces.blockOfCell[static_cast<std::size_t>(neighbour)]});
    }
    for (std::size_t piece = 0; piece < count; ++piece) {
        QVERIFY(members[piece] > 0);
        QVERIFY(std::abs(pieces.figures[piece].cost - costs[piece]) <= 1e-9 * costs[piece]);
    }
    for (std::size_t cell = 0; cell < graph.size(); ++cell)
        QCOMPARE(reachedWithinPiece(graph, pieces.blockOfCell, static_cast<int>(cell)),
                 members[static_cast<std::size_t>(pieces.blockOfCell[cell])]);
    std::set<std::pair<int, int>> listed;
    for (std::size_t piece = 0; piece < count; ++piece)
        for (int other : pieces.adjacency.of(static_cast<int>(piece)))
            listed.insert({static_cast<int>(piece), other});
    QCOMPARE(listed, touching);
    std::set<int> startPieces;
    for (int start : starts)
        QVERIFY(startPieces.insert(pieces.blockOfCell[static_cast<std::size_t>(start)]).second);
}

// Connected parts of the graph, by cell.
std::vector<int> partsOf(const CellGraph& graph, int& partCount) {
    std::vector<int> part(graph.size(), -1);
    partCount = 0;
    for (std::size_t first = 0; first < graph.size(); ++first) {
        if (part[first] >= 0)
            continue;
        part[first] = partCount;
        std::vector<int> queue{static_cast<int>(first)};
        for (std::size_t head = 0; head < queue.size(); ++head)
            for (int neighbour : graph.neighbours(queue[head]))
                if (part[static_cast<std::size_t>(neighbour)] < 0) {
                    part[static_cast<std::size_t>(neighbour)] = partCount;
                    queue.push_back(neighbour);
                }
        ++partCount;
    }
    return part;
}

std::vector<int> spreadStarts(const CellGraph& graph, int count) {
    std::vector<int> starts;
    for (int at = 0; at < count; ++at)
        starts.push_back(static_cast<int>(graph.size() * static_cast<std::size_t>(2 * at + 1) /
                                          static_cast<std::size_t>(2 * count)));
    return starts;
}

} // namespace

class TestTreePieces : public QObject {
    Q_OBJECT

  private slots:
    // Each level's pieces lie within the coarser level's, and each level is a partition as above.
    void levelsNest() {
        const CellGraph graph = test::cellPerPixelGraph(test::obstacleGridProblem(40, 3, 17));
        const double cellCost = graph.cell(0).coverSeconds();
        const std::vector<int> starts = spreadStarts(graph, 6);
        const std::vector<CellBlocks> levels = treePieces(graph, starts, {40 * cellCost, 5 * cellCost});
        QCOMPARE(levels.size(), std::size_t{2});
        QVERIFY(levels[1].figures.size() > levels[0].figures.size());
        std::vector<int> coarserOf(levels[1].figures.size(), -1);
        for (std::size_t cell = 0; cell < graph.size(); ++cell) {
            int& coarser = coarserOf[static_cast<std::size_t>(levels[1].blockOfCell[cell])];
            if (coarser < 0)
                coarser = levels[0].blockOfCell[cell];
            QCOMPARE(levels[0].blockOfCell[cell], coarser);
        }
        for (const CellBlocks& level : levels)
            checkPieces(graph, level, starts);
    }

    void piecesPartitionTheMap() {
        for (std::uint32_t seed : {5U, 11U}) {
            const CellGraph graph = test::cellPerPixelGraph(test::obstacleGridProblem(37, 3, seed));
            const double cellCost = graph.cell(0).coverSeconds();
            const std::vector<int> starts = spreadStarts(graph, 5);
            for (double cells : {0.5, 3.0, 20.0, 1e9}) {
                const CellBlocks pieces = treePieces(graph, starts, {cells * cellCost}).front();
                checkPieces(graph, pieces, starts);
                // Cut where a subtree reaches the cost: on open ground most pieces hold several cells.
                if (cells >= 3.0 && cells < 1e9)
                    QVERIFY(pieces.figures.size() < graph.size() / 2);
            }
        }
    }

    // On a quadtree of several cell sizes the tree weighs time; the pieces are still linked, touch as said
    // and keep starts apart.
    void piecesOfCellsOfSeveralSizes() {
        test::RandomMapSpec spec = test::multiCoverSpec(64, 6);
        const PlanningProblem problem = test::randomProblem(spec);
        const QuadTree tree = QuadTreeBuilder{}.build(problem.grid, problem.classes,
                                                      DecompositionOptions::from(problem.planner.parameters));
        const CellGraph graph = cellGraphOfQuadTree(tree, NeighbourTopologyBuilder{}.build(tree));
        QVERIFY(!graph.hasOneCellSize());
        std::vector<int> starts;
        for (const MapPoint& start : problem.starts)
            starts.push_back(graph.cellAt(start));
        const std::vector<CellBlocks> levels = treePieces(graph, starts, {6 * graph.cell(0).coverSeconds()});
        checkPieces(graph, levels.front(), starts);
        QVERIFY(levels.front().figures.size() < graph.size());
    }

    // On open ground the whole map's tree runs straight across it: its pieces are still cut short of
    // strips, no side longer than four times the side of a square of their cost (here 64 cells: 32 cells).
    void piecesStayCompact() {
        const int columns = 120;
        const int rows = 30;
        const PlanningProblem problem =
            test::uniformProblem(columns, rows, 10.0, std::vector<bool>(columns * rows, false), {});
        const CellGraph graph = test::cellPerPixelGraph(problem);
        const std::vector<int> starts = spreadStarts(graph, 2);
        const CellBlocks pieces = treePieces(graph, starts, {64 * graph.cell(0).coverSeconds()}).front();
        checkPieces(graph, pieces, starts);
        std::vector<int> west(pieces.figures.size(), columns), east(pieces.figures.size(), -1);
        std::vector<int> north(pieces.figures.size(), rows), south(pieces.figures.size(), -1);
        for (std::size_t cell = 0; cell < graph.size(); ++cell) {
            const auto piece = static_cast<std::size_t>(pieces.blockOfCell[cell]);
            const Cell& square = graph.cell(static_cast<int>(cell));
            west[piece] = std::min(west[piece], square.column);
            east[piece] = std::max(east[piece], square.column);
            north[piece] = std::min(north[piece], square.row);
            south[piece] = std::max(south[piece], square.row);
        }
        int longest = 0;
        for (std::size_t piece = 0; piece < pieces.figures.size(); ++piece)
            longest = std::max({longest, east[piece] - west[piece] + 1, south[piece] - north[piece] + 1});
        QVERIFY2(longest <= 32, qPrintable(QString::number(longest)));
        QVERIFY(pieces.figures.size() < graph.size() / 16); // still pieces of many cells
    }

    // A piece cheaper than a cell is a cell; without a limit, every piece holds one start, or is a part of
    // the map that holds none.
    void limitsOfThePieceCost() {
        const CellGraph graph = test::cellPerPixelGraph(test::obstacleGridProblem(30, 2, 4));
        const std::vector<int> starts = spreadStarts(graph, 4);
        QCOMPARE(treePieces(graph, starts, {1e-6}).front().figures.size(), graph.size());
        const CellBlocks whole = treePieces(graph, starts, {1e12}).front();
        int partCount = 0;
        const std::vector<int> part = partsOf(graph, partCount);
        std::set<int> partsWithStarts;
        for (int start : starts)
            partsWithStarts.insert(part[static_cast<std::size_t>(start)]);
        QVERIFY(static_cast<std::size_t>(partCount) > partsWithStarts.size()); // a part without a start
        const std::size_t expected =
            starts.size() + static_cast<std::size_t>(partCount) - partsWithStarts.size();
        QCOMPARE(whole.figures.size(), expected);
        std::vector<int> startsInPiece(whole.figures.size(), 0);
        for (int start : starts)
            ++startsInPiece[static_cast<std::size_t>(whole.blockOfCell[static_cast<std::size_t>(start)])];
        for (std::size_t cell = 0; cell < graph.size(); ++cell)
            if (partsWithStarts.count(part[cell]) > 0)
                QCOMPARE(startsInPiece[static_cast<std::size_t>(whole.blockOfCell[cell])], 1);
    }

    // The whole map's tree takes seconds on maps of a million cells: a cancel request stops it. Not asked,
    // the pieces are the same.
    void aCancelRequestStopsThePieces() {
        const CellGraph graph = test::cellPerPixelGraph(test::obstacleGridProblem(30, 2, 4));
        const std::vector<int> starts = spreadStarts(graph, 4);
        const double cost = 40 * graph.cell(0).coverSeconds();
        std::atomic<bool> cancel{false};
        const ProgressReporter progress({}, &cancel);
        QCOMPARE(treePieces(graph, starts, {cost}, &progress).front().blockOfCell,
                 treePieces(graph, starts, {cost}).front().blockOfCell);
        cancel = true;
        bool cancelled = false;
        try {
            (void)treePieces(graph, starts, {cost}, &progress);
        } catch (const PlanningError& error) {
            cancelled = error.kind() == PlanningError::Kind::Cancelled;
        }
        QVERIFY(cancelled);
    }
};

QTEST_APPLESS_MAIN(TestTreePieces)
#include "test_tree_pieces.moc"
