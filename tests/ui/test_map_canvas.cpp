#include "core/coverage/ImpassableCrossings.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"
#include "ui/CellToolTip.hpp"
#include "ui/MapCanvas.hpp"
#include "ui/MissionDocument.hpp"

#include <QSignalSpy>
#include <QtTest>

using namespace mcpp;

namespace {

std::shared_ptr<io::LoadedRaster> squareRaster() {
    auto raster = std::make_shared<io::LoadedRaster>();
    ClassGrid& grid = raster->grid;
    grid.columns = 100;
    grid.rows = 50;
    grid.originX = 500000.0;
    grid.originY = 4100000.0;
    grid.pixelWidth = 30.0;
    grid.pixelHeight = 30.0;
    grid.values.assign(5000, 1);
    return raster;
}

} // namespace

class TestMapCanvas : public QObject {
    Q_OBJECT

  private slots:
    void init() {
        document_ = std::make_unique<ui::MissionDocument>();
        io::Mission mission;
        mission.classes = ClassTable({LandCoverClass{1, "Grass", 0x80c080, 2.0, 30.0, true}});
        document_->reset(squareRaster(), mission, QString());
        robots_.clear();
        canvas_ = std::make_unique<ui::MapCanvas>(document_.get());
        canvas_->resize(800, 600);
        canvas_->show();
        QVERIFY(QTest::qWaitForWindowExposed(canvas_.get()));
        canvas_->zoomToFit();
    }

    void mapsBothWays() {
        const MapPoint point{501234.0, 4099321.0};
        const MapPoint back = canvas_->mapPointAt(canvas_->devicePointOf(point));
        QVERIFY(std::abs(back.x - point.x) < 1e-6 && std::abs(back.y - point.y) < 1e-6);
        // North is up: a point further north is higher on screen.
        QVERIFY(canvas_->devicePointOf({501000.0, 4099900.0}).y() <
                canvas_->devicePointOf({501000.0, 4099000.0}).y());
    }

    void fitsTheWholeMap() {
        const QPointF topLeft = canvas_->devicePointOf({500000.0, 4100000.0});
        const QPointF bottomRight = canvas_->devicePointOf({503000.0, 4098500.0});
        QVERIFY(topLeft.x() >= 0 && topLeft.y() >= 0);
        QVERIFY(bottomRight.x() <= 800 && bottomRight.y() <= 600);
        QVERIFY(bottomRight.x() - topLeft.x() > 700); // fills the width (the map is 2:1)
    }

    void zoomsAroundTheCursor() {
        const QPoint cursor(200, 150);
        const MapPoint before = canvas_->mapPointAt(cursor);
        const double scale = canvas_->pixelsPerMetre();
        QWheelEvent wheel(QPointF(cursor), canvas_->mapToGlobal(QPointF(cursor)), QPoint(), QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(canvas_.get(), &wheel);
        QVERIFY(canvas_->pixelsPerMetre() > scale);
        const MapPoint after = canvas_->mapPointAt(cursor);
        QVERIFY(std::abs(after.x - before.x) < 0.01 && std::abs(after.y - before.y) < 0.01);
    }

    void pansByDragging() {
        const MapPoint before = canvas_->mapPointAt(QPointF(400, 300));
        QTest::mousePress(canvas_.get(), Qt::LeftButton, {}, QPoint(400, 300));
        QTest::mouseMove(canvas_.get(), QPoint(450, 320));
        QTest::mouseMove(canvas_.get(), QPoint(500, 340));
        QTest::mouseRelease(canvas_.get(), Qt::LeftButton, {}, QPoint(500, 340));
        const MapPoint after = canvas_->mapPointAt(QPointF(500, 340));
        QVERIFY(std::abs(after.x - before.x) < 1.0 && std::abs(after.y - before.y) < 1.0);
    }

    void asksForAStartOnClickInPlaceMode() {
        QSignalSpy placed(canvas_.get(), &ui::MapCanvas::placeStartRequested);
        QTest::mouseClick(canvas_.get(), Qt::LeftButton, {}, QPoint(300, 300));
        QCOMPARE(placed.count(), 0); // the pan tool does not place
        canvas_->setTool(ui::MapCanvas::Tool::PlaceStart);
        QTest::mouseClick(canvas_.get(), Qt::LeftButton, {}, QPoint(300, 300));
        QCOMPARE(placed.count(), 1);
        const auto point = placed.first().first().value<MapPoint>();
        const MapPoint expected = canvas_->mapPointAt(QPointF(300, 300));
        QVERIFY(std::abs(point.x - expected.x) < 1e-6);
    }

    void dragsAMarkerAndDeletesIt() {
        io::RobotSpec robot;
        robot.name = "Robot 1";
        robot.start = {501000.0, 4099000.0};
        document_->setRobots({robot});
        QSignalSpy moved(canvas_.get(), &ui::MapCanvas::moveStartRequested);
        QSignalSpy removed(canvas_.get(), &ui::MapCanvas::removeStartRequested);
        const QPoint marker = canvas_->devicePointOf(robot.start).toPoint();
        QTest::mousePress(canvas_.get(), Qt::LeftButton, {}, marker);
        QTest::mouseMove(canvas_.get(), marker + QPoint(20, 0));
        QTest::mouseMove(canvas_.get(), marker + QPoint(40, 0));
        QTest::mouseRelease(canvas_.get(), Qt::LeftButton, {}, marker + QPoint(40, 0));
        QCOMPARE(moved.count(), 1);
        QCOMPARE(moved.first().first().toInt(), 0);
        QVERIFY(moved.first().at(1).value<MapPoint>().x > robot.start.x);
        QCOMPARE(canvas_->selectedStart(), 0);
        QTest::keyClick(canvas_.get(), Qt::Key_Delete);
        QCOMPARE(removed.count(), 1);
    }

    void zoomStepsShowTheLastDrawingScaledUntilTheViewRests() {
        // Grass on the west half, water on the east: the border is the thing to follow.
        auto raster = squareRaster();
        for (int row = 0; row < 50; ++row)
            for (int column = 50; column < 100; ++column)
                raster->grid.values[static_cast<std::size_t>(row * 100 + column)] = 2;
        io::Mission mission;
        mission.classes = ClassTable({LandCoverClass{1, "Grass", 0x80c080, 2.0, 30.0, true},
                                      LandCoverClass{2, "Water", 0x2040a0, 0.0, 30.0, false}});
        document_->reset(raster, mission, QString());
        canvas_->zoomToFit();
        const auto colourAt = [&](QPointF point) {
            return canvas_->grab().toImage().pixelColor(point.toPoint());
        };
        const QPointF border = canvas_->devicePointOf({501500.0, 4099250.0});
        const QPointF cursor = border - QPointF(40, 0); // on grass, 40 px west of the border
        const QPointF probe = border + QPointF(8, 0);   // on water, just east of it
        QCOMPARE(colourAt(probe), QColor(0x2040a0));

        // Zoomed in twice around the cursor: the border moves east past the probe. Straight after the
        // steps the view still moves, and the last drawing, scaled, already shows it there.
        QWheelEvent wheel(cursor, canvas_->mapToGlobal(cursor), QPoint(), QPoint(0, 240), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(canvas_.get(), &wheel);
        QVERIFY(canvas_->isViewMoving());
        QVERIFY(canvas_->devicePointOf({501500.0, 4099250.0}).x() > probe.x() + 4.0);
        QCOMPARE(colourAt(probe), QColor(0x80c080));
        QVERIFY(canvas_->isViewMoving());
        // Once the view rests the map is drawn afresh at the new view, with the same result.
        QTRY_VERIFY_WITH_TIMEOUT(!canvas_->isViewMoving(), 2000);
        QCOMPARE(colourAt(probe), QColor(0x80c080));

        // A change of what is shown is never previewed from the old drawing: layers off while the view
        // moves leave the background at once.
        QApplication::sendEvent(canvas_.get(), &wheel);
        QVERIFY(canvas_->isViewMoving());
        render::MapLayers none{false, false, false, false, false, false, false};
        canvas_->setLayers(none);
        QCOMPARE(colourAt(cursor), QColor(232, 232, 228));
    }

    // A plan over a corner of the map (an area of interest) fills the view the user left fitted; once the
    // user zooms, a new plan leaves the view alone.
    void aFittedViewFollowsThePlan() {
        PlanningProblem problem;
        problem.grid = squareRaster()->grid;
        problem.grid.outside.assign(problem.grid.values.size(), ClassGrid::outsideArea);
        for (int row = 0; row < 10; ++row) // 300 m x 300 m in the north-west corner
            for (int column = 0; column < 10; ++column)
                problem.grid.outside[problem.grid.index(column, row)] = 0;
        problem.classes = document_->mission().classes;
        problem.starts = {{500045.0, 4099955.0}};
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const auto plan = std::make_shared<const Plan>(makePlanner("mcpp-mlct")->plan(problem, {}));
        const double wholeMapMetres = canvas_->scaleBarMetres();
        document_->setPlan(plan, document_->currentInputs());
        const QPointF topLeft = canvas_->devicePointOf({500000.0, 4100000.0});
        const QPointF bottomRight = canvas_->devicePointOf({500300.0, 4099700.0});
        QVERIFY2(bottomRight.y() - topLeft.y() > 300.0, // the whole map would give it 90 pixels
                 qPrintable(QStringLiteral("%1").arg(bottomRight.y() - topLeft.y())));
        QVERIFY(topLeft.x() >= 0.0 && topLeft.y() >= 0.0 && bottomRight.x() <= 800.0 &&
                bottomRight.y() <= 600.0);
        QVERIFY(canvas_->scaleBarMetres() < wholeMapMetres);
        canvas_->zoomOut();
        const double chosen = canvas_->scaleBarMetres();
        document_->setPlan(std::make_shared<const Plan>(*plan), document_->currentInputs());
        QCOMPARE(canvas_->scaleBarMetres(), chosen);
        canvas_->zoomToFit(); // asked for: the plan's frame again
        QCOMPARE(canvas_->devicePointOf({500000.0, 4100000.0}), topLeft);
    }

    void toolTipExplainsCellsWhosePathCrossesWater() {
        // Scattered water pixels; sub-cells of 2 x 2 pixels keep one water pixel in four (blocked threshold).
        const test::RandomMapSpec spec = test::waterCrossingSpec();
        PlanningProblem problem = test::randomProblem(spec);
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        auto raster = std::make_shared<io::LoadedRaster>();
        raster->grid = problem.grid;
        io::Mission mission;
        mission.classes = problem.classes;
        mission.robots = {{"Scout", problem.starts[0], ""}, {"", problem.starts[1], ""}};
        document_->reset(raster, mission, QString());
        document_->setPlan(std::make_shared<const Plan>(makePlanner("mcpp-mlct")->plan(problem, {})),
                           document_->currentInputs());
        const Plan& plan = *document_->plan();
        const auto crossings = impassableCrossings(plan.cells, plan.regions, problem.grid, problem.classes);
        QVERIFY(!crossings.empty());
        const int crossing = crossings.front().cell;
        int plain = -1; // a covered cell with no water in it
        for (std::size_t id = 0; id < plan.cells.size() && plain < 0; ++id) {
            std::int64_t pixels = 0;
            if (plan.regions.robotOfCell[id] >= 0 &&
                impassableClassesIn(plan.cells.cell(static_cast<int>(id)), problem.grid, problem.classes,
                                    pixels)
                    .empty())
                plain = static_cast<int>(id);
        }
        QVERIFY(crossing >= 0 && plain >= 0);
        const Cell& cell = plan.cells.cell(crossing);
        const QString text = ui::cellToolTip(*document_, {cell.centreX(), cell.centreY()});
        QVERIFY2(text.contains(QStringLiteral("impassable (water)")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("50% of them (Blocked threshold)")), qPrintable(text));
        const int owner = plan.regions.robotOfCell[static_cast<std::size_t>(crossing)];
        // A robot named by its number is not numbered twice.
        QVERIFY2(text.contains(owner == 0 ? QStringLiteral("Covered by Scout (robot 1).")
                                          : QStringLiteral("Covered by Robot 2.")),
                 qPrintable(text));
        const Cell& other = plan.cells.cell(plain);
        const QString plainText = ui::cellToolTip(*document_, {other.centreX(), other.centreY()});
        QVERIFY(plainText.startsWith(QStringLiteral("Covered by")));
        QVERIFY(!plainText.contains(QStringLiteral("impassable")));
        // Off the plan's cells there is nothing to say.
        QVERIFY(ui::cellToolTip(*document_, {problem.grid.originX - 50.0, problem.grid.originY}).isEmpty());
    }

    void drawsAnAreaByItsCorners() {
        QSignalSpy drawn(canvas_.get(), &ui::MapCanvas::areaDrawn);
        canvas_->setTool(ui::MapCanvas::Tool::DrawArea);
        for (const QPoint corner : {QPoint(100, 100), QPoint(300, 100), QPoint(300, 300), QPoint(250, 280)})
            QTest::mouseClick(canvas_.get(), Qt::LeftButton, {}, corner);
        QTest::keyClick(canvas_.get(), Qt::Key_Backspace); // takes back (250, 280)
        QCOMPARE(drawn.count(), 0);
        QTest::mouseDClick(canvas_.get(), Qt::LeftButton, {}, QPoint(100, 300));
        QCOMPARE(drawn.count(), 1);
        const auto ring = drawn.first().first().value<std::vector<MapPoint>>();
        QCOMPARE(ring.size(), std::size_t{4});
        const MapPoint last = canvas_->mapPointAt(QPoint(100, 300));
        QVERIFY(std::abs(ring.back().x - last.x) < 1e-6 && std::abs(ring.back().y - last.y) < 1e-6);
        // Two corners make no area.
        QTest::mouseClick(canvas_.get(), Qt::LeftButton, {}, QPoint(100, 100));
        QTest::mouseClick(canvas_.get(), Qt::LeftButton, {}, QPoint(200, 100));
        QTest::keyClick(canvas_.get(), Qt::Key_Return);
        QCOMPARE(drawn.count(), 1);
    }

    void scaleBarIsARoundNumber() {
        const double metres = canvas_->scaleBarMetres();
        const double mantissa = metres / std::pow(10.0, std::floor(std::log10(metres)));
        QVERIFY(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
                std::abs(mantissa - 5.0) < 1e-9);
        QVERIFY(metres * canvas_->pixelsPerMetre() <= 130.0);
    }

  private:
    std::unique_ptr<ui::MissionDocument> document_;
    std::unique_ptr<ui::MapCanvas> canvas_;
    std::vector<io::RobotSpec> robots_;
};

QTEST_MAIN(TestMapCanvas)
#include "test_map_canvas.moc"
