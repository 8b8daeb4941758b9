#include "GrassMission.hpp"
#include "core/model/TimelineLayer.hpp"
#include "ui/EventTableModel.hpp"
#include "ui/MissionDocument.hpp"
#include "ui/ResultsPanel.hpp"
#include "ui/TimelineBar.hpp"

#include <QBarSet>
#include <QChartView>
#include <QFormLayout>
#include <QLabel>
#include <QSignalSpy>
#include <QStackedBarSeries>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>

using namespace mcpp;

class TestEventsAndTimeline : public QObject {
    Q_OBJECT

  private slots:
    void init() {
        document_ = std::make_unique<ui::MissionDocument>();
        undoStack_ = std::make_unique<QUndoStack>();
        document_->reset(test::grassRaster(), test::twoRobotMission(), QString());
        events_ = std::make_unique<ui::EventTableModel>(document_.get(), undoStack_.get());
    }

    // An added event (robot 0 at half speed) is edited, shown with the robot's name, and undone step by step.
    void eventsAreAddedEditedAndUndone() {
        QVERIFY(events_->addEvent());
        QCOMPARE(events_->rowCount(), 1);
        QCOMPARE(document_->events().front().speedFactor, 0.5);
        QVERIFY(events_->setData(events_->index(0, ui::EventTableModel::Robot), 1));
        QVERIFY(events_->setData(events_->index(0, ui::EventTableModel::Time), 300));
        QVERIFY(events_->setData(events_->index(0, ui::EventTableModel::SpeedFactor), 0));
        const SpeedEvent edited = document_->events().front();
        QCOMPARE(edited.robot, 1);
        QCOMPARE(edited.timeSeconds, 300.0);
        QCOMPARE(edited.speedFactor, 0.0);
        QCOMPARE(events_->data(events_->index(0, ui::EventTableModel::Robot)).toString(),
                 QString("1 · west"));
        QVERIFY(
            events_->data(events_->index(0, ui::EventTableModel::SpeedFactor)).toString().contains("stops"));
        undoStack_->undo();
        QCOMPARE(document_->events().front().speedFactor, 0.5);
        undoStack_->undo();
        undoStack_->undo();
        undoStack_->undo();
        QCOMPARE(events_->rowCount(), 0);
    }

    // Values the planner would refuse are refused here, with the reason, and change nothing.
    void impossibleValuesAreRefused_data() {
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("reason");
        QTest::newRow("time before the start") << int(ui::EventTableModel::Time) << "-10"
                                               << "0 s or later";
        QTest::newRow("no such robot") << int(ui::EventTableModel::Robot) << "2"
                                       << "robot 2 does not exist";
        QTest::newRow("half a robot") << int(ui::EventTableModel::Robot) << "0.5"
                                      << "not a robot number";
        QTest::newRow("negative factor") << int(ui::EventTableModel::SpeedFactor) << "-1"
                                         << "got -1";
        QTest::newRow("not a number") << int(ui::EventTableModel::SpeedFactor) << "fast"
                                      << "not a number";
    }
    void impossibleValuesAreRefused() {
        QFETCH(int, column);
        QFETCH(QString, value);
        QFETCH(QString, reason);
        QVERIFY(events_->addEvent());
        const std::vector<SpeedEvent> before = document_->events();
        QSignalSpy refused(events_.get(), &ui::EventTableModel::editRefused);
        QVERIFY(!events_->setData(events_->index(0, column), value));
        QCOMPARE(refused.count(), 1);
        QVERIFY2(refused.front().front().toString().contains(reason),
                 qPrintable(refused.front().front().toString()));
        QVERIFY(document_->events() == before);
    }

    // An event edit makes the plan stale, like any other input.
    void anEventMakesThePlanStale() {
        document_->setPlan(std::make_shared<Plan>(), document_->currentInputs());
        QVERIFY(!document_->planStale());
        QVERIFY(events_->addEvent());
        QVERIFY(document_->planStale());
    }

    // The bar starts at the end of the mission, moves through it and reports the time it shows.
    void theTimelineBarShowsATime() {
        ui::TimelineBar bar;
        bar.setTimeline(1000.0, {250.0});
        QCOMPARE(bar.seconds(), 1000.0);
        QSignalSpy changed(&bar, &ui::TimelineBar::secondsChanged);
        bar.setSeconds(250.0);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.front().front().toDouble(), 250.0);
        QVERIFY(!bar.isPlaying());
    }

    // A plan played through events says in the results how long it took and what the static plan would.
    void resultsSayWhatReallocationSaved() {
        Plan plan;
        plan.planner = "mdstc";
        TimelineLayer::Summary summary;
        summary.events = {{100.0, 0, 0.5}};
        summary.makespanSeconds = 3600.0;
        summary.staticPlanner = "mcpp-mlct";
        summary.staticMakespanSeconds = 7200.0;
        plan.layers.push_back(
            std::make_shared<TimelineLayer>(summary, std::vector<RobotTimeline>{}, std::vector<int>{}));
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {});
        const auto* label = panel.findChild<QLabel*>(QStringLiteral("timelineLabel"));
        QVERIFY(label != nullptr);
        QVERIFY2(label->text().contains("1 h") && label->text().contains("50") &&
                     label->text().contains("saved"),
                 qPrintable(label->text()));
    }

    // Under events the table says when each robot is done (or stopped), its full-speed time in the tooltip,
    // and the chart shows those times; without events neither changes.
    void theResultsShowWhenEachRobotIsDone() {
        Plan plan;
        plan.planner = "mdstc";
        plan.metrics.robots.resize(2);
        for (int robot = 0; robot < 2; ++robot) {
            plan.metrics.robots[static_cast<std::size_t>(robot)].robot = robot;
            plan.metrics.robots[static_cast<std::size_t>(robot)].timeSeconds = 3600.0;
        }
        std::vector<RobotTimeline> robots(2);
        robots[0] = {0, {}, 5400.0, false, {}, 0.0, 0.0};
        robots[1] = {1, {}, 1800.0, true, {}, 0.0, 0.0};
        TimelineLayer::Summary summary;
        summary.events = {{900.0, 0, 0.5}, {1800.0, 1, 0.0}};
        plan.layers.push_back(std::make_shared<TimelineLayer>(summary, robots, std::vector<int>{}));
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {});
        const auto* table = panel.findChild<QTableWidget*>(QStringLiteral("resultsTable"));
        QVERIFY(table != nullptr);
        // A robot's name in a narrow column is elided on one line and shown whole on hover.
        QVERIFY(!table->wordWrap());
        QCOMPARE(table->item(0, 0)->toolTip(), table->item(0, 0)->text());
        QCOMPARE(table->horizontalHeaderItem(4)->text(), QString("Done at"));
        QCOMPARE(table->item(0, 4)->text(), QString("1 h 30 min"));
        QVERIFY2(table->item(0, 4)->toolTip().startsWith("1 h at full speed"),
                 qPrintable(table->item(0, 4)->toolTip()));
        QCOMPARE(table->item(1, 4)->text(), QString("stopped at 30 min"));
        // The makespan row is the plan at full speed, and says so; the Events row says when it is done.
        const auto* makespan = panel.findChild<QLabel*>(QStringLiteral("makespanLabel"));
        QVERIFY(makespan != nullptr);
        auto* summaryForm = panel.findChild<QFormLayout*>(QStringLiteral("resultsSummary"));
        QVERIFY(summaryForm != nullptr);
        const auto* makespanName =
            qobject_cast<QLabel*>(summaryForm->labelForField(const_cast<QLabel*>(makespan)));
        QVERIFY(makespanName != nullptr);
        QCOMPARE(makespanName->text(), QString("Makespan at full speed"));
        panel.showPlan(nullptr, {}); // a cleared panel does not keep the wording of the events
        QCOMPARE(makespanName->text(), QString("Makespan"));
        QCOMPARE(table->horizontalHeaderItem(4)->text(), QString("Time"));
        panel.showPlan(&plan, {});
        const auto* chart = panel.findChild<QChartView*>(QStringLiteral("timeChart"));
        QVERIFY(chart != nullptr);
        QVERIFY(chart->chart()->title().contains("events"));
        const auto* series = qobject_cast<QStackedBarSeries*>(chart->chart()->series().front());
        QVERIFY(series != nullptr);
        QCOMPARE(series->barSets().at(0)->at(0), 90.0); // minutes
        QCOMPARE(series->barSets().at(1)->at(1), 30.0);

        plan.layers.clear();
        summary.events.clear();
        plan.layers.push_back(std::make_shared<TimelineLayer>(summary, robots, std::vector<int>{}));
        panel.showPlan(&plan, {});
        QCOMPARE(table->horizontalHeaderItem(4)->text(), QString("Time"));
        QCOMPARE(makespanName->text(), QString("Makespan"));
        QCOMPARE(table->item(0, 4)->text(), QString("1 h"));
        QCOMPARE(chart->chart()->title(), QString("Time per robot"));
        QCOMPARE(qobject_cast<QStackedBarSeries*>(chart->chart()->series().front())->barSets().at(0)->at(0),
                 60.0);
    }

  private:
    std::unique_ptr<ui::MissionDocument> document_;
    std::unique_ptr<QUndoStack> undoStack_;
    std::unique_ptr<ui::EventTableModel> events_;
};

QTEST_MAIN(TestEventsAndTimeline)
#include "test_events_and_timeline.moc"
