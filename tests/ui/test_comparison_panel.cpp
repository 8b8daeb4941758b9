#include "tests/ui/GrassMission.hpp"
#include "ui/ComparisonPanel.hpp"

#include <QHeaderView>
#include <QTableWidget>
#include <QtTest>

using namespace mcpp;

namespace {

constexpr int homeColumn = 4; // Planner, State, Ratio, Hours, Home h, Turns, Plan s

io::ComparisonRow plannedRow(const std::string& planner, double ratio, double makespanSeconds) {
    io::ComparisonRow row;
    row.planner = planner;
    row.metrics.ratio = ratio;
    row.metrics.makespanSeconds = makespanSeconds;
    row.planningMilliseconds = 250.0;
    return row;
}

ui::ComparisonOutcome outcomeOf(std::vector<io::ComparisonRow> rows) {
    ui::ComparisonOutcome outcome;
    outcome.plans.assign(rows.size(), nullptr);
    outcome.choices.assign(rows.size(), {});
    outcome.errors.assign(rows.size(), std::nullopt);
    outcome.rows = std::move(rows);
    return outcome;
}

} // namespace

class ComparisonPanelTest : public QObject {
    Q_OBJECT
  private slots:
    // "Home h" shows when the last robot is home where flights split some plan's missions, and is hidden
    // where no plan has times in the field: a column of blanks would say nothing.
    void theHomeColumnShowsOnlyWithTimesInTheField() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        QTableWidget* table = panel.table();
        QCOMPARE(table->horizontalHeaderItem(homeColumn)->text(), QStringLiteral("Home h"));
        QVERIFY(table->isColumnHidden(homeColumn));

        io::ComparisonRow flown = plannedRow("mcpp-mlct", 1.02, 7200.0);
        flown.metrics.fieldMakespanSeconds = 36000.0; // ten hours
        flown.metrics.fieldLowerBoundSeconds = 18000.0;
        io::ComparisonRow walked = plannedRow("darp", 1.20, 9000.0);
        io::ComparisonRow failed;
        failed.planner = "mstc";
        failed.outcome = io::ComparisonRow::Outcome::Failed;
        failed.message = "no free cell";
        panel.showOutcome(outcomeOf({flown, walked, failed}), raster->grid, mission.classes);
        QVERIFY(!table->isColumnHidden(homeColumn));
        const int flownRow = panel.rowOfPlanner("mcpp-mlct");
        QVERIFY(flownRow >= 0);
        QCOMPARE(table->item(flownRow, homeColumn)->data(Qt::DisplayRole).toDouble(), 10.0);
        QCOMPARE(table->item(panel.rowOfPlanner("darp"), homeColumn), nullptr); // no flights: no figure
        QCOMPARE(table->item(panel.rowOfPlanner("mstc"), homeColumn), nullptr);

        // Compared again without flights, the column goes.
        panel.showOutcome(outcomeOf({walked}), raster->grid, mission.classes);
        QVERIFY(table->isColumnHidden(homeColumn));
    }
};

QTEST_MAIN(ComparisonPanelTest)
#include "test_comparison_panel.moc"
