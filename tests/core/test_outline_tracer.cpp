// Region outlines traced on a label grid: hand-made shapes (holes, corner contacts, a hole pinched at a
// corner) and random grids, checked against the pixels themselves: every pixel centre lies in the polygon of
// its own patch and in no other, areas equal pixel counts, rings are simple and keep their orientation.

#include "core/model/ParallelFor.hpp"
#include "core/outlines/OutlineTracer.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QTest>
#include <map>
#include <random>
#include <set>
#include <string>

using namespace mcpp;

namespace {

// Rows of characters: '.' no label, a digit its label.
LabelGrid gridOf(const std::vector<std::string>& rows) {
    LabelGrid grid;
    grid.rows = static_cast<int>(rows.size());
    grid.columns = static_cast<int>(rows.front().size());
    for (const std::string& row : rows)
        for (const char c : row)
            grid.labels.push_back(c == '.' ? LabelGrid::noLabel : c - '0');
    return grid;
}

bool inRing(const OutlineRing& ring, double x, double y) {
    bool result = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const double xi = ring[i].column, yi = ring[i].row, xj = ring[j].column, yj = ring[j].row;
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
            result = !result;
    }
    return result;
}

bool inPolygon(const OutlinePolygon& polygon, double x, double y) {
    if (!inRing(polygon.exterior, x, y))
        return false;
    for (const OutlineRing& hole : polygon.holes)
        if (inRing(hole, x, y))
            return false;
    return true;
}

// A simple ring of grid corners: axis-parallel edges, no straight-through vertex, no vertex twice.
std::string ringProblem(const OutlineRing& ring) {
    std::set<std::pair<int, int>> seen;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const GridVertex a = ring[i], b = ring[(i + 1) % ring.size()], c = ring[(i + 2) % ring.size()];
        if (!seen.insert({a.column, a.row}).second)
            return "a ring passes a vertex twice";
        if (a.column != b.column && a.row != b.row)
            return "an edge is not along the grid";
        if ((a.column == b.column && b.column == c.column) || (a.row == b.row && b.row == c.row))
            return "a vertex is not a corner";
    }
    return {};
}

// Every property the exporters rely on; returns an empty string or what is wrong.
std::string check(const LabelGrid& grid, const std::vector<OutlinePolygon>& polygons) {
    std::map<std::int32_t, std::int64_t> pixelsOfLabel, areaOfLabel;
    for (const std::int32_t label : grid.labels)
        if (label != LabelGrid::noLabel)
            ++pixelsOfLabel[label];
    for (const OutlinePolygon& polygon : polygons) {
        std::int64_t twiceArea = doubledSignedArea(polygon.exterior);
        if (twiceArea <= 0)
            return "an exterior is not counter-clockwise";
        for (const OutlineRing& hole : polygon.holes) {
            if (doubledSignedArea(hole) >= 0)
                return "a hole is not clockwise";
            twiceArea += doubledSignedArea(hole);
        }
        if (twiceArea != 2 * polygon.pixels)
            return "a polygon's area differs from its pixel count";
        areaOfLabel[polygon.label] += polygon.pixels;
        std::vector<const OutlineRing*> rings{&polygon.exterior};
        for (const OutlineRing& hole : polygon.holes)
            rings.push_back(&hole);
        for (const OutlineRing* ring : rings) {
            if (const std::string problem = ringProblem(*ring); !problem.empty())
                return problem;
        }
    }
    if (areaOfLabel != pixelsOfLabel)
        return "the polygons of a label do not add up to its pixels";
    for (int row = 0; row < grid.rows; ++row) {
        for (int column = 0; column < grid.columns; ++column) {
            const std::int32_t label = grid.at(column, row);
            int holders = 0;
            for (const OutlinePolygon& polygon : polygons) {
                if (!inPolygon(polygon, column + 0.5, row + 0.5))
                    continue;
                ++holders;
                if (polygon.label != label)
                    return "pixel " + std::to_string(column) + "," + std::to_string(row) +
                           " lies in a polygon of another label";
            }
            if (holders != (label == LabelGrid::noLabel ? 0 : 1))
                return "pixel " + std::to_string(column) + "," + std::to_string(row) + " lies in " +
                       std::to_string(holders) + " polygons";
        }
    }
    return {};
}

} // namespace

class OutlineTracerTest : public QObject {
    Q_OBJECT

  private slots:
    void oneSquareHasFourCorners() {
        const LabelGrid grid = gridOf({"...", ".0.", "..."});
        const auto polygons = traceOutlines(grid);
        QCOMPARE(polygons.size(), std::size_t{1});
        QCOMPARE(polygons[0].exterior.size(), std::size_t{4});
        QCOMPARE(polygons[0].pixels, std::int64_t{1});
        QVERIFY(polygons[0].holes.empty());
        const std::string problem = check(grid, polygons);
        QVERIFY2(problem.empty(), problem.c_str());
    }

    void straightRunsKeepOnlyCorners() {
        const LabelGrid grid = gridOf({"0000000", "0000000", "00....."});
        const auto polygons = traceOutlines(grid);
        QCOMPARE(polygons.size(), std::size_t{1});
        QCOMPARE(polygons[0].exterior.size(), std::size_t{6}); // an L: six corners whatever its size
        const std::string problem = check(grid, polygons);
        QVERIFY2(problem.empty(), problem.c_str());
    }

    void ringWithAHoleAndAnIslandInIt() {
        const LabelGrid grid = gridOf({"00000", "0...0", "0.1.0", "0...0", "00000"});
        const auto polygons = traceOutlines(grid);
        QCOMPARE(polygons.size(), std::size_t{2});
        QCOMPARE(polygons[0].label, 0);
        QCOMPARE(polygons[0].holes.size(), std::size_t{1});
        QCOMPARE(polygons[1].label, 1);
        const std::string problem = check(grid, polygons);
        QVERIFY2(problem.empty(), problem.c_str());
    }

    void cornerContactMakesTwoPatches() {
        const LabelGrid grid = gridOf({"0.", ".0"});
        const auto polygons = traceOutlines(grid);
        QCOMPARE(polygons.size(), std::size_t{2});
        const std::string problem = check(grid, polygons);
        QVERIFY2(problem.empty(), problem.c_str());
    }

    void holePinchedAtACornerIsSplitOff() {
        // The hole at (1,1) touches the outside only at its south-west corner: the walk around the patch
        // would pass that corner twice, so the hole comes out as a hole ring of its own.
        const LabelGrid grid = gridOf({"000", "0.0", ".00"});
        const auto polygons = traceOutlines(grid);
        QCOMPARE(polygons.size(), std::size_t{1});
        QCOMPARE(polygons[0].holes.size(), std::size_t{1});
        QCOMPARE(polygons[0].holes[0].size(), std::size_t{4});
        const std::string problem = check(grid, polygons);
        QVERIFY2(problem.empty(), problem.c_str());
    }

    void randomGrids_data() {
        QTest::addColumn<int>("seed");
        QTest::addColumn<int>("labels");
        QTest::addColumn<double>("emptyShare");
        for (int seed = 1; seed <= 40; ++seed)
            QTest::addRow("seed %d", seed) << seed << 1 + seed % 4 << 0.1 * (seed % 6);
    }

    void randomGrids() {
        QFETCH(int, seed);
        QFETCH(int, labels);
        QFETCH(double, emptyShare);
        std::mt19937 random(static_cast<unsigned>(seed));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        LabelGrid grid;
        grid.columns = 5 + seed % 17;
        grid.rows = 4 + seed % 13;
        for (int i = 0; i < grid.columns * grid.rows; ++i) {
            grid.labels.push_back(unit(random) < emptyShare
                                      ? LabelGrid::noLabel
                                      : static_cast<std::int32_t>(random() % static_cast<unsigned>(labels)));
        }
        const std::string problem = check(grid, traceOutlines(grid));
        QVERIFY2(problem.empty(), problem.c_str());
    }

    // Grids wide enough that the tracer skips chunks of 32 pixels of a region's inside: rectangles of
    // labels, empty ones among them, and single pixels about columns 32, 64 and 96.
    void wideGrids_data() {
        QTest::addColumn<int>("seed");
        for (int seed = 1; seed <= 12; ++seed)
            QTest::addRow("seed %d", seed) << seed;
    }

    void wideGrids() {
        QFETCH(int, seed);
        std::mt19937 random(static_cast<unsigned>(seed));
        LabelGrid grid;
        grid.columns = 100 + 7 * seed;
        grid.rows = 12 + seed % 5;
        grid.labels.assign(static_cast<std::size_t>(grid.columns * grid.rows), 0);
        const auto label = [&] { return static_cast<LabelGrid::Label>(static_cast<int>(random() % 4) - 1); };
        for (int rectangle = 0; rectangle < 6; ++rectangle) {
            const int west = static_cast<int>(random() % static_cast<unsigned>(grid.columns - 10));
            const int north = static_cast<int>(random() % static_cast<unsigned>(grid.rows - 3));
            const int width = 1 + static_cast<int>(random() % 60U);
            const int height = 1 + static_cast<int>(random() % 6U);
            const LabelGrid::Label value = label();
            for (int row = north; row < std::min(grid.rows, north + height); ++row)
                for (int column = west; column < std::min(grid.columns, west + width); ++column)
                    grid.labels[grid.index(column, row)] = value;
        }
        for (const int column : {31, 32, 33, 63, 64, 65, 96, 97})
            grid.labels[grid.index(
                column, 1 + static_cast<int>(random() % static_cast<unsigned>(grid.rows - 2)))] = label();
        const std::string problem = check(grid, traceOutlines(grid));
        QVERIFY2(problem.empty(), problem.c_str());
    }

    // The walks around a strip inside a wide patch begin at the first side of them met row by row: the
    // bottom of the pixel above the strip's west end and the bottom of the strip's west end, each walked
    // east to the strip's east end.
    void ringsBeginAtTheFirstSideMetRowByRow() {
        LabelGrid grid;
        grid.columns = 100;
        grid.rows = 9;
        grid.labels.assign(static_cast<std::size_t>(grid.columns * grid.rows), 0);
        for (int column = 40; column <= 60; ++column)
            grid.labels[grid.index(column, 5)] = 1;
        const auto polygons = traceOutlines(grid);
        QCOMPARE(polygons.size(), std::size_t{2});
        QCOMPARE(polygons[0].holes.size(), std::size_t{1});
        const OutlineRing& hole = polygons[0].holes[0];
        QCOMPARE(hole.front().column, 61);
        QCOMPARE(hole.front().row, 5);
        QCOMPARE(polygons[1].exterior.front().column, 61);
        QCOMPARE(polygons[1].exterior.front().row, 6);
    }

    // A plan of more cells than one thread labels at a time (2^16): each free sub-cell's pixel holds its
    // robot, blocked sub-cells and obstacles none, whatever the number of threads.
    void regionLabelsOfALargePlan() {
        const CellGraph whole = test::cellPerPixelGraph(test::obstacleGridProblem(300, 2, 5));
        // One cell in seven with a sub-cell blocked.
        std::vector<Cell> cells;
        for (std::size_t id = 0; id < whole.size(); ++id) {
            cells.push_back(whole.cell(static_cast<int>(id)));
            if (id % 7 == 0)
                cells.back().freeSubCells = allSubCells & ~(1U << static_cast<unsigned>(id / 7 % 4));
        }
        Plan plan;
        plan.cells = CellGraph(whole.frame(), cells, whole.neighbourLists());
        QVERIFY(plan.cells.size() > std::size_t{1} << 16);
        plan.regions.robotOfCell.resize(plan.cells.size());
        for (std::size_t id = 0; id < plan.cells.size(); ++id) {
            const CellRecord& cell = plan.cells.record(static_cast<int>(id));
            plan.regions.robotOfCell[id] = (cell.row / 37 + cell.column / 53) % 6 - 1; // -1: unreachable
        }
        std::vector<LabelGrid::Label> expected(static_cast<std::size_t>(2 * 300 * 2 * 300),
                                               LabelGrid::noLabel);
        for (std::size_t id = 0; id < plan.cells.size(); ++id) {
            const Cell cell = plan.cells.cell(static_cast<int>(id));
            const int robot = plan.regions.robotOfCell[id];
            const auto value = static_cast<LabelGrid::Label>(robot >= 0 ? robot : unreachableLabel);
            for (const SubCell subCell : subCellsCounterClockwise) {
                const MapPoint centre = cell.subCellCentre(subCell);
                const auto column = static_cast<std::size_t>((centre.x - plan.cells.frame().originX) / 5.0);
                const auto row = static_cast<std::size_t>((plan.cells.frame().originY - centre.y) / 5.0);
                if (cell.isFree(subCell))
                    expected[row * 600 + column] = value;
            }
        }
        for (const int threads : {1, 2}) {
            setWorkerThreads(threads);
            const LabelGrid labels = regionLabels(plan);
            QCOMPARE(labels.columns, 600);
            QCOMPARE(labels.rows, 600);
            QCOMPARE(labels.labels, expected);
        }
        setWorkerThreads(0);
    }

    void planRegionsOnTheSubCellGrid() {
        // Two cells of a 2 x 1 bottom grid: robot 0 with its south-east sub-cell blocked, robot 1 all free.
        Plan plan;
        GridFrame frame;
        frame.originX = 100.0;
        frame.originY = 50.0;
        frame.bottomCellSize = 10.0;
        frame.columns = 2;
        frame.rows = 1;
        Cell first;
        first.column = 0;
        first.size = 10.0;
        first.freeSubCells = allSubCells & ~(1U << static_cast<unsigned>(SubCell::SouthEast));
        Cell second = first;
        second.column = 1;
        second.freeSubCells = allSubCells;
        plan.cells = CellGraph(frame, {first, second}, NeighbourTopology({0, 1, 2}, {1, 0}));
        plan.regions.robotOfCell = {0, -1};
        const LabelGrid labels = regionLabels(plan);
        QCOMPARE(labels.columns, 4);
        QCOMPARE(labels.rows, 2);
        QCOMPARE(labels.pixelSize, 5.0);
        const LabelGrid::Label unreachable = unreachableLabel;
        const std::vector<LabelGrid::Label> expected{
            0, 0, unreachable, unreachable, 0, LabelGrid::noLabel, unreachable, unreachable};
        QCOMPARE(labels.labels, expected);
        QCOMPARE(labels.x(4), 120.0);
        QCOMPARE(labels.y(2), 40.0);
    }

    // A small area on a large raster: the grid holds the box around the plan's cells, not the whole frame,
    // and stays on the frame's sub-cell lattice.
    void planRegionsCroppedToTheirCells() {
        Plan plan;
        GridFrame frame;
        frame.originX = 100.0;
        frame.originY = 500.0;
        frame.bottomCellSize = 10.0;
        frame.columns = 40;
        frame.rows = 30;
        Cell first;
        first.column = 3;
        first.row = 7;
        first.size = 10.0;
        first.freeSubCells = allSubCells;
        Cell second = first;
        second.column = 4;
        plan.cells = CellGraph(frame, {first, second}, NeighbourTopology({0, 1, 2}, {1, 0}));
        plan.regions.robotOfCell = {1, 0};
        const LabelGrid labels = regionLabels(plan);
        QCOMPARE(labels.columns, 4);
        QCOMPARE(labels.rows, 2);
        QCOMPARE(labels.originX, 130.0);
        QCOMPARE(labels.originY, 430.0);
        const std::vector<LabelGrid::Label> expected{1, 1, 0, 0, 1, 1, 0, 0};
        QCOMPARE(labels.labels, expected);
    }
};

QTEST_GUILESS_MAIN(OutlineTracerTest)
#include "test_outline_tracer.moc"
