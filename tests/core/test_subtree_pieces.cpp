#include "core/allocation/StartComponents.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SubtreePieces.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>

using namespace mcpp;

namespace {

// The benchmark grid of 49 x 49 cells with 15 % obstacles, as MSTC decomposes it, and its largest part's
// robots: their start cells and points, and the part's turn-minimising tree held from the first start.
struct PartOfGrid {
    Plan plan;
    std::vector<int> startCells;
    std::vector<MapPoint> starts;
    std::vector<int> cells;
    std::vector<int> scratch;
    SpanningTree tree;

    explicit PartOfGrid(int robots) {
        PlanningProblem problem = test::obstacleGridProblem(49, robots, 2020);
        problem.planner = defaultPlannerChoice("mstc");
        plan = makePlanner("mstc")->plan(problem, {});
        const std::vector<StartComponent> parts = componentsWithStarts(plan.cells, plan.regions.startCell);
        const StartComponent& part =
            *std::max_element(parts.begin(), parts.end(),
                              [](const auto& a, const auto& b) { return a.robots.size() < b.robots.size(); });
        for (const int robot : part.robots) {
            startCells.push_back(plan.regions.startCell[static_cast<std::size_t>(robot)]);
            starts.push_back(problem.starts[static_cast<std::size_t>(robot)]);
        }
        cells = part.cells;
        scratch.assign(plan.cells.size(), -1);
        tree = SpanningTreeBuilder(plan.cells, scratch).candidate(0, cells, startCells.front());
    }
};

// The pieces' walks from their starts, as a robot would walk them.
struct Walks {
    int turns = 0;
    double longestSeconds = 0.0;
    double meanSeconds = 0.0;
};

Walks walks(const SubtreePieces& pieces, const PartOfGrid& part) {
    TreeCircumnavigation walker(part.plan.cells);
    Walks walked;
    for (std::size_t robot = 0; robot < part.startCells.size(); ++robot) {
        const PathShape shape = walker.walkShape(pieces.pieceTree(robot), part.starts[robot], false);
        walked.turns += shape.turns();
        walked.longestSeconds = std::max(walked.longestSeconds, shape.seconds());
        walked.meanSeconds += shape.seconds() / static_cast<double>(part.startCells.size());
    }
    return walked;
}

} // namespace

class SubtreePiecesTest : public QObject {
    Q_OBJECT

  private slots:
    // Saving turns hands small branches between pieces: fewer turns in all, no piece longer than the
    // longest was or the slack above the mean allows, and still every cell of the part in one piece,
    // each piece a tree round its own start. The times and turns it keeps are those of the pieces' walks.
    // With no slack the longest piece never grows.
    void savingTurnsKeepsTheBudgetAndEveryCell_data() {
        QTest::addColumn<int>("robots");
        QTest::addColumn<double>("slack");
        QTest::addColumn<bool>("mustSave");
        QTest::newRow("8 robots, no slack") << 8 << 0.0 << false;
        QTest::newRow("8 robots, 0.8 %") << 8 << 0.008 << true;
        QTest::newRow("14 robots, no slack") << 14 << 0.0 << true;
        QTest::newRow("14 robots, 0.8 %") << 14 << 0.008 << true;
    }
    void savingTurnsKeepsTheBudgetAndEveryCell() {
        QFETCH(int, robots);
        QFETCH(double, slack);
        QFETCH(bool, mustSave);
        const PartOfGrid part(robots);
        QVERIFY(part.startCells.size() > 1);
        SubtreePieces pieces(part.plan.cells, part.tree, part.startCells, part.starts, {});
        const double longest = pieces.longestSeconds();
        const int turns = pieces.totalTurns();
        const double mostSeconds = (1.0 + slack) * walks(pieces, part).meanSeconds;
        QCOMPARE(pieces.meanSeconds(), walks(pieces, part).meanSeconds);
        const double budget = std::max(longest, mostSeconds);
        const int saved = pieces.saveTurns(mostSeconds, {});
        const QString figures = QStringLiteral("%1 turns, %2 saved; longest %3 s, then %4 s, budget %5 s")
                                    .arg(turns)
                                    .arg(saved)
                                    .arg(longest)
                                    .arg(pieces.longestSeconds())
                                    .arg(budget);
        QVERIFY2(saved > 0 || !mustSave, qPrintable(figures));
        QVERIFY2(pieces.longestSeconds() <= budget, qPrintable(figures));

        std::vector<int> pieceOfCell(part.plan.cells.size(), -1);
        for (std::size_t robot = 0; robot < part.startCells.size(); ++robot) {
            const SpanningTree piece = pieces.pieceTree(robot);
            QCOMPARE(piece.cellOf(piece.root()), part.startCells[robot]);
            for (const int cell : piece.cells()) {
                QCOMPARE(pieceOfCell[static_cast<std::size_t>(cell)], -1);
                pieceOfCell[static_cast<std::size_t>(cell)] = static_cast<int>(robot);
            }
        }
        for (const int cell : part.cells)
            QVERIFY(pieceOfCell[static_cast<std::size_t>(cell)] >= 0);
        const Walks walked = walks(pieces, part);
        QCOMPARE(walked.turns, pieces.totalTurns());
        QCOMPARE(walked.longestSeconds, pieces.longestSeconds());
    }
};

QTEST_APPLESS_MAIN(SubtreePiecesTest)
#include "test_subtree_pieces.moc"
