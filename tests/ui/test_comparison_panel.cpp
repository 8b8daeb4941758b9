#include "tests/ui/GrassMission.hpp"
#include "ui/ComparedWarnings.hpp"
#include "ui/ComparisonPanel.hpp"

#include <QDialog>
#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTableWidget>
#include <QtTest>

using namespace mcpp;

namespace {

constexpr int coveredColumn = 1; // Planner, Covered %, Hours, Home h, x 1st, Turns, Ratio, Plan s, State
constexpr int homeColumn = 3;
constexpr int againstFirstColumn = 4;
constexpr int stateColumn = 8;

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
    // A planned row has a plan, drawn on the sheet (an empty one here); the others have none.
    for (const io::ComparisonRow& row : rows)
        outcome.plans.push_back(row.outcome == io::ComparisonRow::Outcome::Planned ? std::make_shared<Plan>()
                                                                                   : nullptr);
    outcome.choices.assign(rows.size(), {});
    outcome.errors.assign(rows.size(), std::nullopt);
    outcome.rows = std::move(rows);
    return outcome;
}

} // namespace

class ComparisonPanelTest : public QObject {
    Q_OBJECT
  private slots:
    // After a comparison each warning is said once: the mission's own, which every plan carries, under no
    // planner's name; one that some plans carry, under theirs, so that two such warnings of different
    // figures do not read as the mission's contradicting itself.
    void comparedWarningsAreSaidOnceUnderThePlannersCarryingThem() {
        const std::vector<ui::ComparedWarning> said = ui::comparedWarnings({
            {"mcpp-mlct", {"land unreached", "17.4 ha cannot be reached"}},
            {"darp", {"land unreached", "15.9 ha cannot be reached", "flights too long"}},
            {"mstc", {"land unreached", "15.9 ha cannot be reached", "flights too long"}},
        });
        QCOMPARE(said.size(), std::size_t{4});
        QCOMPARE(said[0].planners, std::string());
        QCOMPARE(said[0].text, std::string("land unreached"));
        QCOMPARE(said[1].planners, std::string("mcpp-mlct"));
        QCOMPARE(said[1].text, std::string("17.4 ha cannot be reached"));
        QCOMPARE(said[2].planners, std::string("darp, mstc"));
        QCOMPARE(said[2].text, std::string("15.9 ha cannot be reached"));
        QCOMPARE(said[3].planners, std::string("darp, mstc"));
        QCOMPARE(said[3].text, std::string("flights too long"));
        // A plan compared alone keeps its planner's name.
        const std::vector<ui::ComparedWarning> alone = ui::comparedWarnings({{"darp", {"flights too long"}}});
        QCOMPARE(alone.size(), std::size_t{1});
        QCOMPARE(alone[0].planners, std::string("darp"));
    }

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
        // Not timed in the field: done when its paths end, at its makespan, greyed and said so.
        const QTableWidgetItem* walkedHome = table->item(panel.rowOfPlanner("darp"), homeColumn);
        QVERIFY(walkedHome != nullptr);
        QCOMPARE(walkedHome->text(), QStringLiteral("2.50"));
        QVERIFY(walkedHome->toolTip().contains(QStringLiteral("Not timed in the field")));
        QVERIFY(table->item(flownRow, homeColumn)->toolTip().isEmpty());
        QCOMPARE(table->item(panel.rowOfPlanner("mstc"), homeColumn), nullptr);

        // Compared again without flights, the column goes.
        panel.showOutcome(outcomeOf({walked}), raster->grid, mission.classes);
        QVERIFY(table->isColumnHidden(homeColumn));
    }

    // Plans of weeks are counted in days, as the sheet's chart counts them: 155 days, not 3 720 hours.
    void plansOfWeeksAreCountedInDays() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        QTableWidget* table = panel.table();
        const int makespanColumn = homeColumn - 1;
        panel.showOutcome(outcomeOf({plannedRow("darp", 1.0, 7200.0)}), raster->grid, mission.classes);
        QCOMPARE(table->horizontalHeaderItem(makespanColumn)->text(), QStringLiteral("Hours"));
        QCOMPARE(table->item(0, makespanColumn)->text(), QStringLiteral("2.00"));
        panel.showOutcome(
            outcomeOf({plannedRow("darp", 1.0, 155.5 * 86400.0), plannedRow("mstc", 1.0, 7200.0)}),
            raster->grid, mission.classes);
        QCOMPARE(table->horizontalHeaderItem(makespanColumn)->text(), QStringLiteral("Days"));
        QCOMPARE(table->item(panel.rowOfPlanner("darp"), makespanColumn)->text(), QStringLiteral("155.50"));
        QCOMPARE(table->item(panel.rowOfPlanner("mstc"), makespanColumn)->text(), QStringLiteral("0.08"));
        QCOMPARE(table->horizontalHeaderItem(homeColumn)->text(), QStringLiteral("Home d"));
    }

    // The plan done soonest comes first, not the best balanced: a plan at 1.00 of its bound may still take
    // five times as long. Where robots fly, by when the last is home; plans without that figure after.
    void theSoonestDonePlanComesFirst() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        const QTableWidget* table = panel.table();
        const io::ComparisonRow balanced = plannedRow("mdstc", 1.00, 180000.0);
        const io::ComparisonRow quick = plannedRow("mcpp-mlct", 1.50, 37800.0);
        const io::ComparisonRow middle = plannedRow("darp", 1.10, 90000.0);
        panel.showOutcome(outcomeOf({balanced, quick, middle}), raster->grid, mission.classes);
        QCOMPARE(panel.rowOfPlanner("mcpp-mlct"), 0);
        QCOMPARE(panel.rowOfPlanner("darp"), 1);
        QCOMPARE(panel.rowOfPlanner("mdstc"), 2);
        QCOMPARE(table->horizontalHeader()->sortIndicatorSection(), homeColumn - 1); // Hours
        // Every row stays in view above the sheet, which scrolls on its own.
        QVERIFY(table->minimumHeight() >= 4 * table->verticalHeader()->defaultSectionSize());
        // The first in batch mode's summary is marked, whichever way the table is sorted later.
        QVERIFY(table->item(0, 0)->font().bold());
        QVERIFY(!table->item(1, 0)->font().bold() && !table->item(2, 0)->font().bold());

        io::ComparisonRow flownLate = plannedRow("mcpp-mlct", 1.01, 7200.0);
        flownLate.metrics.fieldMakespanSeconds = 40000.0;
        flownLate.metrics.fieldLowerBoundSeconds = 30000.0;
        io::ComparisonRow flownEarly = plannedRow("darp", 1.30, 9000.0);
        flownEarly.metrics.fieldMakespanSeconds = 32000.0;
        flownEarly.metrics.fieldLowerBoundSeconds = 30000.0;
        panel.showOutcome(outcomeOf({balanced, flownLate, flownEarly}), raster->grid, mission.classes);
        QCOMPARE(panel.rowOfPlanner("darp"), 0);
        QCOMPARE(panel.rowOfPlanner("mcpp-mlct"), 1);
        QCOMPARE(panel.rowOfPlanner("mdstc"), 2); // not timed in the field
        QCOMPARE(table->horizontalHeader()->sortIndicatorSection(), homeColumn);
    }

    // A plan timing its robots at the class table's speeds beside one keeping their own reads sooner done
    // but is not: the table sorts it after, with no time against the first, and the first in bold is the
    // other, as batch mode's summary lists them.
    void aPlanAtTheClassTablesSpeedsSortsAfterOnesKeepingOwnSpeeds() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        const QTableWidget* table = panel.table();
        io::ComparisonRow classSpeeds = plannedRow("mdstc", 1.00, 3600.0);
        classSpeeds.metrics.ownSpeedsIgnored = true;
        const io::ComparisonRow ownSpeeds = plannedRow("darp", 1.05, 7200.0);
        panel.showOutcome(outcomeOf({classSpeeds, ownSpeeds}), raster->grid, mission.classes);
        QCOMPARE(table->horizontalHeader()->sortIndicatorSection(), homeColumn - 1); // Hours
        QCOMPARE(panel.rowOfPlanner("darp"), 0);
        QCOMPARE(panel.rowOfPlanner("mdstc"), 1);
        QVERIFY(table->item(0, 0)->font().bold());
        QVERIFY(!table->item(1, 0)->font().bold());
        QCOMPARE(table->item(0, againstFirstColumn)->text(), QStringLiteral("1.000"));
        QCOMPARE(table->item(1, againstFirstColumn), nullptr);
        // The state says why its "x 1st" is empty.
        QCOMPARE(table->item(0, stateColumn)->text(), QStringLiteral("planned"));
        QCOMPARE(table->item(1, stateColumn)->text(), QStringLiteral("at the class table's speeds"));
    }

    // The panel asks for the width that shows every column, the state last: at that width the table needs no
    // scrolling sideways; at the usual dock's width it did.
    void thePanelAsksForTheWidthOfEveryColumn() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        panel.resize(400, 600);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy wanted(&panel, &ui::ComparisonPanel::widthWanted);
        io::ComparisonRow first = plannedRow("mcpp-mlct", 1.083, 607000.0);
        io::ComparisonRow second = plannedRow("darp-turns", 1.006, 565000.0);
        first.flightsOverBattery = 0;
        second.flightsOverBattery = 59;
        panel.showOutcome(outcomeOf({first, second}), raster->grid, mission.classes);
        QCOMPARE(wanted.count(), 1);
        const int width = wanted.takeFirst().at(0).toInt();
        QVERIFY2(width > 400, qPrintable(QString::number(width)));
        QCOMPARE(panel.table()->item(panel.rowOfPlanner("darp-turns"), stateColumn)->text(),
                 QStringLiteral("flights too long"));
        QApplication::processEvents();
        QVERIFY(panel.table()->horizontalScrollBar()->maximum() > 0);
        panel.resize(width, 600);
        QApplication::processEvents();
        QCOMPARE(panel.table()->horizontalScrollBar()->maximum(), 0);
    }

    // Sorted by when the team is done, a plan at the class table's speeds with no flights comes after the
    // plans timed alike and before one covering less, as batch mode lists them: a missing Home figure would
    // put it last.
    void sortedByHomeAPlanAtTheClassTablesSpeedsComesBeforeOneCoveringLess() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        const QTableWidget* table = panel.table();
        io::ComparisonRow flown = plannedRow("mcpp-mlct", 1.01, 7200.0);
        flown.metrics.coveredFraction = 1.0;
        flown.metrics.fieldMakespanSeconds = 40000.0;
        flown.metrics.fieldLowerBoundSeconds = 30000.0;
        io::ComparisonRow classSpeeds = plannedRow("mdstc", 1.00, 3600.0);
        classSpeeds.metrics.coveredFraction = 1.0;
        classSpeeds.metrics.ownSpeedsIgnored = true;
        io::ComparisonRow partial = plannedRow("darp", 1.02, 7000.0);
        partial.metrics.coveredFraction = 0.98;
        partial.metrics.fieldMakespanSeconds = 20000.0;
        partial.metrics.fieldLowerBoundSeconds = 19000.0;
        panel.showOutcome(outcomeOf({partial, classSpeeds, flown}), raster->grid, mission.classes);
        QCOMPARE(table->horizontalHeader()->sortIndicatorSection(), homeColumn);
        QCOMPARE(panel.rowOfPlanner("mcpp-mlct"), 0);
        QCOMPARE(panel.rowOfPlanner("mdstc"), 1);
        QCOMPARE(panel.rowOfPlanner("darp"), 2);
        QCOMPARE(table->item(1, homeColumn)->text(), QStringLiteral("1.00"));
    }

    // A plan that leaves land uncovered is not done sooner, only smaller: the Covered column says so, and
    // by time, soonest first, it comes after those covering the most (a descending sort turns the whole
    // order round). Half a percent less is within the margin; a point less is not.
    void aPlanCoveringLessSortsAfterThoseCoveringTheMost() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        QTableWidget* table = panel.table();
        QCOMPARE(table->horizontalHeaderItem(coveredColumn)->text(), QStringLiteral("Covered %"));
        io::ComparisonRow partial = plannedRow("spiral-stc", 1.00, 3600.0);
        partial.metrics.coveredFraction = 0.99;
        io::ComparisonRow whole = plannedRow("darp", 1.05, 9000.0);
        whole.metrics.coveredFraction = 1.0;
        io::ComparisonRow nearlyWhole = plannedRow("mcpp-mlct", 1.01, 7200.0);
        nearlyWhole.metrics.coveredFraction = 0.996;
        panel.showOutcome(outcomeOf({partial, whole, nearlyWhole}), raster->grid, mission.classes);
        QCOMPARE(
            table->item(panel.rowOfPlanner("spiral-stc"), coveredColumn)->data(Qt::DisplayRole).toDouble(),
            99.0);
        QCOMPARE(panel.rowOfPlanner("mcpp-mlct"), 0);
        QCOMPARE(panel.rowOfPlanner("darp"), 1);
        QCOMPARE(panel.rowOfPlanner("spiral-stc"), 2);
        QVERIFY(table->item(0, 0)->font().bold()); // the quickest, spiral-stc, covers less
        // Each plan timed against the first, the one figure across plans; none for the smaller plan.
        QCOMPARE(table->horizontalHeaderItem(againstFirstColumn)->text(), QStringLiteral("x 1st"));
        QCOMPARE(table->item(0, againstFirstColumn)->data(Qt::DisplayRole).toDouble(), 1.0);
        QCOMPARE(table->item(1, againstFirstColumn)->data(Qt::DisplayRole).toDouble(), 1.25);
        QCOMPARE(table->item(2, againstFirstColumn), nullptr);
        QCOMPARE(table->item(2, stateColumn)->text(), QStringLiteral("covers less"));
        table->sortByColumn(homeColumn - 1, Qt::DescendingOrder);
        QCOMPARE(panel.rowOfPlanner("spiral-stc"), 0); // reversed as a whole: covering less, now first
        QCOMPARE(panel.rowOfPlanner("darp"), 1);
    }

    // A plan's warnings weigh on its figures: its row says how many, and hovering says them.
    void aPlansWarningsAreFlaggedOnItsRow() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        ui::ComparisonOutcome outcome =
            outcomeOf({plannedRow("cppied", 1.00, 9000.0), plannedRow("mcpp-mlct", 1.01, 7200.0)});
        auto warned = std::make_shared<Plan>();
        warned->issues = {{IssueSeverity::Warning, "own-speeds-ignored",
                           "CPPIED times every robot at the "
                           "class table's speeds"},
                          {IssueSeverity::Information, "cruise-speed", "every robot cruises at 8 m/s"}};
        outcome.plans[0] = warned;
        outcome.plans[1] = std::make_shared<Plan>();
        panel.showOutcome(outcome, raster->grid, mission.classes);
        const QTableWidgetItem* flagged = panel.table()->item(panel.rowOfPlanner("cppied"), stateColumn);
        QCOMPARE(flagged->text(), QStringLiteral("planned, 1 warning"));
        QCOMPARE(flagged->toolTip(),
                 QStringLiteral("<p>CPPIED times every robot at the class table's speeds</p>"));
        QCOMPARE(panel.table()->item(panel.rowOfPlanner("mcpp-mlct"), stateColumn)->text(),
                 QStringLiteral("planned"));

        // What its waypoint files would warn of (flights longer than a battery) counts with them.
        outcome.fileWarnings = {{"north: 13 of its 272 flights take up to 31 min"}, {}};
        panel.showOutcome(outcome, raster->grid, mission.classes);
        const QTableWidgetItem* both = panel.table()->item(panel.rowOfPlanner("cppied"), stateColumn);
        QCOMPARE(both->text(), QStringLiteral("planned, 2 warnings"));
        QCOMPARE(both->toolTip(), QStringLiteral("<p>CPPIED times every robot at the class table's speeds</p>"
                                                 "<p>north: 13 of its 272 flights take up to 31 min</p>"));
    }

    // The dock shows the sheet scaled to its width, too small to read its captions: double-clicking it
    // shows it at full size in a window of its own.
    void theSheetOpensAtFullSize() {
        const auto raster = test::grassRaster();
        const io::Mission mission = test::twoRobotMission();
        ui::ComparisonPanel panel;
        QVERIFY(panel.showFullSizeSheet() == nullptr); // nothing compared yet
        panel.resize(320, 700);
        panel.show();
        panel.showOutcome(
            outcomeOf({plannedRow("darp", 1.00, 9000.0), plannedRow("mcpp-mlct", 1.01, 7200.0)}),
            raster->grid, mission.classes);
        const int shownWidth = panel.sheet()->pixmap().width();
        QVERIFY(shownWidth > 0);
        // One plan under another in the dock, where three side by side came out at a fifth of their size.
        panel.showOutcome(outcomeOf({plannedRow("darp", 1.00, 9000.0), plannedRow("mcpp-mlct", 1.01, 7200.0),
                                     plannedRow("mstc", 1.02, 9500.0)}),
                          raster->grid, mission.classes);
        const QSize sheetSize = panel.sheet()->pixmap().size();
        QVERIFY2(sheetSize.height() > 3 * sheetSize.width(),
                 qPrintable(QStringLiteral("%1 x %2").arg(sheetSize.width()).arg(sheetSize.height())));
        QTest::mouseDClick(panel.sheet(), Qt::LeftButton);
        auto* dialog = panel.findChild<QDialog*>(QStringLiteral("fullSizeSheet"));
        QVERIFY(dialog != nullptr && dialog->isVisible());
        const auto* image = dialog->findChild<QLabel*>();
        QVERIFY(image != nullptr);
        QVERIFY2(image->pixmap().width() > shownWidth,
                 qPrintable(QStringLiteral("%1 against %2").arg(image->pixmap().width()).arg(shownWidth)));
        // There the three plans stand side by side, as comparison.png has them: wider than tall, where the
        // dock's sheet is over three times as tall as wide.
        const QSize fullSize = image->pixmap().size();
        QVERIFY2(fullSize.width() > fullSize.height(),
                 qPrintable(QStringLiteral("%1 x %2").arg(fullSize.width()).arg(fullSize.height())));
        // Another map drops the comparison: nothing left to show at full size.
        panel.clearOutcome();
        QVERIFY(!dialog->isVisible());
        QVERIFY(panel.showFullSizeSheet() == nullptr);
    }
};

QTEST_MAIN(ComparisonPanelTest)
#include "test_comparison_panel.moc"
