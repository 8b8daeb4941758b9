#include "core/allocation/BorderExchange.hpp"
#include "core/decomposition/UniformGridDecomposition.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <numeric>

using namespace mcpp;

namespace {

// Cells of a drawn map (2 x 2 pixels each, 4 s to cover) and their ids by (column, row).
struct DrawnCells {
    CellGraph graph;
    std::vector<int> cells;
    std::vector<int> scratch;

    explicit DrawnCells(const std::vector<std::string>& rows) {
        const PlanningProblem problem = test::drawnProblem(rows, {});
        graph = UniformGridDecomposition(DecompositionOptions{}, GridCellRule::WholeCell)
                    .decompose(problem.grid, problem.classes);
        cells.resize(graph.size());
        std::iota(cells.begin(), cells.end(), 0);
        scratch.assign(graph.size(), -1);
    }

    [[nodiscard]] int at(long long column, long long row) const {
        for (std::size_t id = 0; id < graph.size(); ++id)
            if (graph.cell(static_cast<int>(id)).column == column &&
                graph.cell(static_cast<int>(id)).row == row)
                return static_cast<int>(id);
        return -1;
    }
};

} // namespace

class BorderExchangeTest : public QObject {
    Q_OBJECT

  private slots:
    // Region 0 is a line of six cells; region 1 is one cell under its fifth, which is the only cell of
    // region 0 it touches. No single cell can go without cutting region 0, so the fifth goes with the sixth
    // that hangs on it: 4 cells against 3, within one cell of the fair share of 3.5.
    void aCellGoesWithWhatHangsOnIt() {
        DrawnCells drawn({"............", "............", "########..##", "########..##"});
        QCOMPARE(drawn.graph.size(), std::size_t{7});
        std::vector<int> owner(drawn.graph.size(), 0);
        owner[static_cast<std::size_t>(drawn.at(4, 1))] = 1;
        const CellIndexScope local(drawn.scratch, drawn.cells);
        std::vector<double> weights;
        for (int cell : drawn.cells)
            weights.push_back(drawn.graph.cell(cell).coverSeconds());
        QCOMPARE(weights.front(), 4.0);
        BorderExchange exchange(drawn.graph, drawn.cells, local, weights, {drawn.at(0, 0), drawn.at(4, 1)},
                                [](int, int, int) { return std::int64_t{0}; });
        const double error = exchange.balance(owner, 4.0);
        QVERIFY2(error <= 4.0, qPrintable(QString::number(error)));
        QCOMPARE(owner[static_cast<std::size_t>(drawn.at(4, 0))], 1);
        QCOMPARE(owner[static_cast<std::size_t>(drawn.at(5, 0))], 1);
        for (int column = 0; column < 4; ++column)
            QCOMPARE(owner[static_cast<std::size_t>(drawn.at(column, 0))], 0);
    }

    // A corridor split 8 to 2, asked for less than a cell of error: single cells cross the border until the
    // regions hold 5 each.
    void singleCellsCrossAStraightBorder() {
        DrawnCells drawn({"....................", "...................."});
        std::vector<int> owner(drawn.graph.size(), 0);
        for (int column = 8; column < 10; ++column)
            owner[static_cast<std::size_t>(drawn.at(column, 0))] = 1;
        const CellIndexScope local(drawn.scratch, drawn.cells);
        std::vector<double> weights(drawn.graph.size(), 4.0);
        BorderExchange exchange(drawn.graph, drawn.cells, local, weights, {drawn.at(0, 0), drawn.at(9, 0)},
                                [](int, int, int) { return std::int64_t{0}; });
        QCOMPARE(exchange.balance(owner, 1.0), 0.0);
        for (int column = 0; column < 10; ++column)
            QCOMPARE(owner[static_cast<std::size_t>(drawn.at(column, 0))], column < 5 ? 0 : 1);
    }
};

QTEST_APPLESS_MAIN(BorderExchangeTest)
#include "test_border_exchange.moc"
