#include "GrassMission.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "ui/MainWindow.hpp"
#include "ui/MissionDocument.hpp"
#include "ui/RobotTableModel.hpp"

#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QUndoStack>
#include <QtTest>

using namespace mcpp;

namespace {

// The two robots of the grass mission, the second with its own 30-minute battery.
io::Mission twoRobotMission() {
    io::Mission mission = test::twoRobotMission();
    mission.robots[1].batterySeconds = 1800.0;
    return mission;
}

} // namespace

class TestRobotTableModel : public QObject {
    Q_OBJECT

  private slots:
    void init() {
        document_ = std::make_unique<ui::MissionDocument>();
        undoStack_ = std::make_unique<QUndoStack>();
        document_->reset(test::grassRaster(), twoRobotMission(), QString());
        robots_ = std::make_unique<ui::RobotTableModel>(document_.get(), undoStack_.get());
    }

    // The battery shows in minutes; a robot without one shows nothing and says whose it uses.
    void batteryShowsInMinutes() {
        QCOMPARE(robots_->data(batteryOf(1)).toString(), QString("30"));
        QVERIFY(robots_->data(batteryOf(1), Qt::ToolTipRole).toString().startsWith("30 min"));
        QVERIFY(robots_->data(batteryOf(0)).toString().isEmpty());
        QVERIFY(robots_->data(batteryOf(0), Qt::ToolTipRole).toString().contains("planner's"));
    }

    // Typed in minutes or with a unit, stored in seconds, undone one edit at a time; empty gives the robot
    // the planner's battery again.
    void batteryEditsAreStoredAndUndone_data() {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<double>("seconds");
        QTest::newRow("minutes") << "20" << 1200.0;
        QTest::newRow("decimal minutes") << "2.5" << 150.0;
        QTest::newRow("seconds") << "90 s" << 90.0;
        QTest::newRow("minutes named") << "45min" << 2700.0;
        QTest::newRow("hours") << " 1.5 h " << 5400.0;
    }
    void batteryEditsAreStoredAndUndone() {
        QFETCH(QString, typed);
        QFETCH(double, seconds);
        // A plan on batteries: a battery shapes it (other planners' plans it leaves current).
        document_->setPlannerChoice(defaultPlannerChoice("wavefront-battery"));
        document_->setPlan(std::make_shared<Plan>(), document_->currentInputs());
        QVERIFY(robots_->setData(batteryOf(0), typed));
        QCOMPARE(document_->robots()[0].batterySeconds.value_or(-1.0), seconds);
        QVERIFY(document_->planStale()); // another battery, another plan
        QVERIFY(robots_->setData(batteryOf(1), QString()));
        QVERIFY(!document_->robots()[1].batterySeconds.has_value());
        undoStack_->undo();
        QCOMPARE(document_->robots()[1].batterySeconds.value_or(-1.0), 1800.0);
        undoStack_->undo();
        QVERIFY(!document_->robots()[0].batterySeconds.has_value());
        QVERIFY(!document_->planStale());
    }

    // A cell tabbed through commits its edit text unchanged: the battery stays as it was, with no undo step.
    void aBatteryTabbedThroughStaysAsItWas() {
        QVERIFY(robots_->setData(batteryOf(0), "1234 s"));
        QCOMPARE(undoStack_->count(), 1);
        QVERIFY(robots_->setData(batteryOf(0), robots_->data(batteryOf(0), Qt::EditRole)));
        QCOMPARE(document_->robots()[0].batterySeconds.value_or(-1.0), 1234.0);
        QCOMPARE(undoStack_->count(), 1);
    }

    // What a mission file would refuse is refused here with the reason, and nothing changes.
    void impossibleBatteriesAreRefused_data() {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("reason");
        QTest::newRow("zero") << "0"
                              << "must be between 1 s and";
        QTest::newRow("negative") << "-5"
                                  << "got -300 s";
        QTest::newRow("half a second") << "0.5 s"
                                       << "got 0.5 s";
        QTest::newRow("years") << "1e6 h"
                               << "must be between";
        QTest::newRow("words") << "all day"
                               << "not a duration";
        QTest::newRow("days") << "2 d"
                              << "not a duration";
    }
    void impossibleBatteriesAreRefused() {
        QFETCH(QString, typed);
        QFETCH(QString, reason);
        QSignalSpy refused(robots_.get(), &ui::RobotTableModel::editRefused);
        QVERIFY(!robots_->setData(batteryOf(1), typed));
        QCOMPARE(refused.count(), 1);
        const QString message = refused.front().front().toString();
        QVERIFY2(message.startsWith("Battery: ") && message.contains(reason), qPrintable(message));
        QCOMPARE(document_->robots()[1].batterySeconds.value_or(-1.0), 1800.0);
        QCOMPARE(undoStack_->count(), 0);
    }

    // A charger takes the start's other coordinate until both are typed; empty puts it back at the start.
    void chargerIsPlacedByItsCoordinates() {
        QVERIFY(robots_->data(chargerOf(0, ui::RobotTableModel::ChargerEasting)).toString().isEmpty());
        QVERIFY(robots_->setData(chargerOf(0, ui::RobotTableModel::ChargerEasting), "60"));
        QCOMPARE(document_->robots()[0].charger.value_or(MapPoint{}), (MapPoint{60.0, 55.0}));
        QVERIFY(robots_->setData(chargerOf(0, ui::RobotTableModel::ChargerNorthing), "35"));
        QCOMPARE(document_->robots()[0].charger.value_or(MapPoint{}), (MapPoint{60.0, 35.0}));
        QCOMPARE(robots_->data(chargerOf(0, ui::RobotTableModel::ChargerNorthing)).toString(), QString("35"));
        QCOMPARE(document_->chargers()[0].value_or(MapPoint{}), (MapPoint{60.0, 35.0}));
        QVERIFY(robots_->setData(chargerOf(0, ui::RobotTableModel::ChargerEasting), ""));
        QVERIFY(!document_->robots()[0].charger.has_value());
        // Both at once, where one coordinate alone would fall on the other robot's start pixel (25, 55).
        QVERIFY(robots_->setData(chargerOf(0, ui::RobotTableModel::ChargerNorthing), "25, 85"));
        QCOMPARE(document_->robots()[0].charger.value_or(MapPoint{}), (MapPoint{25.0, 85.0}));
        undoStack_->undo();
        undoStack_->undo();
        QCOMPARE(document_->robots()[0].charger.value_or(MapPoint{}), (MapPoint{60.0, 35.0}));
    }

    void impossibleChargersAreRefused_data() {
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("reason");
        QTest::newRow("words") << int(ui::RobotTableModel::ChargerEasting) << "by the van"
                               << "not a coordinate";
        QTest::newRow("three numbers") << int(ui::RobotTableModel::ChargerNorthing) << "1, 2, 3"
                                       << "not a coordinate";
        QTest::newRow("off the map") << int(ui::RobotTableModel::ChargerEasting) << "500"
                                     << "outside";
        QTest::newRow("on the other start") << int(ui::RobotTableModel::ChargerEasting) << "25"
                                            << "same pixel as west's start";
    }
    void impossibleChargersAreRefused() {
        QFETCH(int, column);
        QFETCH(QString, typed);
        QFETCH(QString, reason);
        QSignalSpy refused(robots_.get(), &ui::RobotTableModel::editRefused);
        QVERIFY(!robots_->setData(chargerOf(0, column), typed));
        QCOMPARE(refused.count(), 1);
        const QString message = refused.front().front().toString();
        QVERIFY2(message.startsWith("Charger") && message.contains(reason), qPrintable(message));
        QVERIFY(!document_->robots()[0].charger.has_value());
    }

    // The battery and charger columns show only while the planner flies on batteries.
    void batteryColumnFollowsThePlanner() {
        ui::MainWindow window;
        auto* view = window.findChild<QTableView*>(QStringLiteral("robotTableView"));
        QVERIFY(view != nullptr);
        const auto batteryColumnsHidden = [&](bool hidden) {
            for (const int column : {ui::RobotTableModel::Battery, ui::RobotTableModel::ChargerEasting,
                                     ui::RobotTableModel::ChargerNorthing})
                if (view->isColumnHidden(column) != hidden)
                    return false;
            return true;
        };
        QVERIFY(batteryColumnsHidden(true));
        window.document()->setPlannerChoice({"wavefront-battery", {}});
        QVERIFY(batteryColumnsHidden(false));
        window.document()->setPlannerChoice({"mdstc", {}});
        QVERIFY(batteryColumnsHidden(true));
    }

    // A start typed into the table moves the robot; the editor the move closes is not committed twice (Qt
    // warns of "an editor that does not belong to this view" where the table was reset under it).
    void aStartTypedInTheTableMovesTheRobot() {
        QTableView view;
        view.setModel(robots_.get());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QModelIndex easting = robots_->index(0, ui::RobotTableModel::Easting);
        const double moved = document_->robots()[0].start.x + 10.0;
        QTest::failOnWarning(QRegularExpression(QStringLiteral("commitData|editor")));
        view.edit(easting);
        auto* editor = qobject_cast<QLineEdit*>(view.indexWidget(easting));
        if (editor == nullptr)
            editor = view.findChild<QLineEdit*>();
        QVERIFY(editor != nullptr);
        editor->setText(QString::number(moved, 'f', 2));
        QTest::keyClick(editor, Qt::Key_Return);
        QCoreApplication::processEvents();
        view.setFocus();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        QCOMPARE(document_->robots()[0].start.x, moved);
        QCOMPARE(undoStack_->count(), 1);
        QCOMPARE(robots_->rowCount(), 2);
    }

  private:
    [[nodiscard]] QModelIndex chargerOf(int robot, int column) const { return robots_->index(robot, column); }
    [[nodiscard]] QModelIndex batteryOf(int robot) const {
        return robots_->index(robot, ui::RobotTableModel::Battery);
    }

    std::unique_ptr<ui::MissionDocument> document_;
    std::unique_ptr<QUndoStack> undoStack_;
    std::unique_ptr<ui::RobotTableModel> robots_;
};

QTEST_MAIN(TestRobotTableModel)
#include "test_robot_table_model.moc"
