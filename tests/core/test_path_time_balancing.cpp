#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathTimeBalancing.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>

using namespace mcpp;

namespace {

struct Split {
    CellGraph graph;
    RegionAllocation regions;
    std::vector<MapPoint> starts;

    // An 8 x 8 free grid; robot 0 (start in the north-west cell) holds the columns west of `border`,
    // robot 1 (start in the south-east cell) the rest.
    explicit Split(int border) {
        PlanningProblem problem = test::uniformProblem(8, 8, 10.0, std::vector<bool>(64, false), {});
        graph = test::cellPerPixelGraph(problem);
        regions.robotOfCell.resize(graph.size());
        regions.costSeconds.assign(2, 0.0);
        regions.startCell.assign(2, -1);
        for (std::size_t id = 0; id < graph.size(); ++id) {
            const Cell& cell = graph.cell(static_cast<int>(id));
            const int robot = cell.column < border ? 0 : 1;
            regions.robotOfCell[id] = robot;
            regions.costSeconds[static_cast<std::size_t>(robot)] += cell.coverSeconds();
            if ((cell.column == 0 && cell.row == 0) || (cell.column == 7 && cell.row == 7))
                regions.startCell[static_cast<std::size_t>(robot)] = static_cast<int>(id);
        }
        for (int start : regions.startCell) {
            const Cell& cell = graph.cell(start);
            starts.push_back(cell.subCellCentre(SubCell::NorthWest));
        }
    }
};

} // namespace

class PathTimeBalancingTest : public QObject {
    Q_OBJECT
  private slots:
    // 48 cells against 16: cells pass to the short path until the two are close, the longest path only
    // ever shortening; regions stay whole, starts stay, and each path is its region's.
    void unevenRegionsEvenOut() {
        Split split(6);
        const SpanningTreeCoverage coverage;
        std::vector<CoveragePath> paths = coverage.plan(split.graph, split.regions, split.starts, {});
        const double before = longestPathSeconds(paths);
        const int moved = PathTimeBalancing(coverage, 1'000'000)
                              .balance(split.graph, split.regions, paths, split.starts, {});
        const double after = longestPathSeconds(paths);
        QVERIFY(moved >= 12);
        QVERIFY2(after < 0.75 * before, qPrintable(QString("%1 -> %2").arg(before).arg(after)));
        const double shorter = std::min(paths[0].timeSeconds, paths[1].timeSeconds);
        QVERIFY2(after <= 1.1 * shorter, qPrintable(QString("%1 against %2").arg(after).arg(shorter)));
        for (int robot : {0, 1}) {
            QCOMPARE(split.regions.robotOfCell[static_cast<std::size_t>(split.regions.startCell[robot])],
                     robot);
            QVERIFY(test::regionIsConnected(split.graph, split.regions.robotOfCell, robot));
            const CoveragePath replanned = coverage.plan(split.graph, split.regions, split.starts, {})[robot];
            QCOMPARE(paths[static_cast<std::size_t>(robot)].timeSeconds, replanned.timeSeconds);
            double cost = 0.0;
            for (std::size_t id = 0; id < split.graph.size(); ++id)
                if (split.regions.robotOfCell[id] == robot)
                    cost += split.graph.cell(static_cast<int>(id)).coverSeconds();
            QVERIFY(std::abs(split.regions.costSeconds[static_cast<std::size_t>(robot)] - cost) < 1e-6);
        }
    }

    // Halves already within 0.2 % of each other: nothing moves.
    void evenRegionsStay() {
        Split split(4);
        const SpanningTreeCoverage coverage;
        std::vector<CoveragePath> paths = coverage.plan(split.graph, split.regions, split.starts, {});
        const std::vector<int> owner = split.regions.robotOfCell;
        QVERIFY(std::abs(paths[0].timeSeconds - paths[1].timeSeconds) < 0.002 * paths[0].timeSeconds);
        QCOMPARE(PathTimeBalancing(coverage, 1'000'000)
                     .balance(split.graph, split.regions, paths, split.starts, {}),
                 0);
        QCOMPARE(split.regions.robotOfCell, owner);
    }

    // A budget below what one chain would replan (the two regions hold 64 cells): nothing is tried.
    void budgetIsHonoured() {
        Split split(6);
        const SpanningTreeCoverage coverage;
        std::vector<CoveragePath> paths = coverage.plan(split.graph, split.regions, split.starts, {});
        const std::vector<int> owner = split.regions.robotOfCell;
        const double before = longestPathSeconds(paths);
        QCOMPARE(PathTimeBalancing(coverage, 63).balance(split.graph, split.regions, paths, split.starts, {}),
                 0);
        QCOMPARE(split.regions.robotOfCell, owner);
        QCOMPARE(longestPathSeconds(paths), before);
        QVERIFY(PathTimeBalancing(coverage, 64).balance(split.graph, split.regions, paths, split.starts, {}) >
                0);
    }

    // A taker only takes what it may (an aircraft, cells within its reach): robot 1 may take column 6
    // alone, so the cells it gets lie there, where even halves would give it columns 4 and 5 too.
    void takersTakeOnlyWhatTheyMay() {
        Split split(7);
        const SpanningTreeCoverage coverage;
        std::vector<CoveragePath> paths = coverage.plan(split.graph, split.regions, split.starts, {});
        const std::vector<int> owner = split.regions.robotOfCell;
        PathTimeBalancing balancing(coverage, 1'000'000);
        const auto allowed = [&split](std::size_t robot, int cell) {
            const int column = split.graph.cell(cell).column;
            return robot == 0 || column >= 6;
        };
        balancing.setMayTake(allowed);
        QVERIFY(balancing.balance(split.graph, split.regions, paths, split.starts, {}) > 0);
        int taken = 0;
        for (std::size_t id = 0; id < split.graph.size(); ++id) {
            const int robot = split.regions.robotOfCell[id];
            if (robot == owner[id])
                continue;
            ++taken;
            QVERIFY2(allowed(static_cast<std::size_t>(robot), static_cast<int>(id)),
                     qPrintable(QStringLiteral("cell %1 went to robot %2").arg(id).arg(robot)));
        }
        QVERIFY(taken > 0);
        QVERIFY(test::regionIsConnected(split.graph, split.regions.robotOfCell, 1));
    }
};

QTEST_GUILESS_MAIN(PathTimeBalancingTest)
#include "test_path_time_balancing.moc"
