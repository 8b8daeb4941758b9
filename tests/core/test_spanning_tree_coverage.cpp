#include "core/coverage/CellIndexScope.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathShape.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "tests/support/PlanInvariants.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <random>
#include <set>

using namespace mcpp;

namespace {

Plan planOf(const PlanningProblem& problem) {
    return MlctPlanner{}.plan(problem, {});
}

QString violations(const PlanningProblem& problem, const Plan& plan) {
    return QString::fromStdString(test::describe(test::checkAllInvariants(problem, plan)));
}

// The first difference between two paths, field by field and waypoint by waypoint; empty when none.
QString differenceBetween(const CoveragePath& a, const CoveragePath& b) {
    if (a.robot != b.robot || a.closed != b.closed)
        return "robot or closed";
    if (a.lengthMetres != b.lengthMetres || a.timeSeconds != b.timeSeconds ||
        a.turnSeconds != b.turnSeconds || a.connectorSeconds != b.connectorSeconds)
        return QString("measures: length %1 / %2, time %3 / %4")
            .arg(a.lengthMetres, 0, 'g', 17)
            .arg(b.lengthMetres, 0, 'g', 17)
            .arg(a.timeSeconds, 0, 'g', 17)
            .arg(b.timeSeconds, 0, 'g', 17);
    if (a.turns != b.turns || a.repeatedSubCellVisits != b.repeatedSubCellVisits)
        return QString("turns %1 / %2, repeats %3 / %4")
            .arg(a.turns)
            .arg(b.turns)
            .arg(a.repeatedSubCellVisits)
            .arg(b.repeatedSubCellVisits);
    if (a.walkedWaypoints != b.walkedWaypoints || a.runFollows != b.runFollows ||
        a.waypoints.size() != b.waypoints.size())
        return QString("merged runs: %1 / %2 waypoints").arg(a.waypoints.size()).arg(b.waypoints.size());
    for (std::size_t i = 0; i < a.waypoints.size(); ++i) {
        const Waypoint& p = a.waypoints[i];
        const Waypoint& q = b.waypoints[i];
        if (p.x != q.x || p.y != q.y || p.cell != q.cell || p.speedMetresPerSecond != q.speedMetresPerSecond)
            return QString("waypoint %1").arg(i);
    }
    return {};
}

} // namespace

class SpanningTreeCoverageTest : public QObject {
    Q_OBJECT
    int startsOffTheWalk_ = 0; // over walkShapeIsThePathsShape's rows

  private slots:
    // Trees are chosen by the shape of their walk without storing it: it must be the shape of the path.
    void walkShapeIsThePathsShape_data() {
        QTest::addColumn<int>("seed");
        QTest::addColumn<bool>("closed");
        for (int seed = 1; seed <= 12; ++seed)
            QTest::addRow("seed %d", seed) << seed << (seed % 3 != 0);
    }

    void walkShapeIsThePathsShape() {
        QFETCH(int, seed);
        QFETCH(bool, closed);
        test::RandomMapSpec spec;
        spec.seed = static_cast<unsigned>(seed);
        spec.landCovers = 1 + seed % 4;
        spec.obstacleFraction = 0.05 * (seed % 4);
        spec.fovPixels = seed % 2 == 0 ? 1.0 : 0.5;
        spec.robots = 1 + seed % 5;
        const PlanningProblem problem = test::randomProblem(spec);
        const Plan plan = planOf(problem);
        const auto cells = cellsByRobot(plan.regions);
        std::vector<int> scratch(plan.cells.size(), -1);
        const SpanningTreeBuilder trees(plan.cells, scratch);
        TreeCircumnavigation walker(plan.cells);
        for (std::size_t robot = 0; robot < cells.size(); ++robot) {
            for (auto preference : {EdgeDirection::EastWest, EdgeDirection::NorthSouth}) {
                const SpanningTree tree =
                    trees.preferring(cells[robot], plan.regions.startCell[robot], preference);
                const MapPoint start = problem.starts[robot];
                const PathShape shape = walker.walkShape(tree, start, closed);
                CoveragePath path =
                    pathFromWalk(static_cast<int>(robot), start, walker.walk(tree, start, closed), closed);
                measurePath(path, plan.cells);
                QCOMPARE(shape.turns(), path.turns);
                QCOMPARE(shape.lengthMetres(), path.lengthMetres);
                // The path written in place from the start is that path, point for point.
                const std::vector<Waypoint> inPlace = walker.walkFromStart(tree, start, closed);
                QCOMPARE(inPlace.size(), path.waypoints.size());
                for (std::size_t i = 0; i < inPlace.size(); ++i) {
                    QCOMPARE(inPlace[i].x, path.waypoints[i].x);
                    QCOMPARE(inPlace[i].y, path.waypoints[i].y);
                    QCOMPARE(inPlace[i].cell, path.waypoints[i].cell);
                    QCOMPARE(inPlace[i].speedMetresPerSecond, path.waypoints[i].speedMetresPerSecond);
                }
                // Measured and merged as it is walked, the path is the whole one measured, then merged.
                CoveragePath merged = path;
                mergeStraightRuns(merged, plan.cells);
                QVERIFY(merged.runsMerged() || merged.waypoints.size() < 3);
                const CoveragePath asWalked =
                    walker.measuredWalk(tree, static_cast<int>(robot), start, closed);
                QVERIFY2(differenceBetween(asWalked, merged).isEmpty(),
                         qPrintable(differenceBetween(asWalked, merged)));
                // Shape and path in one walk: the same shape, and the path while it stays within the limit.
                // A limit of half the kept waypoints is passed mid-walk, where the measuring is given up.
                const std::size_t kept = asWalked.waypoints.size();
                for (const std::size_t limit : {kept, kept - 1, kept / 2}) {
                    const auto both =
                        walker.walkShapeAndPath(tree, static_cast<int>(robot), start, closed, true, limit);
                    QCOMPARE(both.shape.turns(), shape.turns());
                    QCOMPARE(both.shape.lengthMetres(), shape.lengthMetres());
                    QCOMPARE(both.shape.seconds(), shape.seconds());
                    QCOMPARE(both.shape.turningSeconds(), shape.turningSeconds());
                    QCOMPARE(both.path.has_value(), limit == kept);
                    if (both.path)
                        QVERIFY2(differenceBetween(*both.path, asWalked).isEmpty(),
                                 qPrintable(differenceBetween(*both.path, asWalked)));
                }
                // And as the whole path's own sums, by loops of their own, give them.
                QCOMPARE(asWalked.lengthMetres, pathLengthMetres(path.waypoints));
                QCOMPARE(asWalked.timeSeconds, pathSeconds(path.waypoints, plan.cells).total);
                QCOMPARE(asWalked.turns, countTurns(path.waypoints));
                const Waypoint first =
                    walker.walk(tree, start, closed).front(); // a copy: the walk is a temporary
                startsOffTheWalk_ += first.x != start.x || first.y != start.y ? 1 : 0;
            }
        }
    }

    // A region listed in ascending order is numbered by rank, without an array of the map's size, as the
    // array numbers it; another order, given no array, is numbered in an array of the scope's own. Cells
    // outside the region get -1.
    void aRegionIsNumberedTheSameByRank() {
        std::mt19937 random(7);
        std::vector<int> cells;
        for (int id = 0; id < 5000; ++id)
            if (random() % 3 == 0)
                cells.push_back(id);
        cells.push_back(70'000); // a gap of more than a 64-id word
        std::vector<int> array(70'100, -1);
        std::vector<int> none;
        {
            const CellIndexScope byArray(array, cells);
            const CellIndexScope byRank(none, cells);
            QVERIFY(none.empty());
            for (int id = 0; id < 70'100; ++id)
                QCOMPARE(byRank[id], byArray[id]);
            QCOMPARE(byRank[cells[10]], 10);
            QCOMPARE(byRank[70'000], static_cast<int>(cells.size()) - 1);
        }
        QVERIFY(std::all_of(array.begin(), array.end(), [](int local) { return local == -1; }));
        std::vector<int> shuffled = cells;
        std::shuffle(shuffled.begin(), shuffled.end(), random);
        const CellIndexScope unsorted(none, shuffled);
        QVERIFY(none.empty()); // the scope's own array: the caller's stays empty for the next region
        for (std::size_t local = 0; local < shuffled.size(); ++local)
            QCOMPARE(unsorted[shuffled[local]], static_cast<int>(local));
        QCOMPARE(unsorted[70'050], -1);
    }

    // A tree packed while it waits (cells and parents only) comes back unpacked with the same neighbours,
    // parents and depths, and walks point for point as before.
    void aPackedTreeWalksAsBefore() {
        for (int seed = 1; seed <= 6; ++seed) {
            test::RandomMapSpec spec;
            spec.seed = static_cast<unsigned>(seed);
            spec.landCovers = 1 + seed % 3;
            spec.obstacleFraction = 0.05 * (seed % 3);
            spec.robots = 2;
            const PlanningProblem problem = test::randomProblem(spec);
            const Plan plan = planOf(problem);
            const auto cells = cellsByRobot(plan.regions);
            std::vector<int> scratch(plan.cells.size(), -1);
            const SpanningTreeBuilder trees(plan.cells, scratch);
            TreeCircumnavigation walker(plan.cells);
            for (std::size_t robot = 0; robot < cells.size(); ++robot) {
                const SpanningTree tree = trees.fewestTurns(cells[robot], plan.regions.startCell[robot]);
                SpanningTree packed = tree;
                packed.pack();
                QVERIFY(packed.packed());
                QCOMPARE(packed.cells(), tree.cells());
                packed.unpack();
                QVERIFY(!packed.packed());
                QCOMPARE(packed.root(), tree.root());
                for (int node = 0; node < static_cast<int>(tree.size()); ++node) {
                    QCOMPARE(packed.parent(node), tree.parent(node));
                    QCOMPARE(packed.depth(node), tree.depth(node));
                    const auto before = tree.neighbours(node);
                    const auto after = packed.neighbours(node);
                    QCOMPARE(std::set<int>(after.begin(), after.end()),
                             std::set<int>(before.begin(), before.end()));
                }
                const MapPoint start = problem.starts[robot];
                const std::vector<Waypoint> walked = walker.walkFromStart(tree, start, true);
                const std::vector<Waypoint> again = walker.walkFromStart(packed, start, true);
                QCOMPARE(again.size(), walked.size());
                for (std::size_t i = 0; i < walked.size(); ++i) {
                    QCOMPARE(again[i].x, walked[i].x);
                    QCOMPARE(again[i].y, walked[i].y);
                    QCOMPARE(again[i].cell, walked[i].cell);
                }
            }
        }
    }

    // Above the size for merged runs the planned trees wait packed, those of paths too large to be walked
    // with them (cells of several sizes; one size but a path that turns round obstacles); walked, their
    // paths hold the same points as those of trees kept whole.
    void packedTreesPlanTheSamePaths_data() {
        QTest::addColumn<int>("landCovers");
        QTest::newRow("two sizes") << 2;
        QTest::newRow("one size") << 1;
    }

    void packedTreesPlanTheSamePaths() {
        QFETCH(int, landCovers);
        test::RandomMapSpec spec;
        spec.seed = 4;
        spec.landCovers = landCovers;
        spec.obstacleFraction = 0.1;
        spec.robots = 3;
        const PlanningProblem problem = test::randomProblem(spec);
        const Plan plan = planOf(problem);
        QCOMPARE(plan.cells.hasOneCellSize(), landCovers == 1);
        const SpanningTreeCoverage whole;
        const SpanningTreeCoverage packing(true, 1);
        auto wholeTrees = whole.planTrees(plan.cells, plan.regions, problem.starts, {}, true);
        auto packedTrees = packing.planTrees(plan.cells, plan.regions, problem.starts, {}, true);
        for (const auto& planned : packedTrees) {
            QVERIFY(!planned.walked);
            QVERIFY(planned.tree.packed());
        }
        const auto wholePaths = whole.walkTrees(plan.cells, std::move(wholeTrees), problem.starts, {});
        const auto packedPaths = packing.walkTrees(plan.cells, std::move(packedTrees), problem.starts, {});
        QCOMPARE(packedPaths.size(), wholePaths.size());
        for (std::size_t robot = 0; robot < wholePaths.size(); ++robot) {
            const std::vector<Waypoint> walked = walkedWaypoints(packedPaths[robot], plan.cells);
            QCOMPARE(walked.size(), wholePaths[robot].waypoints.size());
            for (std::size_t i = 0; i < walked.size(); ++i) {
                QCOMPARE(walked[i].x, wholePaths[robot].waypoints[i].x);
                QCOMPARE(walked[i].y, wholePaths[robot].waypoints[i].y);
            }
        }
    }

    // Above the size for merged runs, a path of few waypoints is made while its tree is measured and the
    // tree let go: walkTrees hands over that path, the one the tree's own walk makes. A replanned division
    // walks nothing beyond its shapes.
    void smallPathsAreWalkedWithTheirTrees() {
        auto problem = test::uniformProblem(48, 40, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 47, 39)};
        const Plan plan = planOf(problem);
        const SpanningTreeCoverage large(true, 1);
        auto trees = large.planTrees(plan.cells, plan.regions, problem.starts, {}, true);
        const auto replanned =
            large.replanTrees(plan.cells, plan.regions, RegionAllocation{}, {}, problem.starts, {}, true);
        for (std::size_t robot = 0; robot < trees.size(); ++robot) {
            QVERIFY(trees[robot].walked.has_value());
            QCOMPARE(trees[robot].tree.size(), std::size_t{0});
            QVERIFY(trees[robot].walked->waypoints.size() <=
                    SpanningTreeCoverage::walkedPathLimit(cellsByRobot(plan.regions)[robot].size()));
            QVERIFY(!replanned[robot].walked.has_value());
            QCOMPARE(replanned[robot].shape.seconds(), trees[robot].shape.seconds());
        }
        const auto paths = large.walkTrees(plan.cells, std::move(trees), problem.starts, {});
        const auto cells = cellsByRobot(plan.regions);
        std::vector<int> scratch;
        TreeCircumnavigation walker(plan.cells);
        for (std::size_t robot = 0; robot < paths.size(); ++robot) {
            const SpanningTree tree = large
                                          .bestTree(plan.cells, cells[robot], plan.regions.startCell[robot],
                                                    problem.starts[robot], scratch, true)
                                          .first;
            const CoveragePath expected =
                walker.measuredWalk(tree, static_cast<int>(robot), problem.starts[robot], true);
            QVERIFY2(differenceBetween(paths[robot], expected).isEmpty(),
                     qPrintable(differenceBetween(paths[robot], expected)));
        }
    }

    // Some of those paths put their start point before the walk, so walkFromStart was tried on both kinds.
    void someStartsLayOffTheWalk() { QVERIFY(startsOffTheWalk_ > 0); }

    void singleCellIsASquareTour() {
        auto problem = test::uniformProblem(1, 1, 10.0, {}, {});
        problem.starts = {
            {problem.grid.originX + 2.5, problem.grid.originY - 2.5}}; // the north-west sub-cell centre
        const Plan plan = planOf(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        const CoveragePath& path = plan.paths.front();
        QCOMPARE(path.waypoints.size(), std::size_t{5});
        QCOMPARE(path.lengthMetres, 20.0);
        QCOMPARE(path.turns, 3);
        // 20 m at 1 m/s, and three quarter turns at the automatic 1 s each (1 m/s over 1 m/s2).
        QCOMPARE(path.turnSeconds, 3.0);
        QCOMPARE(path.timeSeconds, 23.0);
    }

    // On a uniform grid a closed STC tour steps FOV metres between sub-cells, 4 per cell.
    void closedTourLengthIsFourStepsPerCell() {
        auto problem = test::uniformProblem(6, 4, 10.0, {}, {});
        problem.starts = {{problem.grid.originX + 2.5, problem.grid.originY - 2.5}};
        Plan plan = planOf(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(plan.paths[0].lengthMetres, 24 * 4 * 5.0);
        QCOMPARE(plan.metrics.ratio, 1.0);
        QCOMPARE(plan.metrics.repeatedFraction, 0.0);
        problem.planner.parameters.set("closed_tour", false);
        plan = planOf(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QCOMPARE(plan.paths[0].lengthMetres, 24 * 4 * 5.0 - 5.0);
        QVERIFY(!plan.paths[0].closed);
    }

    // A two-row strip: east-west spines give a tour with a handful of turns, a comb of north-south
    // edges would give dozens.
    void treeChoiceKeepsTurnsLow() {
        auto problem = test::uniformProblem(12, 2, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0)};
        const Plan plan = planOf(problem);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        QVERIFY2(plan.paths[0].turns <= 10, qPrintable(QString::number(plan.paths[0].turns)));
        QCOMPARE(countTurns(plan.paths[0].waypoints), plan.paths[0].turns);
    }

    // Two walks of 4 m at 1 m/s: an L (one turn) and a staircase (three). Where turns are free they take
    // the same time and the L is quicker for its turns; priced, for its time; a walk twice as fast is
    // quicker whatever it turns; and times a rounding apart are one time.
    void quickerWalksTurnLessAtTheSameTime() {
        const auto walk = [](const std::vector<std::pair<double, double>>& points, double speed,
                             double turnSeconds) {
            PathShape shape;
            for (const auto& [x, y] : points)
                shape.add(x, y, speed, turnSeconds);
            return shape;
        };
        const std::vector<std::pair<double, double>> ell{{0, 0}, {2, 0}, {2, 2}};
        const std::vector<std::pair<double, double>> stairs{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}};
        QCOMPARE(walk(ell, 1.0, 0.0).seconds(), walk(stairs, 1.0, 0.0).seconds());
        QVERIFY(isQuicker(walk(ell, 1.0, 0.0), walk(stairs, 1.0, 0.0)));
        QVERIFY(!isQuicker(walk(stairs, 1.0, 0.0), walk(ell, 1.0, 0.0)));
        QVERIFY(isQuicker(walk(ell, 1.0, 1.0), walk(stairs, 1.0, 1.0)));
        QVERIFY(isQuicker(walk(stairs, 2.0, 0.0), walk(ell, 1.0, 0.0)));
        QVERIFY(!isQuicker(walk(ell, 1.0, 0.0), walk(stairs, 2.0, 0.0)));
        QVERIFY(!isQuicker(walk(ell, 1.0, 0.0), walk(ell, 1.0, 0.0))); // the same walk: neither is
        // A millionth of a micrometre shorter: the same time, so the staircase's turns decide.
        const std::vector<std::pair<double, double>> hairShorterStairs{
            {0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2.0 - 1e-12}};
        QVERIFY(isQuicker(walk(ell, 1.0, 0.0), walk(hairShorterStairs, 1.0, 0.0)));
        QVERIFY(!isQuicker(walk(hairShorterStairs, 1.0, 0.0), walk(ell, 1.0, 0.0)));
    }

    // Three land covers with FOVs 5, 10 and 20 m: connectors join cells of different sizes.
    void mixedSizesVisitEverySubCell() {
        PlanningProblem problem;
        problem.grid.columns = 16;
        problem.grid.rows = 16;
        problem.grid.pixelWidth = 5.0;
        problem.grid.pixelHeight = 5.0;
        problem.grid.values.assign(256, 3);
        for (int row = 0; row < 16; ++row)
            for (int column = 0; column < 16; ++column) {
                if (column < 4 && row < 6)
                    problem.grid.values[problem.grid.index(column, row)] = 1;
                else if (row >= 10 && column >= 8)
                    problem.grid.values[problem.grid.index(column, row)] = 2;
            }
        problem.grid.values[problem.grid.index(2, 12)] = 9;
        problem.classes = ClassTable({{1, "wood", 0, 0.5, 5.0, true},
                                      {2, "grass", 0, 1.0, 10.0, true},
                                      {3, "road", 0, 3.0, 20.0, true},
                                      {9, "pond", 0, 0.0, 5.0, false}});
        problem.starts = {{7.0, -7.0}, {70.0, -70.0}};
        const Plan plan = planOf(problem);
        QCOMPARE(plan.cells.frame().levels, 3);
        QVERIFY2(test::checkAllInvariants(problem, plan).empty(), qPrintable(violations(problem, plan)));
        std::set<int> levels;
        for (const Cell& cell : plan.cells.cells())
            levels.insert(cell.level);
        QCOMPARE(levels.size(), std::size_t{3});
    }

    // A second division keeps the trees of the regions it leaves as they were (taken from the earlier
    // trees, not planned again) and plans the others anew.
    void replannedTreesKeepOnlyUnchangedRegions() {
        auto problem = test::uniformProblem(12, 12, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 0, 0), test::pixelCentre(problem.grid, 11, 0),
                          test::pixelCentre(problem.grid, 6, 11)};
        const Plan plan = planOf(problem);
        const SpanningTreeCoverage coverage;
        const RegionAllocation& earlier = plan.regions;
        const RegionAllocation later = withOneCellMoved(plan.cells, earlier, 0, 1);
        QVERIFY(later.robotOfCell != earlier.robotOfCell);
        const auto earlierTrees = coverage.planTrees(plan.cells, earlier, problem.starts, {}, true);
        const auto laterTrees = coverage.planTrees(plan.cells, later, problem.starts, {}, true);
        // Robot 2's earlier tree stands in for a stranger's: a kept tree must be the one given.
        auto given = earlierTrees;
        given[2] = earlierTrees[0];
        const auto replanned =
            coverage.replanTrees(plan.cells, later, earlier, given, problem.starts, {}, true);
        QCOMPARE(replanned.size(), std::size_t{3});
        QCOMPARE(replanned[2].shape.lengthMetres(), earlierTrees[0].shape.lengthMetres());
        QCOMPARE(replanned[2].shape.turns(), earlierTrees[0].shape.turns());
        for (std::size_t robot : {std::size_t{0}, std::size_t{1}}) {
            QCOMPARE(replanned[robot].shape.lengthMetres(), laterTrees[robot].shape.lengthMetres());
            QCOMPARE(replanned[robot].shape.turns(), laterTrees[robot].shape.turns());
            QVERIFY(replanned[robot].shape.lengthMetres() != earlierTrees[robot].shape.lengthMetres());
        }
    }

  private:
    // `division` with one cell of `from` that touches `to` handed to `to`, `from` staying in one piece.
    static RegionAllocation withOneCellMoved(const CellGraph& cells, const RegionAllocation& division,
                                             int from, int to) {
        for (std::size_t cell = 0; cell < division.robotOfCell.size(); ++cell) {
            if (division.robotOfCell[cell] != from ||
                division.startCell[static_cast<std::size_t>(from)] == static_cast<int>(cell))
                continue;
            const auto around = cells.neighbours(static_cast<int>(cell));
            if (std::none_of(around.begin(), around.end(), [&](int other) {
                    return division.robotOfCell[static_cast<std::size_t>(other)] == to;
                }))
                continue;
            RegionAllocation moved = division;
            moved.robotOfCell[cell] = to;
            if (test::regionIsConnected(cells, moved.robotOfCell, from))
                return moved;
        }
        return division;
    }
};

QTEST_APPLESS_MAIN(SpanningTreeCoverageTest)
#include "test_spanning_tree_coverage.moc"
