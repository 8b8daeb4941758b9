#include "core/coverage/ApproachRoutes.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>

using namespace mcpp;

namespace {

// A 10 x 10 grid of 10 m cells at 1 m/s, water where `blocked` holds (column, row).
template <typename Blocked> CellGraph gridGraph(Blocked blocked) {
    std::vector<bool> water(100, false);
    for (int row = 0; row < 10; ++row)
        for (int column = 0; column < 10; ++column)
            water[static_cast<std::size_t>(row * 10 + column)] = blocked(column, row);
    return test::cellPerPixelGraph(test::uniformProblem(10, 10, 10.0, water, {}));
}

int cellAt(const CellGraph& graph, int column, int row) {
    for (std::size_t id = 0; id < graph.size(); ++id)
        if (graph.cell(static_cast<int>(id)).column == column && graph.cell(static_cast<int>(id)).row == row)
            return static_cast<int>(id);
    return -1;
}

// Changes of direction along a route of cells.
int turnsAlong(const CellGraph& graph, const std::vector<int>& cells) {
    int turns = 0;
    for (std::size_t k = 2; k < cells.size(); ++k) {
        const Cell a = graph.cell(cells[k - 2]);
        const Cell b = graph.cell(cells[k - 1]);
        const Cell c = graph.cell(cells[k]);
        if (b.column - a.column != c.column - b.column || b.row - a.row != c.row - b.row)
            ++turns;
    }
    return turns;
}

} // namespace

// The ways a robot takes to a piece of work elsewhere: the quickest, the straightest among them.
class TestApproachRoutes : public QObject {
    Q_OBJECT

  private slots:
    // Across an open field, five cells east and five south: 100 m at 1 m/s, and of the many quickest
    // staircases the one that turns once.
    void anOpenFieldIsCrossedWithOneTurn() {
        const CellGraph graph = gridGraph([](int, int) { return false; });
        const ApproachRoutes routes(graph);
        const int from = cellAt(graph, 0, 0);
        const int to = cellAt(graph, 5, 5);
        QCOMPARE(static_cast<double>(routes.secondsFrom(from)[static_cast<std::size_t>(to)]), 100.0);
        const std::vector<int> cells = routes.cellsBetween(from, to);
        QCOMPARE(cells.size(), std::size_t{11});
        QCOMPARE(cells.front(), from);
        QCOMPARE(cells.back(), to);
        QCOMPARE(turnsAlong(graph, cells), 1);
        for (std::size_t k = 1; k < cells.size(); ++k)
            QVERIFY(graph.areNeighbours(cells[k - 1], cells[k]));
    }

    // A wall down column 3 but for its last row: the way round goes down, along and up again, 24 cells of
    // travel and two turns.
    void aWallIsWalkedRound() {
        const CellGraph graph = gridGraph([](int column, int row) { return column == 3 && row < 9; });
        const ApproachRoutes routes(graph);
        const int from = cellAt(graph, 0, 0);
        const int to = cellAt(graph, 6, 0);
        QCOMPARE(static_cast<double>(routes.secondsFrom(from)[static_cast<std::size_t>(to)]), 240.0);
        const std::vector<int> cells = routes.cellsBetween(from, to);
        QCOMPARE(cells.size(), std::size_t{25});
        QCOMPARE(turnsAlong(graph, cells), 2);
    }

    // A cell walled in on every side lies in another part: no time reaches it and no way leads there.
    void aWalledInCellIsOutOfReach() {
        const CellGraph graph = gridGraph([](int column, int row) {
            return std::abs(column - 7) <= 1 && std::abs(row - 7) <= 1 && !(column == 7 && row == 7);
        });
        const ApproachRoutes routes(graph);
        const int from = cellAt(graph, 0, 0);
        const int inside = cellAt(graph, 7, 7);
        QVERIFY(std::isinf(routes.secondsFrom(from)[static_cast<std::size_t>(inside)]));
        QVERIFY(routes.cellsBetween(from, inside).empty());
        QCOMPARE(routes.cellsBetween(from, from), std::vector<int>{from});
    }
};

QTEST_MAIN(TestApproachRoutes)
#include "test_approach_routes.moc"
