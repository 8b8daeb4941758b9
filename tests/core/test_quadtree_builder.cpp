#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "core/decomposition/QuadTreeGridSize.hpp"
#include "core/decomposition/UniformGridDecomposition.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/PlanningError.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <cmath>
#include <cstring>
#include <random>

using namespace mcpp;

namespace {

// A grid of `columns` x `rows` one-metre pixels filled with `value`.
ClassGrid filledGrid(int columns, int rows, std::int32_t value, double pixel = 1.0) {
    ClassGrid grid;
    grid.columns = columns;
    grid.rows = rows;
    grid.pixelWidth = pixel;
    grid.pixelHeight = pixel;
    grid.values.assign(static_cast<std::size_t>(columns * rows), value);
    return grid;
}

// `grid` with only its pixels [firstColumn, endColumn) x [firstRow, endRow) inside the task area.
ClassGrid withAreaOfInterest(ClassGrid grid, int firstColumn, int endColumn, int firstRow, int endRow) {
    grid.outside.assign(grid.values.size(), ClassGrid::outsideArea);
    for (int row = firstRow; row < endRow; ++row)
        for (int column = firstColumn; column < endColumn; ++column)
            grid.outside[grid.index(column, row)] = 0;
    return grid;
}

int countActiveAtLevel(const QuadTree& tree, int level) {
    int count = 0;
    for (int index : tree.activeCells)
        count += tree.cells[static_cast<std::size_t>(index)].level == level ? 1 : 0;
    return count;
}

// Sets the memory budget while it lives and gives the machine's back after, however the test ends.
class BudgetForScope {
  public:
    explicit BudgetForScope(std::int64_t bytes) : machine_(memoryBudgetBytes()) {
        setMemoryBudgetBytes(bytes);
    }
    ~BudgetForScope() { setMemoryBudgetBytes(machine_); }
    BudgetForScope(const BudgetForScope&) = delete;
    BudgetForScope& operator=(const BudgetForScope&) = delete;

  private:
    std::int64_t machine_;
};

} // namespace

class QuadTreeBuilderTest : public QObject {
    Q_OBJECT
  private slots:
    void gridCoversTheMapInWholeTopCells() {
        // FOV 5 m over three levels: bottom cells of 10 m, top cells of 40 m.
        const QuadTreeGridSize exact = quadTreeGridSize(120.0, 80.0, 5.0, 3);
        QCOMPARE(exact.topCellSize, 40.0);
        QCOMPARE(exact.topColumns, 3);
        QCOMPARE(exact.topRows, 2);
        QCOMPARE(exact.bottomColumns, std::int64_t{12});
        QCOMPARE(exact.bottomRows, std::int64_t{8});
        // Rounding noise adds no top cell; a metre more does.
        QCOMPARE(quadTreeGridSize(120.0 + 1e-11, 80.0, 5.0, 3).topColumns, 3);
        QCOMPARE(quadTreeGridSize(121.0, 80.0, 5.0, 3).topColumns, 4);
        // A map smaller than one top cell still has one.
        QCOMPARE(quadTreeGridSize(3.0, 3.0, 5.0, 3).bottomRows, std::int64_t{4});
    }

    // The paper's example: FOVs 5, 7 and 21 m round down to 5, 5 and 20 m, giving three levels.
    void paperFieldOfViewExample() {
        ClassTable table({{1, "farm", 0, 1.0, 5.0, true},
                          {2, "road", 0, 3.0, 7.0, true},
                          {3, "gobi", 0, 2.0, 21.0, true}});
        const auto rounded = roundFieldsOfView(table, {1, 2, 3});
        QCOMPARE(rounded.size(), std::size_t{3});
        QCOMPARE(rounded[0].roundedMetres, 5.0);
        QCOMPARE(rounded[1].roundedMetres, 5.0);
        QCOMPARE(rounded[2].roundedMetres, 20.0);
        QCOMPARE(rounded[0].level, 3);
        QCOMPARE(rounded[2].level, 1);
        // A class absent from the raster does not set the minimum.
        const auto withoutFarm = roundFieldsOfView(table, {2, 3});
        QCOMPARE(withoutFarm[0].roundedMetres, 7.0);
        QCOMPARE(withoutFarm[1].roundedMetres, 14.0);
    }

    void exactPowersOfTwoKeepTheirLevel() {
        ClassTable table(
            {{1, "a", 0, 1.0, 2.5, true}, {2, "b", 0, 1.0, 10.0, true}, {3, "c", 0, 1.0, 40.0, true}});
        const auto rounded = roundFieldsOfView(table, {1, 2, 3});
        QCOMPARE(rounded[1].roundedMetres, 10.0);
        QCOMPARE(rounded[2].roundedMetres, 40.0);
        QCOMPARE(rounded[2].level, 1);
        QCOMPARE(rounded[0].level, 5);
    }

    void singleClassMakesOneLevelOfActiveCells() {
        ClassTable table({{1, "grass", 0, 2.0, 5.0, true}});
        const QuadTree tree = QuadTreeBuilder{}.build(filledGrid(40, 30, 1), table, {});
        QCOMPARE(tree.levels, 1);
        QCOMPARE(tree.topCellSize, 10.0);
        QCOMPARE(tree.topColumns, 4);
        QCOMPARE(tree.topRows, 3);
        QCOMPARE(tree.activeCount(), std::size_t{12});
        for (int index : tree.activeCells) {
            QCOMPARE(tree.cells[static_cast<std::size_t>(index)].speedMetresPerSecond, 2.0);
            QCOMPARE(tree.cells[static_cast<std::size_t>(index)].classValue, 1);
        }
        QCOMPARE(tree.passableAreaSquareMetres, 1200.0);
    }

    // A 40 x 40 m map of a 20 m FOV class with one 10 x 10 m patch of a 5 m FOV class in a corner:
    // only the cells holding the patch split down to the bottom level.
    void threeLevelsSplitOnlyWhereNeeded() {
        ClassTable table({{1, "open", 0, 2.0, 20.0, true}, {2, "wood", 0, 1.0, 5.0, true}});
        ClassGrid grid = filledGrid(40, 40, 1);
        for (int r = 0; r < 10; ++r)
            for (int c = 0; c < 10; ++c)
                grid.values[grid.index(c, r)] = 2;
        const QuadTree tree = QuadTreeBuilder{}.build(grid, table, {});
        QCOMPARE(tree.levels, 3);
        QCOMPARE(tree.topCellSize, 40.0);
        QCOMPARE(countActiveAtLevel(tree, 3), 4); // the north-west quarter as four 10 m cells
        QCOMPARE(countActiveAtLevel(tree, 2), 3); // the other quarters stay 20 m cells
        QCOMPARE(countActiveAtLevel(tree, 1), 0);
        int wood = 0;
        for (int index : tree.activeCells) {
            const QuadCell& cell = tree.cells[static_cast<std::size_t>(index)];
            if (cell.classValue == 2) {
                ++wood;
                QCOMPARE(cell.level, 3);
                QCOMPARE(cell.minX, 0.0);
                QCOMPARE(cell.maxY(), 0.0);
            }
        }
        QCOMPARE(wood, 1);
        // Counted before they are stored: a large map's tree takes no memory beyond its cells (libstdc++
        // reserves exactly what is asked).
        QCOMPARE(tree.cells.size(), std::size_t{1 + 4 + 4});
        QCOMPARE(tree.cells.capacity(), tree.cells.size());
        QCOMPARE(tree.activeCells.capacity(), tree.activeCells.size());
    }

    void harmonicMeanSpeedOfMixedBottomCell() {
        ClassTable table({{1, "road", 0, 4.0, 1.0, true}, {2, "mud", 0, 1.0, 1.0, true}});
        ClassGrid grid = filledGrid(2, 2, 1);
        grid.values[0] = 2; // one pixel of four is mud: harmonic mean 4 / (3/4 + 1/1) = 16/7
        DecompositionOptions settings;
        const QuadTree tree = QuadTreeBuilder{}.build(grid, table, settings);
        QCOMPARE(tree.activeCount(), std::size_t{1});
        const QuadCell& cell = tree.active(0);
        QCOMPARE(cell.classValue, 1);
        QVERIFY(std::abs(cell.speedMetresPerSecond - 16.0 / 7.0) < 1e-12);
    }

    void blockedThresholdDecidesMixedObstacleCells() {
        ClassTable table({{1, "grass", 0, 1.0, 1.0, true}, {9, "rock", 0, 0.0, 1.0, false}});
        ClassGrid grid = filledGrid(2, 2, 1);
        grid.values[0] = 9;
        grid.values[1] = 9; // half obstacle: not more than 50%, so active
        QCOMPARE(QuadTreeBuilder{}.build(grid, table, {}).activeCount(), std::size_t{1});
        grid.values[2] = 9; // three quarters
        DecompositionOptions settings;
        QCOMPARE(QuadTreeBuilder{}.build(grid, table, settings).activeCount(), std::size_t{0});
        settings.blockedThreshold = 0.8;
        QCOMPARE(QuadTreeBuilder{}.build(grid, table, settings).activeCount(), std::size_t{1});
    }

    void purityToleranceIgnoresStrayPixels() {
        ClassTable table({{1, "open", 0, 2.0, 10.0, true}, {2, "wood", 0, 1.0, 5.0, true}});
        ClassGrid grid = filledGrid(20, 20, 1);
        grid.values[grid.index(3, 3)] = 2; // one stray pixel in 400
        const QuadTree strict = QuadTreeBuilder{}.build(grid, table, {});
        QCOMPARE(strict.activeCount(), std::size_t{4});
        DecompositionOptions settings;
        settings.purityTolerance = 0.02;
        const QuadTree tolerant = QuadTreeBuilder{}.build(grid, table, settings);
        QCOMPARE(tolerant.activeCount(), std::size_t{1});
        QVERIFY(tolerant.active(0).speedMetresPerSecond < 2.0); // the stray pixel still slows the cell
    }

    void nodataAndRasterEdgeAreOutside() {
        ClassTable table({{1, "grass", 0, 1.0, 2.0, true}});
        ClassGrid grid = filledGrid(6, 4, 1); // 6 x 4 m, bottom cells of 4 m: the top grid spills over
        grid.outside.assign(grid.values.size(), 0);
        grid.outside[grid.index(0, 0)] = 1;
        const QuadTree tree = QuadTreeBuilder{}.build(grid, table, {});
        QCOMPARE(tree.topColumns, 2);
        QCOMPARE(tree.topRows, 1);
        // Cell 0 has 1 of 16 pixels outside (active); cell 1 is half beyond the raster (blocked? exactly 50%:
        // active).
        QCOMPARE(tree.activeCount(), std::size_t{2});
        QCOMPARE(tree.passableAreaSquareMetres, 23.0);
    }

    // A tree of one level is made as its grid, without nodes; the graph must be the tree's, field for field.
    // A grid of over a million cells is judged in bands of rows side by side: the same at one thread or two.
    void oneLevelGridIsTheTreesGraph_data() {
        QTest::addColumn<int>("columns");
        QTest::addColumn<int>("rows");
        QTest::addColumn<double>("pixel");
        QTest::addColumn<double>("fieldOfView");
        QTest::addRow("37 x 29 pixels, 4 x 4 a cell") << 37 << 29 << 1.0 << 2.0;
        QTest::addRow("1100 x 1000 pixels, one a cell") << 1100 << 1000 << 4.0 << 2.0;
        // Areas of 1.69 m2, which floating point adds up differently in another order.
        QTest::addRow("1100 x 1000 pixels of 1.3 m, one a cell") << 1100 << 1000 << 1.3 << 0.65;
    }

    void oneLevelGridIsTheTreesGraph() {
        QFETCH(int, columns);
        QFETCH(int, rows);
        QFETCH(double, pixel);
        QFETCH(double, fieldOfView);
        ClassTable table({{1, "grass", 0, 1.5, fieldOfView, true},
                          {2, "scrub", 0, 0.7, fieldOfView, true},
                          {9, "lake", 0, 0.0, fieldOfView / 2.0, false}});
        ClassGrid grid =
            filledGrid(columns, rows, 1, pixel); // 4 m cells: the top grid spills over east and south
        grid.originX = 500000.0;
        grid.originY = 4100000.0;
        grid.outside.assign(grid.values.size(), 0);
        std::mt19937 random(11);
        for (std::size_t i = 0; i < grid.values.size(); ++i) {
            const auto draw = random() % 10;
            grid.values[i] = draw < 5 ? 1 : draw < 8 ? 2 : 9;
            grid.outside[i] = random() % 13 == 0 ? 1 : 0;
        }
        DecompositionOptions options;
        options.blockedThreshold = 0.4;
        const QuadTreeLeaves leaves = QuadTreeBuilder{}.buildLeaves(grid, table, options);
        QVERIFY(std::holds_alternative<OneLevelQuadTree>(leaves));
        const CellGraph fromGrid = cellGraphOfLeaves(leaves);
        QuadTree tree = QuadTreeBuilder{}.build(grid, table, options);
        const NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
        const CellGraph fromTree = cellGraphOfQuadTree(std::move(tree), topology);

        const double cellSide = 2.0 * fieldOfView;
        const auto topCells = static_cast<std::size_t>(std::ceil(columns * pixel / cellSide - 1e-9) *
                                                       std::ceil(rows * pixel / cellSide - 1e-9));
        QVERIFY(fromTree.size() > topCells / 4 && fromTree.size() < topCells); // some blocked, most active
        QCOMPARE(fromGrid.size(), fromTree.size());
        QCOMPARE(fromGrid.frame().columns, fromTree.frame().columns);
        QCOMPARE(fromGrid.frame().rows, fromTree.frame().rows);
        QCOMPARE(fromGrid.frame().bottomCellSize, fromTree.frame().bottomCellSize);
        QCOMPARE(fromGrid.passableAreaSquareMetres, fromTree.passableAreaSquareMetres);
        QCOMPARE(fromGrid.fieldsOfView.size(), fromTree.fieldsOfView.size());
        for (int id = 0; id < static_cast<int>(fromTree.size()); ++id) {
            const Cell& a = fromGrid.cell(id);
            const Cell& b = fromTree.cell(id);
            QCOMPARE(a.column, b.column);
            QCOMPARE(a.row, b.row);
            QCOMPARE(a.span, b.span);
            QCOMPARE(a.level, b.level);
            QCOMPARE(a.freeSubCells, b.freeSubCells);
            QCOMPARE(a.classValue, b.classValue);
            QCOMPARE(a.minX, b.minX);
            QCOMPARE(a.minY, b.minY);
            QCOMPARE(a.size, b.size);
            QCOMPARE(a.speedMetresPerSecond, b.speedMetresPerSecond);
            QCOMPARE(a.passableAreaSquareMetres, b.passableAreaSquareMetres);
            const auto gridNeighbours = fromGrid.neighbours(id);
            const auto treeNeighbours = fromTree.neighbours(id);
            QVERIFY(std::equal(gridNeighbours.begin(), gridNeighbours.end(), treeNeighbours.begin(),
                               treeNeighbours.end()));
        }
        for (const int threads : {1, 2}) {
            setWorkerThreads(threads);
            const auto again =
                std::get<OneLevelQuadTree>(QuadTreeBuilder{}.buildLeaves(grid, table, options));
            setWorkerThreads(0);
            const auto& first = std::get<OneLevelQuadTree>(leaves);
            // Bit for bit: QCOMPARE would let the last bits differ.
            QVERIFY(std::memcmp(&again.passableAreaSquareMetres, &first.passableAreaSquareMetres,
                                sizeof(double)) == 0);
            QVERIFY(std::memcmp(&again.areaRounding, &first.areaRounding, sizeof(double)) == 0);
            QCOMPARE(again.cells.size(), first.cells.size());
            QVERIFY(std::memcmp(again.cells.data(), first.cells.data(),
                                first.cells.size() * sizeof(CellRecord)) == 0);
        }
        if (columns >= 100)
            return;
        // Both classes at one size, and a class that needs cells of another: the tree is kept.
        ClassTable twoSizes({{1, "grass", 0, 1.5, 2.0, true},
                             {2, "scrub", 0, 0.7, 4.0, true},
                             {9, "lake", 0, 0.0, 1.0, false}});
        QVERIFY(std::holds_alternative<QuadTree>(QuadTreeBuilder{}.buildLeaves(grid, twoSizes, options)));
    }

    void coarsePixelsAreSampledAtCellCentres() {
        ClassTable table({{1, "grass", 0, 1.0, 2.5, true}, {9, "lake", 0, 0.0, 1.0, false}});
        ClassGrid grid = filledGrid(2, 2, 1, 30.0); // 30 m pixels, 5 m cells
        grid.values[grid.index(1, 1)] = 9;
        const QuadTree tree = QuadTreeBuilder{}.build(grid, table, {});
        QCOMPARE(tree.activeCount(), std::size_t{3 * 36});
        QVERIFY(std::abs(tree.passableAreaSquareMetres - 2700.0) < 1e-6);
    }

    void badInputIsNamed() {
        ClassTable table({{1, "grass", 0, 1.0, 5.0, true}});
        ClassGrid grid = filledGrid(4, 4, 1);
        grid.values[5] = 7;
        try {
            (void)QuadTreeBuilder{}.build(grid, table, {});
            QFAIL("a value missing from the table must be refused");
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::InvalidClassTable);
            QVERIFY2(std::string(error.what()).find("raster value 7") != std::string::npos, error.what());
            QVERIFY2(std::string(error.what()).find("column 1, row 1") != std::string::npos, error.what());
        }
        ClassTable negative({{1, "grass", 0, -1.0, 5.0, true}});
        QVERIFY_THROWS_EXCEPTION(PlanningError,
                                 (void)QuadTreeBuilder{}.build(filledGrid(4, 4, 1), negative, {}));
        ClassTable zeroFov({{1, "grass", 0, 1.0, 0.0, true}});
        QVERIFY_THROWS_EXCEPTION(PlanningError,
                                 (void)QuadTreeBuilder{}.build(filledGrid(4, 4, 1), zeroFov, {}));
        ClassTable nanSpeed({{1, "grass", 0, std::nan(""), 5.0, true}});
        QVERIFY_THROWS_EXCEPTION(PlanningError,
                                 (void)QuadTreeBuilder{}.build(filledGrid(4, 4, 1), nanSpeed, {}));
        ClassTable onlyWater({{1, "water", 0, 0.0, 5.0, false}});
        try {
            (void)QuadTreeBuilder{}.build(filledGrid(4, 4, 1), onlyWater, {});
            QFAIL("a map without passable land must be refused");
        } catch (const PlanningError& error) {
            QCOMPARE(error.kind(), PlanningError::Kind::NoPassableCell);
        }
        ClassTable tinyFov({{1, "grass", 0, 1.0, 1.0, true}});
        try {
            (void)QuadTreeBuilder{}.build(filledGrid(100, 100, 1, 100.0), tinyFov, {});
            QFAIL("a map of millions of bottom cells must be refused before it is built");
        } catch (const PlanningError& error) {
            QVERIFY2(std::string(error.what()).find("5000 x 5000 bottom cells") != std::string::npos,
                     error.what());
        }
        // With less memory the message names the smallest FOV that fits, and that FOV does fit.
        {
            const BudgetForScope small(std::int64_t{400} * 1000 * 1000); // a million bottom cells
            try {
                (void)QuadTreeBuilder{}.build(filledGrid(100, 100, 1, 100.0), tinyFov, {});
                QFAIL("a grid above the memory budget must be refused");
            } catch (const PlanningError& error) {
                const std::string message = error.what();
                QVERIFY2(message.find("10.0 GB of memory") != std::string::npos, error.what());
                QVERIFY2(message.find("this machine allows 0.4 GB") != std::string::npos, error.what());
                const std::string marker = "A smallest field of view of ";
                const auto at = message.find(marker);
                QVERIFY2(at != std::string::npos, error.what());
                const double fitting = std::stod(message.substr(at + marker.size()));
                QVERIFY2(fitting >= 5.0 && fitting <= 5.5,
                         error.what()); // 10 km / 2 FOV <= 1000 cells a side
                ClassTable fittingFov({{1, "grass", 0, 1.0, fitting, true}});
                const QuadTree tree = QuadTreeBuilder{}.build(filledGrid(100, 100, 1, 100.0), fittingFov, {});
                QVERIFY(tree.activeCount() <= 1000000);
            }
        }
        // A small area of interest in a large raster is counted by the top cells that hold it, as the tree
        // is built: 500 m square of a 10 km raster at a 1 m FOV (62 500 cells where the raster's 25 million
        // do not fit).
        {
            const BudgetForScope small(std::int64_t{400} * 1000 * 1000);
            const ClassGrid area = withAreaOfInterest(filledGrid(100, 100, 1, 100.0), 30, 35, 40, 45);
            const QuadTree tree = QuadTreeBuilder{}.build(area, tinyFov, {});
            QCOMPARE(tree.activeCount(), 250 * 250);
            QCOMPARE(tree.originX, 3000.0);
        }
        // Fields of view 2^16 apart need 17 levels, past what a cell's span holds; even where the memory
        // budget would let such a grid through, it is refused by name before any cell is made.
        {
            const BudgetForScope unlimited(std::numeric_limits<std::int64_t>::max());
            ClassTable farApart({{1, "grass", 0, 1.0, 1.0, true}, {2, "sea", 0, 1.0, 65536.0, true}});
            ClassGrid twoClasses = filledGrid(4, 4, 1);
            twoClasses.values[0] = 2;
            try {
                (void)QuadTreeBuilder{}.build(twoClasses, farApart, {});
                QFAIL("17 quadtree levels must be refused");
            } catch (const PlanningError& error) {
                QCOMPARE(error.kind(), PlanningError::Kind::InvalidClassTable);
                QVERIFY2(std::string(error.what()).find("would need 17 levels") != std::string::npos,
                         error.what());
            }
        }
        // With several levels the grid rounds up to whole top cells: the FOV named as fitting is searched on
        // that grid, so a table scaled to it is built (a search without that rounding named 1.6 m, 315 x 315
        // cells, but a quadtree of 25.6 m top cells makes 320 x 320).
        {
            const BudgetForScope small(std::int64_t{40} * 1000 * 1000); // 100 000 cells at 400 bytes
            ClassGrid twoClasses = filledGrid(1000, 1000, 1);
            for (std::size_t pixel = 0; pixel < twoClasses.values.size(); pixel += 7)
                twoClasses.values[pixel] = 2;
            try {
                (void)QuadTreeBuilder{}.build(
                    twoClasses,
                    ClassTable({{1, "grass", 0, 1.0, 1.0, true}, {2, "scrub", 0, 1.0, 8.0, true}}), {});
                QFAIL("a grid above the memory budget must be refused");
            } catch (const PlanningError& error) {
                const std::string message = error.what();
                const std::string marker = "A smallest field of view of ";
                const auto at = message.find(marker);
                QVERIFY2(at != std::string::npos, error.what());
                const double fitting = std::stod(message.substr(at + marker.size()));
                const QuadTree tree =
                    QuadTreeBuilder{}.build(twoClasses,
                                            ClassTable({{1, "grass", 0, 1.0, fitting, true},
                                                        {2, "scrub", 0, 1.0, 8.0 * fitting, true}}),
                                            {});
                QVERIFY(tree.levels == 4);
            }
        }
        // Fields of view far apart make a quadtree whose one top cell is already too much: no FOV is named
        // as fitting, the message says why instead (and is reached at once).
        {
            const BudgetForScope small(std::int64_t{400} * 1000 * 1000);
            ClassGrid twoClasses = filledGrid(100, 100, 1);
            twoClasses.values[0] = 2;
            try {
                (void)QuadTreeBuilder{}.build(
                    twoClasses,
                    ClassTable({{1, "grass", 0, 1.0, 1.0, true}, {2, "sea", 0, 1.0, 4096.0, true}}), {});
                QFAIL("a quadtree of 13 levels cannot fit 0.4 GB");
            } catch (const PlanningError& error) {
                const std::string message = error.what();
                QVERIFY2(message.find(
                             "No field of view fits while the classes' fields of view need a quadtree of 13 "
                             "levels (a top cell spans 4096 bottom cells a side)") != std::string::npos,
                         error.what());
                QVERIFY2(message.find("A smallest field of view") == std::string::npos, error.what());
            }
        }
        // A planner measured at scale declares what it takes per cell, and is held to that figure alone.
        {
            const BudgetForScope small(std::int64_t{300} * 1000 * 1000); // a million cells at 300 bytes
            DecompositionOptions measured;
            measured.bytesPerBottomCell = 250;
            const QuadTree tree = QuadTreeBuilder{}.build(
                filledGrid(1000, 1000, 1, 2.0), ClassTable({{1, "grass", 0, 1.0, 1.0, true}}), measured);
            QCOMPARE(tree.activeCount(), std::size_t{1000000});
            QVERIFY_THROWS_EXCEPTION(
                PlanningError, (void)QuadTreeBuilder{}.build(filledGrid(1000, 1000, 1, 2.0),
                                                             ClassTable({{1, "grass", 0, 1.0, 1.0, true}}),
                                                             DecompositionOptions{}));
        }
        DecompositionOptions badPurity;
        badPurity.purityTolerance = std::nan("");
        QVERIFY_THROWS_EXCEPTION(PlanningError,
                                 (void)QuadTreeBuilder{}.build(filledGrid(4, 4, 1), table, badPurity));
    }

    // Each planner is refused by its own figure: MCPP-MLCT, measured on large maps, plans a grid that a
    // planner at the unmeasured figure is refused, with the memory message.
    void plannersAreHeldToTheirOwnMemoryFigure() {
        const std::int64_t mlctBytes = findPlannerDescription("mcpp-mlct")->bytesPerBottomCell;
        QVERIFY(mlctBytes < unmeasuredBytesPerBottomCell);
        QCOMPARE(findPlannerDescription("darp")->bytesPerBottomCell, unmeasuredBytesPerBottomCell);
        QCOMPARE(leastBytesPerBottomCell(), mlctBytes);
        PlanningProblem problem = test::obstacleGridProblem(49, 2, 2020); // 49 x 49 cells of 10 m
        const std::int64_t cells = 49 * 49;
        const BudgetForScope between(cells * (mlctBytes + unmeasuredBytesPerBottomCell) / 2);
        for (const std::string name : {"mcpp-mlct", "darp"}) {
            problem.planner = defaultPlannerChoice(name);
            try {
                const Plan plan = makePlanner(name)->plan(problem, {});
                QVERIFY2(name == "mcpp-mlct", name.c_str());
                QCOMPARE(plan.paths.size(), std::size_t{2});
            } catch (const PlanningError& error) {
                QVERIFY2(name == "darp", error.what());
                QVERIFY2(std::string(error.what()).find("49 x 49 bottom cells") != std::string::npos,
                         error.what());
            }
        }
    }

    // The grid planners' uniform grid spans the cells over the task area, as the quadtree does: the same
    // cells, square for square, as over a raster cut to that window, and a small area of interest in a large
    // raster is planned where its whole raster would be refused.
    void aUniformGridSpansTheTaskArea() {
        const ClassTable grass({{1, "grass", 0, 1.0, 1.0, true}, {2, "rock", 0, 0.0, 1.0, false}});
        // One-metre pixels serve as samples (FOV 1 m, cells of 2 m): an area from an odd pixel, a rock in it.
        ClassGrid map = withAreaOfInterest(filledGrid(400, 400, 1), 101, 151, 201, 261);
        map.originX = 1000.0;
        map.originY = 9000.0;
        map.values[map.index(120, 230)] = 2;
        // The window: cells from column 50 (even) to 76 and rows 100 to 131, pixels 100-152 and 200-262.
        ClassGrid cut = filledGrid(52, 62, 1);
        cut.originX = 1100.0;
        cut.originY = 8800.0;
        cut.outside.assign(cut.values.size(), 0);
        for (int row = 0; row < cut.rows; ++row)
            for (int column = 0; column < cut.columns; ++column) {
                cut.values[cut.index(column, row)] = map.valueAt(column + 100, row + 200);
                cut.outside[cut.index(column, row)] = map.outside[map.index(column + 100, row + 200)];
            }
        for (const GridCellRule rule :
             {GridCellRule::WholeCell, GridCellRule::AllSubCellsFree, GridCellRule::AnySubCellFree}) {
            const UniformGridDecomposition decomposition({}, rule);
            const CellGraph inMap = decomposition.decompose(map, grass);
            const CellGraph inCut = decomposition.decompose(cut, grass);
            QCOMPARE(inMap.frame().columns, 26);
            QCOMPARE(inMap.frame().rows, 31);
            QCOMPARE(inMap.frame().originX, 1100.0);
            QCOMPARE(inMap.frame().originY, 8800.0);
            QVERIFY(inMap.size() >= 24 * 29 - 1); // the cells wholly inside, but the rock's
            QCOMPARE(inMap.size(), inCut.size());
            for (int id = 0; id < static_cast<int>(inMap.size()); ++id) {
                const Cell a = inMap.cell(id);
                const Cell b = inCut.cell(id);
                QCOMPARE(a.minX, b.minX);
                QCOMPARE(a.minY, b.minY);
                QCOMPARE(a.freeSubCells, b.freeSubCells);
                QCOMPARE(a.passableAreaSquareMetres, b.passableAreaSquareMetres);
                QCOMPARE(inMap.neighbours(id).size(), inCut.neighbours(id).size());
            }
            QCOMPARE(inMap.passableAreaSquareMetres, inCut.passableAreaSquareMetres);
            QVERIFY(std::abs(inMap.passableAreaSquareMetres - 2999.0) < 1e-6 * 2999.0);
        }
        // Pixels larger than the cells are sampled at the cells' centres: a 500 m area of a 10 km raster at a
        // 1 m FOV is 250 x 250 cells where the raster's 5000 x 5000 do not fit.
        const BudgetForScope small(std::int64_t{400} * 1000 * 1000);
        ClassGrid large = withAreaOfInterest(filledGrid(100, 100, 1, 100.0), 30, 35, 40, 45);
        const CellGraph area = UniformGridDecomposition({}, GridCellRule::WholeCell).decompose(large, grass);
        QCOMPARE(area.size(), std::size_t{250 * 250});
        QCOMPARE(area.frame().originX, 3000.0);
        QCOMPARE(area.frame().originY, -4000.0);
        QVERIFY(std::abs(area.passableAreaSquareMetres - 250000.0) < 1e-6 * 250000.0);
        large.outside.clear();
        QVERIFY_THROWS_EXCEPTION(
            PlanningError,
            (void)UniformGridDecomposition({}, GridCellRule::WholeCell).decompose(large, grass));
    }
};

QTEST_APPLESS_MAIN(QuadTreeBuilderTest)
#include "test_quadtree_builder.moc"
