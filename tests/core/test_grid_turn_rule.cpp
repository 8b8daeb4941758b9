#include "core/allocation/StartComponents.hpp"
#include "core/coverage/GridTurnRule.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <numeric>
#include <random>

using namespace mcpp;

namespace {

constexpr unsigned east = 1U << 0, north = 1U << 1, west = 1U << 2, south = 1U << 3;

// A map's grid as MSTC makes it (cells of 2 x 2 free sub-cells, blocked cells left out), its largest part
// and the first start in it.
struct GridPart {
    Plan plan;
    std::vector<int> cells;
    int rootCell = -1;
    MapPoint start;

    explicit GridPart(PlanningProblem problem) {
        problem.planner = defaultPlannerChoice("mstc");
        plan = makePlanner("mstc")->plan(problem, {});
        const std::vector<StartComponent> parts = componentsWithStarts(plan.cells, plan.regions.startCell);
        const StartComponent& part =
            *std::max_element(parts.begin(), parts.end(),
                              [](const auto& a, const auto& b) { return a.cells.size() < b.cells.size(); });
        cells = part.cells;
        const auto robot = static_cast<std::size_t>(part.robots.front());
        rootCell = plan.regions.startCell[robot];
        start = problem.starts[robot];
    }
};

// A spanning tree of the part's cells drawn at random (Kruskal over the grid edges in a shuffled order).
SpanningTree randomTree(const GridPart& part, std::mt19937& random) {
    std::vector<int> nodeOfCell(part.plan.cells.size(), -1);
    for (std::size_t node = 0; node < part.cells.size(); ++node)
        nodeOfCell[static_cast<std::size_t>(part.cells[node])] = static_cast<int>(node);
    std::vector<std::pair<int, int>> gridEdges;
    for (std::size_t node = 0; node < part.cells.size(); ++node)
        for (const int next : part.plan.cells.neighbours(part.cells[node]))
            if (const int other = nodeOfCell[static_cast<std::size_t>(next)]; other > static_cast<int>(node))
                gridEdges.emplace_back(static_cast<int>(node), other);
    std::shuffle(gridEdges.begin(), gridEdges.end(), random);
    std::vector<int> group(part.cells.size());
    std::iota(group.begin(), group.end(), 0);
    const auto find = [&](int node) {
        while (group[static_cast<std::size_t>(node)] != node)
            node = group[static_cast<std::size_t>(node)] =
                group[static_cast<std::size_t>(group[static_cast<std::size_t>(node)])];
        return node;
    };
    std::vector<std::pair<int, int>> treeEdges;
    for (const auto& [a, b] : gridEdges)
        if (const int ga = find(a), gb = find(b); ga != gb) {
            group[static_cast<std::size_t>(ga)] = gb;
            treeEdges.emplace_back(a, b);
        }
    return SpanningTree(part.cells, nodeOfCell[static_cast<std::size_t>(part.rootCell)], treeEdges);
}

// The side of cell `here` that `there` lies beyond: 0 east, 1 north, 2 west, 3 south (rows run south).
int sideOf(const Cell& here, const Cell& there) {
    if (there.column > here.column)
        return 0;
    if (there.row < here.row)
        return 1;
    return there.column < here.column ? 2 : 3;
}

// The rule summed over every cell of the tree.
int turnsByRule(const SpanningTree& tree, const CellGraph& graph) {
    int turns = 0;
    for (std::size_t node = 0; node < tree.size(); ++node) {
        unsigned sides = 0;
        const Cell& here = graph.cell(tree.cellOf(static_cast<int>(node)));
        for (const int next : tree.neighbours(static_cast<int>(node)))
            sides |= 1U << sideOf(here, graph.cell(tree.cellOf(next)));
        turns += GridTurnRule::turnsInCell(sides);
    }
    return turns;
}

// The turns of the closed walk round the tree, the one where it closes included.
int turnsOfClosedWalk(const SpanningTree& tree, const GridPart& part) {
    std::vector<Waypoint> walk = TreeCircumnavigation(part.plan.cells).walk(tree, part.start, true);
    if (walk.size() > 1)
        walk.push_back(walk[1]);
    return countTurns(walk);
}

} // namespace

class GridTurnRuleTest : public QObject {
    Q_OBJECT

  private slots:
    void turnsInOneCell_data() {
        QTest::addColumn<unsigned>("sides");
        QTest::addColumn<int>("turns");
        QTest::newRow("alone: round the cell") << 0U << 4;
        QTest::newRow("a leaf: back the way it came") << east << 2;
        QTest::newRow("straight through") << (east | west) << 0;
        QTest::newRow("a corner") << (east | north) << 2;
        QTest::newRow("a branch off a straight run") << (east | north | west) << 2;
        QTest::newRow("a crossing") << (east | north | west | south) << 4;
    }

    void turnsInOneCell() {
        QFETCH(unsigned, sides);
        QFETCH(int, turns);
        QCOMPARE(GridTurnRule::turnsInCell(sides), turns);
    }

    // Toggling an edge changes the turns of its own cell as the rule counts them, and only beside it.
    void toggleChangesWhatTheRuleCounts() {
        for (unsigned sides = 0; sides < 16; ++sides)
            for (int side = 0; side < 4; ++side) {
                unsigned toggled = sides;
                const int change = GridTurnRule::toggle(toggled, side);
                QCOMPARE(toggled, sides ^ (1U << side));
                QCOMPARE(change, GridTurnRule::turnsInCell(toggled) - GridTurnRule::turnsInCell(sides));
                QVERIFY(std::abs(change) <= 2);
            }
    }

    // The rule counts the closed walk's turns exactly, on the turn-minimising trees and on random ones, on
    // an open grid and on the benchmark grid with 15 % of its cells blocked.
    void theRuleCountsTheWalksTurns_data() {
        QTest::addColumn<bool>("obstacles");
        QTest::newRow("open grid") << false;
        QTest::newRow("15 % obstacles") << true;
    }

    void theRuleCountsTheWalksTurns() {
        QFETCH(bool, obstacles);
        const GridPart part(obstacles ? test::obstacleGridProblem(49, 4, 2020)
                                      : test::uniformProblem(40, 30, 10.0, {}, {{500105.0, 3999895.0}}));
        QVERIFY(part.cells.size() > 500);
        std::vector<int> scratch(part.plan.cells.size(), -1);
        const SpanningTreeBuilder trees(part.plan.cells, scratch);
        for (int candidate = 0; candidate < trees.candidatesFor(part.cells); ++candidate) {
            const SpanningTree tree = trees.candidate(candidate, part.cells, part.rootCell);
            QCOMPARE(turnsByRule(tree, part.plan.cells), turnsOfClosedWalk(tree, part));
        }
        std::mt19937 random(7);
        for (int drawn = 0; drawn < 20; ++drawn) {
            const SpanningTree tree = randomTree(part, random);
            QCOMPARE(turnsByRule(tree, part.plan.cells), turnsOfClosedWalk(tree, part));
        }
    }
};

QTEST_APPLESS_MAIN(GridTurnRuleTest)
#include "test_grid_turn_rule.moc"
