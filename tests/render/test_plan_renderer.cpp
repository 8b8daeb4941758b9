#include "core/coverage/ImpassableCrossings.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "render/MapDecorations.hpp"
#include "render/PlanFrame.hpp"
#include "render/PlanImage.hpp"
#include "render/PlanLegend.hpp"
#include "render/PlanRenderer.hpp"
#include "render/PlanSheet.hpp"
#include "render/PreparedPictureMemory.hpp"
#include "render/RobotPalette.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QFile>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <QtTest>

using namespace mcpp;

namespace {

// One robot's path through `points` in `sorties` from a charger.
Plan sortiePlan(const std::vector<std::pair<double, double>>& points, MapPoint charger,
                std::vector<Sortie> sorties) {
    Plan plan;
    plan.planner = "test";
    CoveragePath path;
    for (const auto& [x, y] : points) {
        Waypoint waypoint;
        waypoint.x = x;
        waypoint.y = y;
        path.waypoints.push_back(waypoint);
    }
    plan.paths.push_back(path);
    RobotSorties robot;
    robot.charger = charger;
    robot.sorties = std::move(sorties);
    plan.layers.push_back(std::make_shared<SortieLayer>(std::vector<RobotSorties>{robot}));
    return plan;
}

constexpr std::uint32_t kMeadow = 0x40a040;
constexpr std::uint32_t kWater = 0x2060c0;

// 20 x 10 pixels of 10 m: meadow (1) on the west half, water (2) on the east half.
ClassGrid twoClassGrid() {
    ClassGrid grid = test::filledGrid(20, 10, 1000.0, 5000.0, 10.0, 1);
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column)
            grid.values[grid.index(column, row)] = column < 10 ? 1 : 2;
    return grid;
}

ClassTable twoClassTable() {
    return ClassTable({LandCoverClass{1, "Meadow", kMeadow, 2.0, 10.0, true},
                       LandCoverClass{2, "Water", kWater, 0.0, 10.0, false}});
}

// One robot going east along y = 4950 (the middle row) across the meadow half.
Plan eastboundPlan() {
    Plan plan;
    plan.planner = "test";
    CoveragePath path;
    path.robot = 0;
    path.closed = false;
    for (double x : {1005.0, 1050.0, 1095.0}) {
        Waypoint waypoint;
        waypoint.x = x;
        waypoint.y = 4950.0;
        path.waypoints.push_back(waypoint);
    }
    plan.paths.push_back(path);
    return plan;
}

bool near(QColor actual, QColor expected, int tolerance = 8) {
    return std::abs(actual.red() - expected.red()) <= tolerance &&
           std::abs(actual.green() - expected.green()) <= tolerance &&
           std::abs(actual.blue() - expected.blue()) <= tolerance;
}

// Scattered water pixels on grass, sub-cells of 2 x 2 pixels: a sub-cell with one water pixel in four is
// kept (25 % < the 50 % blocked threshold), so the path crosses water there.
struct CrossingScene {
    PlanningProblem problem;
    Plan plan;
};

CrossingScene crossingScene() {
    const test::RandomMapSpec spec = test::waterCrossingSpec();
    CrossingScene scene{test::randomProblem(spec), {}};
    scene.problem.planner = defaultPlannerChoice("mcpp-mlct");
    scene.plan = makePlanner("mcpp-mlct")->plan(scene.problem, {});
    return scene;
}

// Two 100 m cells side by side, west at (1000, 4900): image x 10-190 and 210-390 at 400 x 200 pixels.
Plan twoCellPlan() {
    Plan plan;
    GridFrame frame;
    frame.originX = 1000.0;
    frame.originY = 5000.0;
    frame.bottomCellSize = 100.0;
    frame.columns = 2;
    frame.rows = 1;
    Cell west;
    west.minX = 1000.0;
    west.minY = 4900.0;
    west.size = 100.0;
    west.speedMetresPerSecond = 1.0;
    Cell east = west;
    east.column = 1;
    east.minX = 1100.0;
    plan.cells = CellGraph(frame, {west, east}, NeighbourTopology({0, 1, 2}, {1, 0}));
    return plan;
}

// Three columns and two rows of 80 m cells from (1000, 5000), all robot 0's: over the 200 x 100 m raster
// of twoClassGrid they reach 40 m past its east edge and 60 m past its south edge.
Plan overhangingPlan() {
    Plan plan;
    GridFrame frame;
    frame.originX = 1000.0;
    frame.originY = 5000.0;
    frame.bottomCellSize = 80.0;
    frame.columns = 3;
    frame.rows = 2;
    std::vector<Cell> cells;
    std::vector<int> offsets{0};
    std::vector<int> neighbours;
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 3; ++column) {
            Cell cell;
            cell.column = column;
            cell.row = row;
            cell.minX = 1000.0 + 80.0 * column;
            cell.minY = 5000.0 - 80.0 * (row + 1);
            cell.size = 80.0;
            cell.speedMetresPerSecond = 1.0;
            cells.push_back(cell);
            for (const auto& [dc, dr] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}})
                if (column + dc >= 0 && column + dc < 3 && row + dr >= 0 && row + dr < 2)
                    neighbours.push_back((row + dr) * 3 + column + dc);
            offsets.push_back(static_cast<int>(neighbours.size()));
        }
    plan.cells =
        CellGraph(frame, std::move(cells), NeighbourTopology(std::move(offsets), std::move(neighbours)));
    plan.regions.robotOfCell.assign(6, 0);
    return plan;
}

} // namespace

class TestPlanRenderer : public QObject {
    Q_OBJECT

  private slots:
    // The north arrow points to true north: up on a grid that is, to the right where true north lies a
    // quarter turn clockwise of the grid's (trueNorthRadians -pi/2).
    void northArrowPointsToTrueNorth() {
        const auto inkedBox = [](double trueNorthRadians) {
            QImage image(80, 80, QImage::Format_ARGB32);
            image.fill(Qt::white);
            QPainter painter(&image);
            render::paintNorthArrow(painter, QPointF(40, 22), trueNorthRadians);
            painter.end();
            int left = 80, right = -1, top = 80, bottom = -1;
            for (int y = 0; y < 80; ++y)
                for (int x = 0; x < 80; ++x)
                    if (qGray(image.pixel(x, y)) < 128) {
                        left = std::min(left, x);
                        right = std::max(right, x);
                        top = std::min(top, y);
                        bottom = std::max(bottom, y);
                    }
            return QRect(QPoint(left, top), QPoint(right, bottom));
        };
        const QRect up = inkedBox(0.0);
        QVERIFY2(up.height() > up.width(),
                 qPrintable(QStringLiteral("%1 x %2").arg(up.width()).arg(up.height())));
        QVERIFY2(std::abs(up.top() - 22) <= 1, qPrintable(QString::number(up.top()))); // the tip at the top
        const QRect right = inkedBox(-std::acos(-1.0) / 2.0);
        QVERIFY2(right.width() > right.height(),
                 qPrintable(QStringLiteral("%1 x %2").arg(right.width()).arg(right.height())));
        QVERIFY2(right.right() >= 40 + 17,
                 qPrintable(QString::number(right.right()))); // the tip on the right
    }

    // A plan over the whole raster shows all of it; one over a small part (an area of interest) shows that
    // part with a fifth of its extent around it, in whole pixels of the raster.
    void aSmallPlanIsFramedWithAMargin() {
        const ClassGrid grid = twoClassGrid(); // x 1000-1200, y 4900-5000, 10 m pixels
        const Plan whole = twoCellPlan();
        const ClassGrid wholeFrame = render::planFrame(grid, {&whole});
        QCOMPARE(wholeFrame.columns, grid.columns);
        QCOMPARE(wholeFrame.rows, grid.rows);
        QCOMPARE(wholeFrame.originX, grid.originX);
        QCOMPARE(wholeFrame.originY, grid.originY);
        QVERIFY(wholeFrame.values.empty());

        Plan small;
        GridFrame frame;
        frame.originX = 1100.0;
        frame.originY = 4960.0;
        frame.bottomCellSize = 20.0;
        frame.columns = 1;
        frame.rows = 1;
        Cell cell; // x 1100-1120, y 4940-4960: 10 m of margin (a twentieth of 200 m) reach x 1090-1130
        cell.minX = 1100.0;
        cell.minY = 4940.0;
        cell.size = 20.0;
        cell.speedMetresPerSecond = 1.0;
        small.cells = CellGraph(frame, {cell}, NeighbourTopology({0, 0}, {}));
        const ClassGrid smallFrame = render::planFrame(grid, {&small});
        QCOMPARE(smallFrame.originX, 1090.0);
        QCOMPARE(smallFrame.originY, 4970.0);
        QCOMPARE(smallFrame.columns, 4);
        QCOMPARE(smallFrame.rows, 4);
        // A flight-reach ring crossing the cell is taken in where it reaches no further than the plan's
        // extent again on each side (x 1080-1140, y 4920-4980); a ring of a kilometre would shrink the plan
        // to a dot, and one round the whole cell has nothing beyond it to show: both are left to the frame's
        // edge.
        QCOMPARE(render::planFrame(grid, {&small}, {{{1110.0, 4950.0}, 0.0}}).columns, 4);
        const ClassGrid ringed = render::planFrame(grid, {&small}, {{{1105.0, 4945.0}, 18.0}});
        QCOMPARE(ringed.originX, 1080.0); // the ring reaches x 1086.5, past the margin's 1090
        QCOMPARE(ringed.originY, 4970.0);
        QCOMPARE(ringed.columns, 5);
        QCOMPARE(ringed.rows, 5);
        QCOMPARE(render::planFrame(grid, {&small}, {{{1110.0, 4950.0}, 25.0}}).columns, 4); // round it all
        QCOMPARE(render::planFrame(grid, {&small}, {{{1110.0, 4950.0}, 1000.0}}).columns, 4);
        // Its outline shows in the frame (x 1090-1130, y 4930-4970) when it crosses it: not wholly round
        // it, nor wholly beside it.
        QVERIFY(render::someRingShows(smallFrame, {{{1110.0, 4950.0}, 25.0}}));
        QVERIFY(render::someRingShows(smallFrame, {{{1110.0, 4950.0}, 15.0}}));
        QVERIFY(!render::someRingShows(smallFrame, {{{1110.0, 4950.0}, 1000.0}}));
        QVERIFY(!render::someRingShows(smallFrame, {{{1160.0, 4950.0}, 25.0}}));
        QVERIFY(render::someRingShows(smallFrame, {{{1160.0, 4950.0}, 35.0}}));
        QVERIFY(!render::someRingShows(smallFrame, {{{1110.0, 4950.0}, 0.0}}));
        QVERIFY(render::someRingShows(smallFrame, {{{1160.0, 4950.0}, 25.0}, {{1110.0, 4950.0}, 15.0}}));
        // On a raster twenty times as wide, a twentieth of it (100 m) would shrink the cell to a speck: the
        // margin stays within a quarter of the plan's extent (5 m; 10 m in whole pixels), as above.
        ClassGrid wide = grid;
        wide.columns *= 20;
        wide.rows *= 20;
        wide.originY = grid.originY + 1000.0; // x 1000-5000, y 4000-6000 round the cell
        wide.values.assign(static_cast<std::size_t>(wide.columns) * static_cast<std::size_t>(wide.rows), 1);
        const ClassGrid wideFrame = render::planFrame(wide, {&small});
        QCOMPARE(wideFrame.originX, 1090.0);
        QCOMPARE(wideFrame.columns, 4);
        // Several plans share one frame that holds them all; none at all shows the raster.
        QCOMPARE(render::planFrame(grid, {&small, &whole}).columns, grid.columns);
        QCOMPARE(render::planFrame(grid, {nullptr}).columns, grid.columns);

        // Before any plan, a view fits the area of interest the same way: its pixels x 1100-1120,
        // y 4940-4960 are framed as that cell is.
        ClassGrid withArea = grid;
        QCOMPARE(render::taskAreaFrame(withArea).columns, grid.columns); // no area: the whole raster
        withArea.outside.assign(grid.values.size(), ClassGrid::outsideArea);
        for (int row = 4; row < 6; ++row)
            for (int column = 10; column < 12; ++column)
                withArea.outside[withArea.index(column, row)] = 0;
        const ClassGrid areaFrame = render::taskAreaFrame(withArea);
        QCOMPARE(areaFrame.originX, 1090.0);
        QCOMPARE(areaFrame.originY, 4970.0);
        QCOMPARE(areaFrame.columns, 4);
        QCOMPARE(areaFrame.rows, 4);
        // Nodata round it (a raster read only round its area) frames it too; the area alone in the
        // flags, the same.
        for (std::uint8_t& flag : withArea.outside)
            flag = flag == ClassGrid::outsideArea ? ClassGrid::outsideNodata : flag;
        QCOMPARE(render::taskAreaFrame(withArea).originX, 1090.0);
        QCOMPARE(render::taskAreaFrame(withArea).columns, 4);
        withArea.outside.assign(grid.values.size(), 0);
        QCOMPARE(render::taskAreaFrame(withArea).columns, grid.columns);
        // The picture of the small plan is the frame's shape: square, not the raster's 2 : 1.
        const QImage image =
            render::renderPlanImage(grid, twoClassTable(), &small, QSize(400, 200), {}, nullptr, &smallFrame);
        QCOMPARE(image.size(), QSize(200, 200));
    }

    void fitsKeepingAspect() {
        const QImage image =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), nullptr, QSize(400, 400));
        QCOMPARE(image.size(), QSize(400, 200));
    }

    void drawsLandCoverInClassColours() {
        const QImage image =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), nullptr, QSize(400, 200));
        // 2 device pixels per metre: (50, 50) is meadow, (350, 150) is water.
        QVERIFY2(near(image.pixelColor(50, 50), QColor::fromRgb(kMeadow)),
                 qPrintable(image.pixelColor(50, 50).name()));
        QVERIFY2(near(image.pixelColor(350, 150), QColor::fromRgb(kWater)),
                 qPrintable(image.pixelColor(350, 150).name()));
    }

    void drawsPathInRobotColourAndLeavesTheRestAlone() {
        const Plan plan = eastboundPlan();
        const QImage image = render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200));
        // y = 4950 is device row 100; x = 1030 is device column 60 (between arrows).
        const QColor onPath = image.pixelColor(60, 100);
        QVERIFY2(near(onPath, render::RobotPalette::colour(0), 30), qPrintable(onPath.name()));
        // Far from the path the land cover shows unchanged.
        QVERIFY(near(image.pixelColor(40, 20), QColor::fromRgb(kMeadow)));
        QVERIFY(near(image.pixelColor(350, 180), QColor::fromRgb(kWater)));
    }

    // A path off the pixel grid (y = 4950.2, device row 99.6) is still drawn on whole pixels: across it,
    // the meadow, one white pixel of casing, two of the robot's colour, one white, the meadow again, and
    // no blend of them (which antialiased edges at a fractional row would leave).
    void pathLinesCoverWholePixels() {
        Plan plan = eastboundPlan();
        for (Waypoint& waypoint : plan.paths.front().waypoints)
            waypoint.y = 4950.2;
        const QImage image = render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200));
        const QRgb robot = render::RobotPalette::colour(0).rgb();
        const QRgb white = QColor(Qt::white).rgb();
        QString across;
        for (int row = 90; row <= 110; ++row) {
            const QRgb pixel = image.pixel(60, row);
            across += (pixel & 0xffffffu) == kMeadow ? '.'
                      : pixel == white               ? 'w'
                      : pixel == robot               ? 'r'
                                                     : '?';
        }
        QCOMPARE(across.count('?'), 0);
        QVERIFY2(across.contains(QStringLiteral(".wrrw.")), qPrintable(across));
        QCOMPARE(across.count('r'), 2);
    }

    // A battery plan's sorties fly from the charger: the reach ring is drawn round it, not round the start
    // 50 m west of it (a ring of 40 m round the start would not touch the charger's ring at these angles).
    void ringsTheReachRoundTheChargerSortiesFlyFrom() {
        const ClassGrid grid = twoClassGrid();
        const ClassTable classes = twoClassTable();
        const Plan plan =
            sortiePlan({{1050, 4950}, {1100, 4950}, {1100, 4940}, {1100, 4950}, {1100, 4960}, {1100, 4950}},
                       {1100, 4950}, {{0, 3}, {3, 5}});
        render::PlanRenderer renderer;
        renderer.setMap(&grid, &classes);
        renderer.setPlan(&plan);
        renderer.setStarts({{1050.0, 4950.0}});
        renderer.setFlightReach({40.0});
        QImage image(400, 200, QImage::Format_RGB32);
        QPainter painter(&image);
        renderer.paint(painter, render::PlanRenderer::fitTransform(grid, QSizeF(400, 200)),
                       QRectF(0, 0, 400, 200));
        painter.end();
        // 2 pixels a metre: the charger at (200, 100), the start at (100, 100); the ring's side away from the
        // start, at angles -60 to 60 degrees round the charger.
        const auto ringPixelsRound = [&](double centreX) {
            int drawn = 0;
            for (int step = -12; step <= 12; ++step) {
                const double angle = step * 5.0 * 3.14159265358979 / 180.0;
                const QColor pixel =
                    image.pixelColor(static_cast<int>(std::lround(centreX + 80 * std::cos(angle))),
                                     static_cast<int>(std::lround(100 + 80 * std::sin(angle))));
                drawn += near(pixel, render::RobotPalette::colour(0).darker(130), 40) ? 1 : 0;
            }
            return drawn;
        };
        QVERIFY2(ringPixelsRound(200.0) > 12, qPrintable(QString::number(ringPixelsRound(200.0))));
        QVERIFY2(ringPixelsRound(100.0) < 4, qPrintable(QString::number(ringPixelsRound(100.0))));
    }

    // Two sorties from a charger at the west end: out and back along y = 4950, then along y = 4915. The
    // second is drawn darker (device rows 100 and 170), and the legend says so.
    void drawsEverySecondSortieDarker() {
        Plan plan = sortiePlan({{1005, 4950},
                                {1095, 4950},
                                {1005, 4950},
                                {1005, 4915},
                                {1095, 4915},
                                {1005, 4915},
                                {1005, 4950}},
                               {1005, 4950}, {{0, 2}, {2, 6}});
        plan.paths.front().closed = true;
        const QImage image = render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200));
        const QColor first = image.pixelColor(60, 100);
        const QColor second = image.pixelColor(60, 170);
        QVERIFY2(near(first, render::RobotPalette::colour(0), 30), qPrintable(first.name()));
        QVERIFY2(near(second, render::RobotPalette::alternateSortieColour(0), 30), qPrintable(second.name()));
        QVERIFY(!near(first, second, 30));
        const auto sections = render::planLegend(twoClassTable(), &plan, {});
        QVERIFY(std::any_of(sections.back().items.begin(), sections.back().items.end(),
                            [](const render::LegendItem& item) { return item.label.contains("sortie"); }));
        QVERIFY(sections[1].title.contains("charger"));
    }

    // Land a battery leaves beyond its reach is not called unreachable: the legend says how much of what no
    // robot covers lies beyond the batteries (a 200 m2 corridor, half of it beyond a 101 s battery).
    void legendTellsLandBeyondTheBatteries() {
        PlanningProblem problem =
            test::drawnProblem(std::vector<std::string>(2, std::string(100, '.')), {{0.5, 0.5}});
        problem.planner = defaultPlannerChoice("wavefront-battery");
        problem.planner.parameters.set("battery_s", 101.0);
        problem.planner.parameters.set("turn_s", 0.0);
        const Plan plan = makePlanner("wavefront-battery")->plan(problem, {});
        QCOMPARE(plan.metrics.unreachableAreaSquareMetres, 100.0);
        const auto sections = render::planLegend(problem.classes, &plan, {});
        QVERIFY(std::any_of(
            sections.back().items.begin(), sections.back().items.end(), [](const render::LegendItem& item) {
                return item.label == "Not covered: 100 m2, 100 m2 of it beyond the batteries' reach";
            }));
    }

    // Drones taking off from one spot: both markers show, the second beside the first.
    void startsAtOneSpotAreFannedOut() {
        const ClassGrid grid = twoClassGrid();
        const ClassTable classes = twoClassTable();
        render::PlanRenderer renderer;
        renderer.setMap(&grid, &classes);
        renderer.setStarts({{1050.0, 4950.0}, {1050.0, 4950.0}});
        QImage image(400, 200, QImage::Format_RGB32);
        QPainter painter(&image);
        const QTransform transform = render::PlanRenderer::fitTransform(grid, QSizeF(400, 200));
        renderer.paint(painter, transform, QRectF(0, 0, 400, 200));
        painter.end();
        // Both robots' colours near (100, 100), where the start lies at 2 pixels a metre.
        const auto seen = [&](const QColor& colour) {
            for (int y = 85; y <= 115; ++y)
                for (int x = 85; x <= 140; ++x)
                    if (near(image.pixelColor(x, y), colour, 10))
                        return true;
            return false;
        };
        QVERIFY(seen(render::RobotPalette::colour(0)));
        QVERIFY(seen(render::RobotPalette::colour(1)));
    }

    // An aircraft's reach in one flight: a dashed ring of that radius round its start in the robot's colour,
    // none without one.
    void ringsTheGroundAFlightReaches() {
        const ClassGrid grid = twoClassGrid();
        const ClassTable classes = twoClassTable();
        const auto ringPixels = [&](std::vector<double> reach) {
            render::PlanRenderer renderer;
            renderer.setMap(&grid, &classes);
            renderer.setStarts({{1050.0, 4950.0}});
            renderer.setFlightReach(std::move(reach));
            QImage image(400, 200, QImage::Format_RGB32);
            QPainter painter(&image);
            const QTransform transform = render::PlanRenderer::fitTransform(grid, QSizeF(400, 200));
            renderer.paint(painter, transform, QRectF(0, 0, 400, 200));
            painter.end();
            // 2 pixels a metre: 40 m is a ring of 80 pixels round (100, 100); count its pixels of the
            // robot's colour, darkened, at 72 angles.
            int drawn = 0;
            for (int step = 0; step < 72; ++step) {
                const double angle = step * 5.0 * 3.14159265358979 / 180.0;
                const QColor pixel =
                    image.pixelColor(static_cast<int>(std::lround(100 + 80 * std::cos(angle))),
                                     static_cast<int>(std::lround(100 + 80 * std::sin(angle))));
                drawn += near(pixel, render::RobotPalette::colour(0).darker(130), 40) ? 1 : 0;
            }
            return drawn;
        };
        QVERIFY2(ringPixels({40.0}) > 36, qPrintable(QString::number(ringPixels({40.0}))));
        QCOMPARE(ringPixels({0.0}), 0);
        QCOMPARE(ringPixels({}), 0);
        // The exported sheet draws them too, and its legend says what they are.
        const Plan plan = eastboundPlan();
        const auto sheetImage = [&](std::vector<double> reach) {
            const render::PlanSheet sheet(grid, classes, plan, {nullptr, {}, std::move(reach), nullptr, {}},
                                          QSize(400, 400));
            QImage image(sheet.size(), QImage::Format_RGB32);
            image.fill(Qt::white);
            QPainter painter(&image);
            sheet.paint(painter);
            return image;
        };
        const QImage without = sheetImage({});
        const QImage with = sheetImage({40.0});
        QVERIFY(with.height() >= without.height());
        int differing = 0;
        for (int y = 0; y < without.height(); ++y)
            for (int x = 0; x < without.width(); ++x)
                differing += with.pixel(x, y) != without.pixel(x, y) ? 1 : 0;
        QVERIFY2(differing > 200, qPrintable(QString::number(differing)));
        // The legend explains the ring only where it shows: one of 100 km lies round the whole sheet.
        const auto explainsRings = [&](double reach) {
            const render::PlanSheet sheet(grid, classes, plan, {nullptr, {}, {reach}, nullptr, {}},
                                          QSize(400, 400));
            for (const render::LegendSection& section : sheet.legend())
                for (const render::LegendItem& item : section.items)
                    if (item.symbol == render::LegendSymbol::FlightReach)
                        return true;
            return false;
        };
        QVERIFY(explainsRings(40.0));
        QVERIFY(!explainsRings(100000.0));
    }

    // Where a robot is done in the field later than its path takes (an aircraft's flights from its start,
    // turnarounds), its line of the sheet's legend says when, and in how many flights; others keep their
    // path's time alone.
    void legendGivesTimeInTheField() {
        Plan plan = eastboundPlan();
        plan.paths.push_back(plan.paths.front());
        plan.paths.back().robot = 1;
        plan.metrics.robots.resize(2);
        plan.metrics.robots[0].timeSeconds = 3600.0;
        plan.metrics.robots[1].timeSeconds = 1800.0;
        render::SheetExtras extras;
        extras.fieldTimes = {{7500.0, 3, true}, {}};
        const render::PlanSheet sheet(twoClassGrid(), twoClassTable(), plan, extras, QSize(400, 400));
        QStringList lines;
        for (const render::LegendSection& section : sheet.legend())
            for (const render::LegendItem& item : section.items)
                if (item.symbol == render::LegendSymbol::StartMarker)
                    lines << item.label;
        QCOMPARE(lines.size(), 2);
        QCOMPARE(lines[0], QStringLiteral("Robot 1 — 1 h; in the field 2 h 5 min, 3 flights"));
        QCOMPARE(lines[1], QStringLiteral("Robot 2 — 30 min"));
    }

    // The rings' legend line joins "On the map", or makes it before there is a plan.
    void legendExplainsTheFlightReach() {
        std::vector<render::LegendSection> mapOnly = render::planLegend(twoClassTable(), nullptr, {});
        const std::size_t sections = mapOnly.size();
        render::addFlightReach(mapOnly, {0.0, 250.0});
        QCOMPARE(mapOnly.size(), sections + 1);
        QCOMPARE(mapOnly.back().title, QStringLiteral("On the map"));
        QVERIFY(mapOnly.back().items.back().symbol == render::LegendSymbol::FlightReach);
        const Plan plan = eastboundPlan();
        std::vector<render::LegendSection> planned = render::planLegend(twoClassTable(), &plan, {});
        const std::size_t plannedSections = planned.size();
        const std::size_t overlays = planned.back().items.size();
        render::addFlightReach(planned, {250.0});
        QCOMPARE(planned.size(), plannedSections);
        QCOMPARE(planned.back().items.size(), overlays + 1);
        QVERIFY(planned.back().items.back().label.contains(QStringLiteral("one flight")));
    }

    // The area of interest's edge is a dark dashed line on a white halo over the map, a no-go zone is
    // hatched red inside its dashed edge; neither shows with the layer off or without an area. The legend and
    // the exported sheet say what they are.
    void drawsTheAreaEdgeAndHatchesNoGoZones() {
        const ClassGrid grid = twoClassGrid();
        const ClassTable classes = twoClassTable();
        AreaOutline area;
        area.include = {{{{1020, 4920}, {1180, 4920}, {1180, 4980}, {1020, 4980}}}}; // x 40-360, y 40-160
        // x 60-140, with a hole of x 90-110, y 90-110
        area.exclude = {{{{1030, 4930}, {1070, 4930}, {1070, 4970}, {1030, 4970}, {1030, 4930}},
                         {{1045, 4945}, {1055, 4945}, {1055, 4955}, {1045, 4955}}}};
        const auto painted = [&](const AreaOutline& outline, bool layerOn) {
            render::PlanRenderer renderer;
            renderer.setMap(&grid, &classes);
            renderer.setArea(outline);
            render::MapLayers layers;
            layers.area = layerOn;
            renderer.setLayers(layers);
            QImage image(400, 200, QImage::Format_RGB32);
            QPainter painter(&image);
            renderer.paint(painter, render::PlanRenderer::fitTransform(grid, QSizeF(400, 200)),
                           QRectF(0, 0, 400, 200));
            return image;
        };
        // Along the area's north edge (y = 40) and across the no-go zone's middle (y = 100, x 64-136).
        const auto count = [](const QImage& image, int y, int fromX, int toX, const QColor& colour) {
            int found = 0;
            for (int x = fromX; x <= toX; ++x)
                found += near(image.pixelColor(x, y), colour, 40) ? 1 : 0;
            return found;
        };
        const QColor edge = render::RobotPalette::areaEdgeColour();
        const QColor noGo = render::RobotPalette::noGoColour();
        const QImage drawn = painted(area, true);
        QVERIFY2(count(drawn, 40, 50, 350, edge) > 120,
                 qPrintable(QString::number(count(drawn, 40, 50, 350, edge))));
        QVERIFY2(count(drawn, 40, 50, 350, Qt::white) > 40, "a halo beside the dashes");
        QVERIFY2(count(drawn, 100, 64, 136, noGo) > 8,
                 qPrintable(QString::number(count(drawn, 100, 64, 136, noGo))));
        QCOMPARE(count(drawn, 100, 200, 350, noGo), 0); // meadow and water outside the zone stay plain
        QCOMPARE(count(drawn, 100, 95, 105, noGo), 0);  // and so does the zone's hole
        QVERIFY(near(drawn.pixelColor(200, 100), QColor::fromRgb(kMeadow)) ||
                near(drawn.pixelColor(200, 100), QColor::fromRgb(kWater)));
        // The same rectangle traced with 8 000 corners (a surveyed boundary) draws the same edge.
        AreaOutline traced;
        traced.include.emplace_back().emplace_back();
        for (int step = 0; step < 8000; ++step) {
            const double along = (step % 2000) / 2000.0;
            const int side = step / 2000;
            traced.include.back().back().push_back(side == 0   ? MapPoint{1020 + 160 * along, 4920}
                                                   : side == 1 ? MapPoint{1180, 4920 + 60 * along}
                                                   : side == 2 ? MapPoint{1180 - 160 * along, 4980}
                                                               : MapPoint{1020, 4980 - 60 * along});
        }
        const QImage tracedImage = painted(traced, true);
        const int tracedEdge = count(tracedImage, 40, 50, 350, edge);
        const int cornersEdge = count(drawn, 40, 50, 350, edge);
        QVERIFY2(std::abs(tracedEdge - cornersEdge) <= cornersEdge / 10,
                 qPrintable(QString("%1 against %2").arg(tracedEdge).arg(cornersEdge)));
        for (const QImage& plain : {painted(area, false), painted(AreaOutline{}, true)}) {
            QCOMPARE(count(plain, 40, 50, 350, edge), 0);
            QCOMPARE(count(plain, 100, 64, 136, noGo), 0);
        }

        std::vector<render::LegendSection> legend = render::planLegend(classes, nullptr, {});
        const std::size_t sections = legend.size();
        render::addAreaOutline(legend, AreaOutline{});
        QCOMPARE(legend.size(), sections);
        render::addAreaOutline(legend, area);
        QCOMPARE(legend.back().title, QStringLiteral("On the map"));
        QCOMPARE(legend.back().items.size(), std::size_t{2});
        QVERIFY(legend.back().items[0].symbol == render::LegendSymbol::AreaEdge);
        QVERIFY(legend.back().items[1].symbol == render::LegendSymbol::NoGoZone);

        const Plan plan = eastboundPlan();
        const render::PlanSheet sheet(grid, classes, plan, {nullptr, {}, {}, &area, {}}, QSize(400, 400));
        int explained = 0;
        for (const render::LegendSection& section : sheet.legend())
            for (const render::LegendItem& item : section.items)
                explained += item.symbol == render::LegendSymbol::AreaEdge ||
                                     item.symbol == render::LegendSymbol::NoGoZone
                                 ? 1
                                 : 0;
        QCOMPARE(explained, 2);
        // An area reaching far past the raster is drawn within the sheet's map, not over its margins or
        // legend.
        AreaOutline wide;
        wide.include = {{{{1100, 4700}, {1900, 4700}, {1900, 5300}, {1100, 5300}}}};
        wide.exclude = {{{{1150, 4600}, {1250, 4600}, {1250, 4950}, {1150, 4950}}}};
        // Edge-coloured pixels (the title's text is near black too) in the map and beyond it.
        const auto edgePixels = [&](const AreaOutline* outline) {
            const render::PlanSheet wideSheet(grid, classes, plan, {nullptr, {}, {}, outline, {}},
                                              QSize(400, 400));
            QImage image(wideSheet.size(), QImage::Format_RGB32);
            image.fill(Qt::white);
            QPainter painter(&image);
            wideSheet.paint(painter);
            painter.end();
            const QRect legendArea = wideSheet.legendArea().toAlignedRect();
            std::pair<int, int> insideAndOut{0, 0};
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor pixel = image.pixelColor(x, y);
                    if (!near(pixel, edge, 40) && !near(pixel, noGo, 40))
                        continue;
                    if (wideSheet.mapArea().contains(x, y))
                        ++insideAndOut.first;
                    else if (!legendArea.contains(x, y))
                        ++insideAndOut.second;
                }
            return insideAndOut;
        };
        const auto [insideWith, outsideWith] = edgePixels(&wide);
        const auto [insideWithout, outsideWithout] = edgePixels(nullptr);
        QVERIFY2(insideWith > insideWithout + 50,
                 qPrintable(QString("%1 %2").arg(insideWith).arg(insideWithout)));
        QCOMPARE(outsideWith, outsideWithout);
    }

    // A detection layer over the meadow half: its western half seen as required (green), its eastern
    // half not seen (red); switched off, the meadow shows plain. The legend explains the colours.
    void drawsWhatTheSensorSees() {
        Plan plan = eastboundPlan();
        DetectionGrid grid;
        grid.originX = 1000.0;
        grid.originY = 5000.0;
        grid.cellSize = 10.0;
        grid.columns = 10;
        grid.rows = 10;
        for (int row = 0; row < grid.rows; ++row)
            for (int column = 0; column < grid.columns; ++column) {
                grid.probability.push_back(column < 5 ? 0.97F : 0.0F);
                grid.required.push_back(0.95F);
            }
        DetectionSummary summary;
        summary.requiredProbability = 0.95;
        plan.layers.push_back(std::make_shared<DetectionLayer>(grid, summary));
        render::MapLayers layers;
        layers.paths = false;
        layers.starts = false;
        const QImage image =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200), layers);
        const QColor seen = image.pixelColor(40, 40);
        const QColor unseen = image.pixelColor(160, 40);
        QVERIFY2(seen.green() > seen.red() + 20, qPrintable(seen.name()));
        QVERIFY2(unseen.red() > unseen.green() + 40, qPrintable(unseen.name()));
        layers.detection = false;
        layers.regions = false;
        const QImage plain =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200), layers);
        QVERIFY(near(plain.pixelColor(160, 40), QColor::fromRgb(kMeadow)));
        const auto sections = render::planLegend(twoClassTable(), &plan, {});
        QVERIFY(
            std::any_of(sections.back().items.begin(), sections.back().items.end(),
                        [](const render::LegendItem& item) { return item.label.contains("0.95 or more"); }));
    }

    // A plan played through time, shown 5 s into a 20 s path: the first quarter is drawn, with the robot's
    // dot where it is; the rest of the way is not driven yet. Without a time, the whole path shows.
    void drawsThePathAsDrivenSoFar() {
        Plan plan = eastboundPlan();
        RobotTimeline robot;
        robot.secondsAtWaypoint = {0.0, 10.0, 20.0};
        robot.completionSeconds = 20.0;
        plan.layers.push_back(std::make_shared<TimelineLayer>(TimelineLayer::Summary{}, std::vector{robot},
                                                              std::vector<int>{}));
        const ClassGrid grid = twoClassGrid();
        const ClassTable classes = twoClassTable();
        const auto draw = [&](std::optional<double> seconds) {
            QImage image(400, 200, QImage::Format_ARGB32_Premultiplied);
            render::PlanRenderer renderer;
            renderer.setMap(&grid, &classes);
            renderer.setPlan(&plan);
            render::MapLayers layers;
            layers.starts = false;
            renderer.setLayers(layers);
            renderer.setTimelineSeconds(seconds);
            QPainter painter(&image);
            renderer.paint(painter, render::PlanRenderer::fitTransform(grid, QSizeF(400, 200)),
                           QRectF(0, 0, 400, 200));
            return image;
        };
        const QColor colour = render::RobotPalette::colour(0);
        // World x 1005..1095 along y 4950 is image x 10..190 at y 100; at 5 s the robot is at x 1027.5.
        const QImage early = draw(5.0);
        QVERIFY2(near(early.pixelColor(30, 100), colour, 30), qPrintable(early.pixelColor(30, 100).name()));
        QVERIFY2(near(early.pixelColor(55, 100), colour, 30), qPrintable(early.pixelColor(55, 100).name()));
        QVERIFY2(near(early.pixelColor(150, 100), QColor::fromRgb(kMeadow)),
                 qPrintable(early.pixelColor(150, 100).name()));
        const QImage whole = draw(std::nullopt);
        QVERIFY2(near(whole.pixelColor(150, 100), colour, 30), qPrintable(whole.pixelColor(150, 100).name()));
    }

    void hidesPathsWhenTheLayerIsOff() {
        const Plan plan = eastboundPlan();
        render::MapLayers layers;
        layers.paths = false;
        layers.starts = false;
        const QImage image =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200), layers);
        QVERIFY(near(image.pixelColor(60, 100), QColor::fromRgb(kMeadow)));
    }

    void tintsRegionsAndHatchesUnreachableCells() {
        Plan plan = twoCellPlan();
        plan.regions.robotOfCell = {1, -1};
        render::MapLayers layers;
        layers.quadTree = false;
        const QImage image =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200), layers);
        // The owned cell is meadow tinted towards robot 1's colour: no longer the plain class colour.
        const QColor tinted = image.pixelColor(100, 100);
        QVERIFY2(!near(tinted, QColor::fromRgb(kMeadow)), qPrintable(tinted.name()));
        // Somewhere in the unreachable cell the hatch lines show a dark red.
        bool sawHatch = false;
        for (int x = 210; x < 390 && !sawHatch; ++x) {
            const QColor pixel = image.pixelColor(x, 100);
            sawHatch = pixel.red() > pixel.green() + 40 && pixel.red() > pixel.blue() + 40;
        }
        QVERIFY(sawHatch);
    }

    // Cells along the raster's east and south edges may reach past it (odd rasters under cells of two
    // pixels): their tint, outlines and borders stop at the raster's edge, where the canvas shows no map.
    void drawsThePlanWithinTheRaster() {
        const Plan plan = overhangingPlan();
        const ClassGrid grid = twoClassGrid(); // 1000-1200 x 4900-5000
        const ClassTable classes = twoClassTable();
        render::PlanRenderer renderer;
        renderer.setMap(&grid, &classes);
        renderer.setPlan(&plan);
        QImage image(500, 400, QImage::Format_RGB32);
        image.fill(Qt::white);
        // 2 pixels a metre: x 1000-1250 on 0-500, y 5000-4800 on 0-400.
        const QTransform worldToDevice(2.0, 0.0, 0.0, -2.0, -2000.0, 10000.0);
        {
            QPainter painter(&image);
            renderer.paint(painter, worldToDevice, QRectF(0, 0, 500, 400));
        }
        QVERIFY(!near(image.pixelColor(100, 100), QColor::fromRgb(kMeadow))); // tinted on the raster
        for (int x = 3; x < 500; x += 7)
            for (int y = 3; y < 400; y += 7) {
                if (x < 400 && y < 200)
                    continue; // on the raster
                QVERIFY2(image.pixelColor(x, y) == QColor(Qt::white),
                         qPrintable(QString("%1, %2: %3").arg(x).arg(y).arg(image.pixelColor(x, y).name())));
            }
    }

    // In a plan simulated over time, the cells a robot took over from another are hatched in its colour;
    // its own cells are only tinted.
    void hatchesTheCellsARobotTookOver() {
        Plan plan = twoCellPlan();
        plan.regions.robotOfCell = {0, 0};
        RobotTimeline robot;
        robot.cellsTakenOver = {1};
        plan.layers.push_back(std::make_shared<TimelineLayer>(TimelineLayer::Summary{}, std::vector{robot},
                                                              std::vector<int>{0, 1}));
        render::MapLayers layers;
        layers.quadTree = false;
        layers.starts = false;
        const QImage image =
            render::renderPlanImage(twoClassGrid(), twoClassTable(), &plan, QSize(400, 200), layers);
        const QColor hatch = render::RobotPalette::colour(0).darker(140);
        const auto sawHatch = [&](int fromX, int toX) {
            for (int x = fromX; x < toX; ++x)
                if (near(image.pixelColor(x, 100), hatch, 20))
                    return true;
            return false;
        };
        QVERIFY(!sawHatch(10, 190));
        QVERIFY(sawHatch(210, 390));
    }

    // A planned map seen whole, half-way in and close up: the paths show in their robot's colour at every
    // zoom (thin lines while passes are a few pixels apart, full lines with arrows closer in).
    void pathsShowAtEveryZoom_data() {
        QTest::addColumn<double>("pixelsPerMetre");
        QTest::newRow("whole map") << 0.0;
        QTest::newRow("passes 2 px apart") << 0.4;
        QTest::newRow("passes 8 px apart") << 1.6;
        QTest::newRow("close up") << 6.0;
    }

    void pathsShowAtEveryZoom() {
        QFETCH(double, pixelsPerMetre);
        PlanningProblem problem = test::uniformProblem(60, 40, 10.0, {}, {});
        problem.starts = {test::pixelCentre(problem.grid, 5, 5), test::pixelCentre(problem.grid, 50, 30)};
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        QTransform transform = render::PlanRenderer::fitTransform(problem.grid, QSizeF(400, 300));
        if (pixelsPerMetre > 0.0) {
            const double x = problem.grid.originX + 100.0, y = problem.grid.originY - 100.0;
            transform = QTransform(pixelsPerMetre, 0.0, 0.0, -pixelsPerMetre, 200.0 - x * pixelsPerMetre,
                                   150.0 + y * pixelsPerMetre);
        }
        const auto draw = [&](bool paths) {
            render::PlanRenderer renderer;
            renderer.setMap(&problem.grid, &problem.classes);
            renderer.setPlan(&plan);
            render::MapLayers layers;
            layers.quadTree = false;
            layers.regions = false;
            layers.starts = false;
            layers.paths = paths;
            renderer.setLayers(layers);
            QImage image(400, 300, QImage::Format_ARGB32_Premultiplied);
            image.fill(Qt::white);
            QPainter painter(&image);
            renderer.paint(painter, transform, QRectF(0, 0, 400, 300));
            return image;
        };
        const QImage without = draw(false);
        const QImage with = draw(true);
        int changed = 0;
        int onMap = 0;
        for (int y = 0; y < with.height(); ++y) {
            for (int x = 0; x < with.width(); ++x) {
                const QColor before = without.pixelColor(x, y);
                onMap += before != QColor(Qt::white);
                changed += !near(before, with.pixelColor(x, y), 40);
            }
        }
        // The passes are at most 5 m apart: lines cover a good share of the map at any zoom.
        QVERIFY2(changed * 10 > onMap,
                 qPrintable(QStringLiteral("%1 of %2 map pixels show a path").arg(changed).arg(onMap)));
    }

    // A batch run paints plan.png into memory faulted in ahead (filled with zeros, not white): the file is
    // the same byte for byte, and the picture took the block.
    void picturePaintedIntoPreparedMemoryIsTheSame() {
        QTemporaryDir directory;
        const Plan plan = eastboundPlan();
        QString error;
        const QString fresh = directory.filePath(QStringLiteral("fresh.png"));
        QVERIFY2(render::writePlanPng(twoClassGrid(), twoClassTable(), plan, fresh, QSize(800, 800), &error),
                 qPrintable(error));
        const QString prepared = directory.filePath(QStringLiteral("prepared.png"));
        {
            const render::PreparedPictureMemory memory(std::size_t{16} << 20);
            QVERIFY2(render::writePlanPng(twoClassGrid(), twoClassTable(), plan, prepared, QSize(800, 800),
                                          &error),
                     qPrintable(error));
            QVERIFY(render::PreparedPictureMemory::take(1024) == nullptr); // taken by the picture
        }
        QFile freshFile(fresh);
        QFile preparedFile(prepared);
        QVERIFY(freshFile.open(QIODevice::ReadOnly) && preparedFile.open(QIODevice::ReadOnly));
        const QByteArray freshBytes = freshFile.readAll();
        QVERIFY(freshBytes.size() > 1000);
        QCOMPARE(preparedFile.readAll(), freshBytes);
    }

    // The exported picture is a map sheet: title, the map fitted as asked, scale bar, north arrow and a
    // legend with the classes (obstacles marked) and the robots by name.
    void writesPngAndSvgSheets() {
        QTemporaryDir directory;
        Plan plan = eastboundPlan();
        plan.metrics.robots.resize(1);
        plan.metrics.robots[0].timeSeconds = 5400.0;
        const std::vector<std::string> names{"Scout"};
        QString error;
        const QString png = directory.filePath(QStringLiteral("plan.png"));
        QVERIFY2(render::writePlanPng(twoClassGrid(), twoClassTable(), plan, png, QSize(800, 800), &error,
                                      {nullptr, names, {}, nullptr, {}}),
                 qPrintable(error));
        const render::PlanSheet sheet(twoClassGrid(), twoClassTable(), plan,
                                      {nullptr, names, {}, nullptr, {}}, QSize(800, 800));
        QCOMPARE(sheet.mapArea().size(), QSize(800, 400));
        QImage readBack(png);
        QCOMPARE(readBack.size(), sheet.size());
        QVERIFY(readBack.width() > 800 + 50 && readBack.height() > 400);
        // The legend's swatches carry the class and robot colours; the map's left half is meadow.
        const QRect legend = sheet.legendArea().toAlignedRect();
        QVERIFY(legend.left() > sheet.mapArea().right());
        const auto legendHolds = [&](QColor colour) {
            for (int y = legend.top(); y <= legend.bottom(); ++y)
                for (int x = legend.left(); x <= std::min(legend.right(), legend.left() + 30); ++x)
                    if (near(readBack.pixelColor(x, y), colour, 3))
                        return true;
            return false;
        };
        QVERIFY(legendHolds(QColor::fromRgb(kMeadow)));
        QVERIFY(legendHolds(QColor::fromRgb(kWater)));
        QVERIFY(legendHolds(render::RobotPalette::colour(0)));
        QVERIFY(near(readBack.pixelColor(sheet.mapArea().left() + 100, sheet.mapArea().top() + 100),
                     QColor::fromRgb(kMeadow), 40));

        const QString svg = directory.filePath(QStringLiteral("plan.svg"));
        QVERIFY2(render::writePlanSvg(twoClassGrid(), twoClassTable(), plan, svg, QSize(800, 800), &error,
                                      {nullptr, names, {}, nullptr, {}}),
                 qPrintable(error));
        QFile file(svg);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.contains("<svg"));
        for (const char* words : {"Water (obstacle)", "Meadow", "Scout", "1 h 30 min", "Coverage plan: test"})
            QVERIFY2(text.contains(words), words);
    }

    // Where flights make a robot later than its path, the title says when the last one is home first, as
    // batch mode's summary does; without field times it gives the paths' makespan alone.
    void sheetTitleSaysWhenTheLastRobotIsHome() {
        Plan plan = eastboundPlan();
        plan.paths[0].timeSeconds = 5400.0;
        plan.metrics.makespanSeconds = 5400.0;
        plan.metrics.ratio = 1.25;
        const std::vector<std::string> names{"Scout"};
        const render::PlanSheet pathsOnly(twoClassGrid(), twoClassTable(), plan,
                                          {nullptr, names, {}, nullptr, {}}, QSize(800, 800));
        QCOMPARE(pathsOnly.title(),
                 QStringLiteral("Coverage plan: test, 1 robot, makespan 1 h 30 min (1.250 × "
                                "the lower bound)"));
        const render::PlanSheet flown(twoClassGrid(), twoClassTable(), plan,
                                      {nullptr, names, {}, nullptr, {{9000.0, 4, true}}}, QSize(800, 800));
        QCOMPARE(flown.title(),
                 QStringLiteral("Coverage plan: test, 1 robot, the last home after 2 h 30 min; the "
                                "paths' makespan 1 h 30 min (1.250 × the lower bound)"));
    }

    void marksCellsWhosePathCrossesImpassableLand() {
        const CrossingScene scene = crossingScene();
        const auto crossings = impassableCrossings(scene.plan.cells, scene.plan.regions, scene.problem.grid,
                                                   scene.problem.classes);
        const auto crossing = static_cast<std::int64_t>(crossings.size());
        QVERIFY2(crossing > 0, "the scene should have cells with some water in their free sub-cells");
        // A quarter of a sub-cell's pixels at most (one water pixel in four), and never a cell of no robot.
        for (const ImpassableCrossing& found : crossings) {
            QVERIFY(found.impassableShare > 0.0 && found.impassableShare <= 0.25);
            QVERIFY(scene.plan.regions.robotOfCell[static_cast<std::size_t>(found.cell)] >= 0);
        }
        const auto countDashes = [&](bool layerOn) {
            render::PlanRenderer renderer;
            renderer.setMap(&scene.problem.grid, &scene.problem.classes);
            renderer.setPlan(&scene.plan);
            render::MapLayers layers{false, false, false, false, false, false, layerOn};
            renderer.setLayers(layers);
            QImage image(960, 960, QImage::Format_ARGB32_Premultiplied);
            image.fill(Qt::white);
            QPainter painter(&image);
            renderer.paint(painter,
                           render::PlanRenderer::fitTransform(scene.problem.grid, QSizeF(image.size())),
                           QRectF(0, 0, 960, 960));
            painter.end();
            int dashes = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    dashes +=
                        near(image.pixelColor(x, y), render::RobotPalette::crossingColour(), 20) ? 1 : 0;
            return dashes;
        };
        QVERIFY(countDashes(true) > 20 * crossing);
        QCOMPARE(countDashes(false), 0);
        // The legend says what the dashes mean, looking for crossings itself or told what was found.
        const auto mentionsCrossing = [](const std::vector<render::LegendSection>& sections) {
            const auto& overlays = sections.back().items;
            return std::any_of(overlays.begin(), overlays.end(), [](const render::LegendItem& item) {
                return item.symbol == render::LegendSymbol::Crossing;
            });
        };
        const auto& classes = scene.problem.classes;
        QVERIFY(mentionsCrossing(render::planLegend(classes, &scene.plan, {}, &scene.problem.grid)));
        QVERIFY(
            mentionsCrossing(render::planLegend(classes, &scene.plan, {}, &scene.problem.grid, &crossings)));
        const std::vector<ImpassableCrossing> none;
        QVERIFY(!mentionsCrossing(render::planLegend(classes, &scene.plan, {}, &scene.problem.grid, &none)));
    }

    void legendListsClassesRobotsAndOverlays() {
        Plan plan = eastboundPlan();
        plan.metrics.unreachableAreaSquareMetres = 25000.0;
        const auto sections = render::planLegend(twoClassTable(), &plan, {});
        QCOMPARE(sections.size(), std::size_t{3});
        QCOMPARE(sections[0].items.size(), std::size_t{2});
        QCOMPARE(sections[0].items[1].symbol, render::LegendSymbol::Obstacle);
        QCOMPARE(sections[1].items.front().label.left(7),
                 QStringLiteral("Robot 1")); // unnamed: numbered as on the map
        QCOMPARE(sections[1].items.front().marker, QStringLiteral("1"));
        QVERIFY(sections[2].items.back().label.contains(QStringLiteral("2.5 ha")));
        QCOMPARE(render::planLegend(twoClassTable(), nullptr, {}).size(),
                 std::size_t{1}); // no plan: classes only
    }

    void reportsUnwritablePaths() {
        QString error;
        QVERIFY(!render::writePlanPng(twoClassGrid(), twoClassTable(), eastboundPlan(),
                                      QStringLiteral("/nonexistent-folder/plan.png"), QSize(100, 100),
                                      &error));
        QVERIFY(error.contains(QStringLiteral("/nonexistent-folder/plan.png")));
        error.clear();
        QVERIFY(!render::writePlanSvg(twoClassGrid(), twoClassTable(), eastboundPlan(),
                                      QStringLiteral("/nonexistent-folder/plan.svg"), QSize(100, 100),
                                      &error));
        QVERIFY(!error.isEmpty());
    }

    void robotColoursAreDistinct() {
        QVERIFY(render::RobotPalette::size() >= 12);
        for (int a = 0; a < render::RobotPalette::size(); ++a)
            for (int b = a + 1; b < render::RobotPalette::size(); ++b)
                QVERIFY(render::RobotPalette::colour(a) != render::RobotPalette::colour(b));
    }
};

QTEST_MAIN(TestPlanRenderer)
#include "test_plan_renderer.moc"
