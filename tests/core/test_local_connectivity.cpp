#include "core/model/LocalConnectivity.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <random>
#include <string>
#include <vector>

using namespace mcpp;

namespace {

// Owners drawn row by row, one cell per character: a digit for a region, '.' for nobody.
struct DrawnOwners {
    CellGraph graph;
    std::vector<int> owner;
    int columns = 0;
    [[nodiscard]] int cellAt(int column, int row) const {
        for (std::size_t id = 0; id < graph.size(); ++id)
            if (graph.cell(static_cast<int>(id)).column == column &&
                graph.cell(static_cast<int>(id)).row == row)
                return static_cast<int>(id);
        return -1;
    }
};

DrawnOwners drawn(const std::vector<std::string>& owners) {
    DrawnOwners result;
    result.columns = static_cast<int>(owners.front().size());
    const PlanningProblem problem =
        test::uniformProblem(result.columns, static_cast<int>(owners.size()), 10.0, {}, {});
    result.graph = test::cellPerPixelGraph(problem);
    result.owner.assign(result.graph.size(), -1);
    for (std::size_t id = 0; id < result.graph.size(); ++id) {
        const Cell& cell = result.graph.cell(static_cast<int>(id));
        const char owner = owners[static_cast<std::size_t>(cell.row)][static_cast<std::size_t>(cell.column)];
        result.owner[id] = owner == '.' ? -1 : owner - '0';
    }
    return result;
}

// The rule as documented, searched the plain way: from the cell's first neighbour in its region, breadth
// first within the region less the cell, until every other such neighbour is found or `limit` cells are
// queued.
bool plainCanRemove(const CellGraph& graph, const std::vector<int>& owner, int cell, std::size_t limit) {
    const int region = owner[static_cast<std::size_t>(cell)];
    std::vector<int> targets;
    for (int neighbour : graph.neighbours(cell))
        if (owner[static_cast<std::size_t>(neighbour)] == region)
            targets.push_back(neighbour);
    if (targets.size() <= 1)
        return !targets.empty();
    std::vector<char> seen(graph.size(), 0);
    seen[static_cast<std::size_t>(cell)] = 1;
    seen[static_cast<std::size_t>(targets.front())] = 1;
    std::vector<int> queue{targets.front()};
    std::size_t found = 1;
    for (std::size_t head = 0; head < queue.size() && queue.size() < limit; ++head)
        for (int next : graph.neighbours(queue[head])) {
            if (owner[static_cast<std::size_t>(next)] != region || seen[static_cast<std::size_t>(next)] != 0)
                continue;
            seen[static_cast<std::size_t>(next)] = 1;
            queue.push_back(next);
            if (std::find(targets.begin(), targets.end(), next) != targets.end() && ++found == targets.size())
                return true;
        }
    return false;
}

} // namespace

class TestLocalConnectivity : public QObject {
    Q_OBJECT

  private slots:
    // A cell whose removal cuts a short tail off its region would cut it, however wide the search; a cell
    // of a thick part can go.
    void cellsThatCutATailOffAreKept() {
        const DrawnOwners map = drawn({
            "1111111111", //
            "1111111111", //
            "1111111111", //
            "1111112222", //
            "2222212222", //
            "2222212222", //
        });
        LocalConnectivity connectivity(map.graph);
        const int neck = map.cellAt(5, 3); // joins the tail (5, 4) and (5, 5) to the rest of region 1
        for (std::size_t limit : {std::size_t{24}, std::size_t{256}})
            QVERIFY(!connectivity.canRemove(neck, map.owner, limit));
        QVERIFY(connectivity.canRemove(map.cellAt(2, 1), map.owner, 24));
        QVERIFY(connectivity.canRemove(map.cellAt(2, 1), map.owner, 256));
        QVERIFY(connectivity.canRemove(map.cellAt(5, 5), map.owner, 256)); // the tail's tip
    }

    // Regions reconnecting only through a loop longer than the search count as cut: the check never
    // splits a region, at the price of keeping some cells it could give.
    void aLongLoopCountsAsCutForAShortSearch() {
        const DrawnOwners map = drawn({
            "1111111111", //
            "1000000001", //
            "1000000001", //
            "1111111111", //
        });
        LocalConnectivity connectivity(map.graph);
        const int onTheLoop = map.cellAt(4, 0);
        QVERIFY(!connectivity.canRemove(onTheLoop, map.owner, 8));
        QVERIFY(connectivity.canRemove(onTheLoop, map.owner, 256));
    }

    // On random divisions (fixed seed) of many thin parts, every answer is the plain search's, for narrow
    // and wide searches alike, and every cell it lets go leaves its region in one piece.
    void answersAsThePlainSearchDoes() {
        const int side = 40;
        const PlanningProblem problem = test::uniformProblem(side, side, 10.0, {}, {});
        const CellGraph graph = test::cellPerPixelGraph(problem);
        std::mt19937 random(20261129);
        std::vector<int> owner(graph.size());
        // Blobs of three regions grown from random seeds, then a tenth of the cells given to a random one:
        // necks, tails and small cut-off parts of every size.
        for (std::size_t id = 0; id < graph.size(); ++id) {
            const Cell& cell = graph.cell(static_cast<int>(id));
            owner[id] = ((cell.column / 7) + (cell.row / 5)) % 3;
            if (random() % 10 == 0)
                owner[id] = static_cast<int>(random() % 3);
        }
        LocalConnectivity connectivity(graph);
        int removable = 0;
        int kept = 0;
        for (std::size_t limit : {std::size_t{8}, std::size_t{24}, std::size_t{64}, std::size_t{256}})
            for (int cell = 0; cell < static_cast<int>(graph.size()); ++cell) {
                const bool answer = connectivity.canRemove(cell, owner, limit);
                QCOMPARE(answer, plainCanRemove(graph, owner, cell, limit));
                (answer ? removable : kept) += 1;
            }
        QVERIFY2(removable > 1000 && kept > 1000,
                 qPrintable(QString("%1 removable, %2 kept").arg(removable).arg(kept)));

        // Removal judged on a connected region: hand each removable cell to nobody and look.
        const DrawnOwners strip = drawn({
            "1111111111", //
            "1001111001", //
            "1111001111", //
        });
        LocalConnectivity stripConnectivity(strip.graph);
        for (int cell = 0; cell < static_cast<int>(strip.graph.size()); ++cell) {
            if (strip.owner[static_cast<std::size_t>(cell)] != 1 ||
                !stripConnectivity.canRemove(cell, strip.owner, 256))
                continue;
            std::vector<int> without = strip.owner;
            without[static_cast<std::size_t>(cell)] = -1;
            QVERIFY2(test::regionIsConnected(strip.graph, without, 1), qPrintable(QString::number(cell)));
        }
    }
};

QTEST_GUILESS_MAIN(TestLocalConnectivity)
#include "test_local_connectivity.moc"
