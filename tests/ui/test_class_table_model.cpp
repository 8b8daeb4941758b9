#include "GrassMission.hpp"
#include "ui/ClassBulkEditDialog.hpp"
#include "ui/ClassTableModel.hpp"
#include "ui/MissionDocument.hpp"
#include "ui/RobotTableModel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

using namespace mcpp;

namespace {

// 10 x 10 pixels of 10 m: grass everywhere but a water column at x = 5 and one nodata pixel.
std::shared_ptr<io::LoadedRaster> smallRaster() {
    auto raster = test::grassRaster();
    ClassGrid& grid = raster->grid;
    for (int row = 0; row < 10; ++row)
        grid.values[grid.index(5, row)] = 2;
    grid.outside[grid.index(0, 0)] = 1;
    raster->classPixelCounts = {{1, 89}, {2, 10}};
    return raster;
}

io::Mission smallMission() {
    io::Mission mission;
    mission.classes = ClassTable({LandCoverClass{1, "Grass", 0x80c080, 2.0, 10.0, true},
                                  LandCoverClass{2, "Water", 0x3050c0, 0.0, 10.0, false}});
    return mission;
}

} // namespace

class TestClassTableModel : public QObject {
    Q_OBJECT

  private slots:
    void init() {
        document_ = std::make_unique<ui::MissionDocument>();
        undoStack_ = std::make_unique<QUndoStack>();
        document_->reset(smallRaster(), smallMission(), QString());
        classes_ = std::make_unique<ui::ClassTableModel>(document_.get(), undoStack_.get());
        robots_ = std::make_unique<ui::RobotTableModel>(document_.get(), undoStack_.get());
    }

    void showsClassesWithRoundedFieldOfView() {
        QCOMPARE(classes_->rowCount(), 2);
        QCOMPARE(classes_->data(classes_->index(0, ui::ClassTableModel::Name)).toString(),
                 QStringLiteral("Grass"));
        QCOMPARE(classes_->data(classes_->index(0, ui::ClassTableModel::RoundedFieldOfView)).toString(),
                 QStringLiteral("10"));
        QCOMPARE(classes_->data(classes_->index(0, ui::ClassTableModel::Level)).toInt(), 1);
        QCOMPARE(
            classes_->data(classes_->index(1, ui::ClassTableModel::Passable), Qt::CheckStateRole).toInt(),
            int(Qt::Unchecked));
        QCOMPARE(classes_->data(classes_->index(0, ui::ClassTableModel::Colour), Qt::DecorationRole)
                     .value<QColor>(),
                 QColor(0x80, 0xc0, 0x80));
    }

    void acceptsAValidSpeedAndUndoesIt() {
        const auto speed = classes_->index(0, ui::ClassTableModel::Speed);
        QVERIFY(classes_->setData(speed, QStringLiteral("3.5")));
        QCOMPARE(document_->classes().find(1)->speedMetresPerSecond, 3.5);
        QCOMPARE(undoStack_->count(), 1);
        undoStack_->undo();
        QCOMPARE(document_->classes().find(1)->speedMetresPerSecond, 2.0);
    }

    // A class's own detection probability: set, shown, refused outside 0 to 1, cleared back to the
    // planner's default by an empty cell, each an undo step.
    void editsTheDetectionProbability() {
        const auto detection = classes_->index(0, ui::ClassTableModel::Detection);
        QCOMPARE(classes_->data(detection).toString(), QStringLiteral("default"));
        QVERIFY(classes_->flags(detection) & Qt::ItemIsEditable);
        QVERIFY(classes_->setData(detection, QStringLiteral("0.4")));
        QCOMPARE(*document_->classes().find(1)->detectionProbability, 0.4);
        QCOMPARE(classes_->data(detection).toString(), QStringLiteral("0.4"));
        QVERIFY(!classes_->setData(detection, QStringLiteral("1.3")));
        QVERIFY(classes_->lastRefusal().contains(QStringLiteral("0 to 1")));
        QCOMPARE(*document_->classes().find(1)->detectionProbability, 0.4);
        QVERIFY(classes_->setData(detection, QString()));
        QVERIFY(!document_->classes().find(1)->detectionProbability);
        QCOMPARE(undoStack_->count(), 2);
        undoStack_->undo();
        QCOMPARE(*document_->classes().find(1)->detectionProbability, 0.4);
    }

    // Several rows at once, as one undo step; a value one row may not take refuses the whole edit.
    void bulkEditChangesEverySelectedRowInOneStep() {
        ui::ClassBulkEdit edit;
        edit.speed = 1.5;
        edit.passable = true;
        edit.fieldOfViewFactor = 2.0;
        QVERIFY(classes_->editRows({0, 1}, edit));
        QCOMPARE(undoStack_->count(), 1);
        for (const std::int32_t value : {1, 2}) {
            const LandCoverClass* row = document_->classes().find(value);
            QCOMPARE(row->speedMetresPerSecond, 1.5);
            QVERIFY(row->passable);
            QCOMPARE(row->fieldOfViewMetres, 20.0);
        }
        QCOMPARE(document_->classes().find(1)->name, std::string("Grass")); // untouched parts stay
        undoStack_->undo();
        QVERIFY(document_->classes() == smallMission().classes);

        ui::ClassBulkEdit fieldOfView;
        fieldOfView.fieldOfView = 5.0;
        fieldOfView.fieldOfViewFactor = 3.0;
        QVERIFY(classes_->editRows({1}, fieldOfView));
        QCOMPARE(document_->classes().find(2)->fieldOfViewMetres, 15.0);
        QCOMPARE(document_->classes().find(1)->fieldOfViewMetres, 10.0);
        QCOMPARE(undoStack_->count(), 1);

        QSignalSpy refused(classes_.get(), &ui::ClassTableModel::editRefused);
        const ClassTable before = document_->classes();
        ui::ClassBulkEdit tooWide;
        tooWide.speed = 2.0;
        tooWide.fieldOfViewFactor = 1e4; // 150 km for Water
        QVERIFY(!classes_->editRows({0, 1}, tooWide));
        QVERIFY(document_->classes() == before);
        QCOMPARE(undoStack_->count(), 1);
        QCOMPARE(refused.count(), 1);
        QVERIFY2(classes_->lastRefusal().contains(QStringLiteral("FOV")),
                 qPrintable(classes_->lastRefusal()));
        QVERIFY(!classes_->editRows({}, edit));
        QVERIFY(classes_->lastRefusal().contains(QStringLiteral("Select")));
    }

    void bulkEditDialogSetsOnlyWhatIsTicked() {
        ui::ClassBulkEditDialog dialog(3);
        QVERIFY(dialog.windowTitle().contains(QStringLiteral("3")));
        QVERIFY(!dialog.speed->isEnabled());
        dialog.speed->setValue(2.5); // not ticked: ignored
        dialog.passableCheck->setChecked(true);
        dialog.passable->setCurrentIndex(1);
        dialog.fieldOfViewFactor->setValue(0.5);
        ui::ClassBulkEdit edit = dialog.edit();
        QVERIFY(!edit.speed && !edit.fieldOfView);
        QCOMPARE(edit.passable, std::optional<bool>(false));
        QCOMPARE(edit.fieldOfViewFactor, 0.5);
        dialog.speedCheck->setChecked(true);
        QVERIFY(dialog.speed->isEnabled());
        QCOMPARE(dialog.edit().speed, std::optional<double>(2.5));
    }

    void refusesInvalidEditsSayingWhy() {
        QSignalSpy refused(classes_.get(), &ui::ClassTableModel::editRefused);
        QVERIFY(!classes_->setData(classes_->index(0, ui::ClassTableModel::Speed), QStringLiteral("-1")));
        QVERIFY(classes_->lastRefusal().contains(QStringLiteral("negative")));
        QVERIFY(!classes_->setData(classes_->index(0, ui::ClassTableModel::Speed), QStringLiteral("fast")));
        QVERIFY(classes_->lastRefusal().contains(QStringLiteral("number")));
        QVERIFY(!classes_->setData(classes_->index(0, ui::ClassTableModel::Speed), QStringLiteral("nan")));
        QVERIFY(
            !classes_->setData(classes_->index(0, ui::ClassTableModel::FieldOfView), QStringLiteral("0")));
        QVERIFY(!classes_->setData(classes_->index(0, ui::ClassTableModel::Name), QStringLiteral("  ")));
        QCOMPARE(refused.count(), 5);
        QCOMPARE(undoStack_->count(), 0);
        QCOMPARE(document_->classes().find(1)->speedMetresPerSecond, 2.0);
    }

    void togglesPassable() {
        QVERIFY(classes_->setData(classes_->index(1, ui::ClassTableModel::Passable), Qt::Checked,
                                  Qt::CheckStateRole));
        QVERIFY(document_->classes().find(2)->passable);
    }

    void addsRobotsOnlyWhereTheyCanStart() {
        QSignalSpy refused(robots_.get(), &ui::RobotTableModel::editRefused);
        QVERIFY(robots_->addRobot({15.0, 45.0}));
        QVERIFY(!robots_->addRobot({55.0, 45.0})); // water
        QVERIFY(refused.last().first().toString().contains(QStringLiteral("obstacle")));
        QVERIFY(!robots_->addRobot({500.0, 45.0}));
        QVERIFY(refused.last().first().toString().contains(QStringLiteral("outside")));
        QVERIFY(!robots_->addRobot({5.0, 95.0}));  // nodata
        QVERIFY(!robots_->addRobot({16.0, 44.0})); // same pixel as Robot 1
        QVERIFY(robots_->addRobot({85.0, 15.0}));
        QCOMPARE(robots_->rowCount(), 2);
        QCOMPARE(robots_->data(robots_->index(1, ui::RobotTableModel::Name)).toString(),
                 QStringLiteral("Robot 2"));
        QVERIFY(robots_->moveRobot(0, {25.0, 25.0}));
        QCOMPARE(document_->robots()[0].start, (MapPoint{25.0, 25.0}));
        undoStack_->undo();
        QCOMPARE(document_->robots()[0].start, (MapPoint{15.0, 45.0}));
        QVERIFY(robots_->removeRobot(0));
        QCOMPARE(document_->robots().size(), std::size_t{1});
        undoStack_->undo();
        QCOMPARE(document_->robots().size(), std::size_t{2});
        QVERIFY(!robots_->setData(robots_->index(0, ui::RobotTableModel::Easting), QStringLiteral("55")));
    }

    // A drone may stand where a rover cannot start (water, nodata, another robot's pixel: a road beside the
    // field, say): it takes off there. Off the raster it may not, and a robot of its own that drives may not.
    void aDroneMayStandWhereItTakesOff() {
        io::Mission mission = smallMission();
        mission.exports.vehicle.type = io::VehicleType::Multirotor;
        document_->reset(smallRaster(), mission, QString());
        QSignalSpy refused(robots_.get(), &ui::RobotTableModel::editRefused);
        QVERIFY(robots_->addRobot({55.0, 45.0})); // water
        QVERIFY(robots_->addRobot({5.0, 95.0}));  // nodata
        QVERIFY(robots_->addRobot({56.0, 44.0})); // the first drone's pixel
        QVERIFY(!robots_->addRobot({500.0, 45.0}));
        QVERIFY(refused.last().first().toString().contains(QStringLiteral("outside the raster")));
        auto robots = document_->robots();
        robots[0].vehicle.type = io::VehicleType::Rover;
        document_->setRobots(robots);
        QVERIFY(!robots_->moveRobot(0, {55.0, 25.0})); // a rover on the water, told a drone would do
        // The window's words for where the vehicle is set, not the mission file's.
        QVERIFY2(
            refused.last().first().toString().contains(QStringLiteral(
                "An aircraft would take off there (Plan menu, Robot vehicles: Multirotor or Fixed wing).")),
            qPrintable(refused.last().first().toString()));
        QVERIFY(robots_->moveRobot(1, {55.0, 25.0}));   // a drone there
        QVERIFY(!robots_->moveRobot(0, {500.0, 25.0})); // off the raster: no drone either
        QVERIFY(!refused.last().first().toString().contains(QStringLiteral("An aircraft")));
    }

  private:
    std::unique_ptr<ui::MissionDocument> document_;
    std::unique_ptr<QUndoStack> undoStack_;
    std::unique_ptr<ui::ClassTableModel> classes_;
    std::unique_ptr<ui::RobotTableModel> robots_;
};

QTEST_MAIN(TestClassTableModel)
#include "test_class_table_model.moc"
