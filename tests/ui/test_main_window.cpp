#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ExportCatalogue.hpp"
#include "io/Mission.hpp"
#include "tests/support/SyntheticMaps.hpp"
#include "tests/support/TestData.hpp"
#include "tests/ui/GrassMission.hpp"
#include "ui/ApplicationResources.hpp"
#include "ui/ClassTableBanner.hpp"
#include "ui/ClassTableModel.hpp"
#include "ui/ComparisonPanel.hpp"
#include "ui/ExportFileName.hpp"
#include "ui/LegendPanel.hpp"
#include "ui/MainWindow.hpp"
#include "ui/MapCanvas.hpp"
#include "ui/MessageLog.hpp"
#include "ui/ResultsPanel.hpp"
#include "ui/RobotTableModel.hpp"
#include "ui/SampleMission.hpp"

#include <QAction>
#include <QBarCategoryAxis>
#include <QBarSet>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QCursor>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGuiApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QSignalSpy>
#include <QStackedBarSeries>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolBar>
#include <QUndoCommand>
#include <QUndoStack>
#include <QtTest>
#include <memory>

using namespace mcpp;

namespace {

// A window that asks nothing (no dialogs) and opens no sample of its own on a first start.
std::unique_ptr<ui::MainWindow> quietWindow() {
    auto window = std::make_unique<ui::MainWindow>();
    window->setDialogsEnabled(false);
    window->setOpenSampleOnFirstStart(false);
    return window;
}

// A quiet window with the bundled sample mission open (lastError() says why not); null without the sample.
std::unique_ptr<ui::MainWindow> sampleWindow() {
    const QString sample = ui::findSampleMission();
    if (sample.isEmpty())
        return nullptr;
    std::unique_ptr<ui::MainWindow> window = quietWindow();
    (void)window->openMission(sample);
    return window;
}

// Two robots' figures, an hour and two hours of path, as a results panel shows them.
Plan twoRobotPlan() {
    Plan plan;
    plan.planner = "mcpp-mlct";
    plan.metrics.robots.resize(2);
    for (int robot = 0; robot < 2; ++robot) {
        plan.metrics.robots[static_cast<std::size_t>(robot)].robot = robot;
        plan.metrics.robots[static_cast<std::size_t>(robot)].timeSeconds = 3600.0 * (robot + 1);
    }
    return plan;
}

constexpr int kPlanningTimeoutMilliseconds = 180'000;

QString dataPath(const std::string& relative) {
    return QString::fromStdString(test::testDataPath(relative));
}

// Field teams plan this 34 x 43 km map with a wide sensor swath: FOVs of 160-320 m keep the cell count (and
// a Debug build's planning time) small. Edited through the table, as a user would.
void widenFieldsOfView(ui::ClassTableModel& model, const ui::MissionDocument& document) {
    for (int row = 0; row < model.rowCount(); ++row) {
        const LandCoverClass& landCoverClass = document.classes().classes()[static_cast<std::size_t>(row)];
        if (!landCoverClass.isTraversable())
            continue;
        const QString fieldOfView =
            landCoverClass.fieldOfViewMetres >= 20.0 ? QStringLiteral("320") : QStringLiteral("160");
        QVERIFY(model.setData(model.index(row, ui::ClassTableModel::FieldOfView), fieldOfView));
    }
}

// Pixel centres whose 9 x 9 neighbourhood is one traversable class, spread over the map, so that a click a
// device pixel off still lands on a valid start.
std::vector<MapPoint> passableSpots(const ui::MissionDocument& document, int wanted) {
    const ClassGrid& grid = *document.grid();
    std::vector<MapPoint> spots;
    const int step = std::max(grid.columns, grid.rows) / 6;
    for (int row = grid.rows / 4; row < grid.rows - 5 && static_cast<int>(spots.size()) < wanted;
         row += step) {
        for (int column = grid.columns / 5;
             column < grid.columns - 5 && static_cast<int>(spots.size()) < wanted; column += step) {
            bool uniform = true;
            const std::int32_t value = grid.valueAt(column, row);
            for (int dy = -4; dy <= 4 && uniform; ++dy)
                for (int dx = -4; dx <= 4 && uniform; ++dx)
                    uniform = !grid.isOutside(column + dx, row + dy) &&
                              grid.valueAt(column + dx, row + dy) == value;
            const LandCoverClass* landCoverClass = document.classes().find(value);
            if (!uniform || landCoverClass == nullptr || !landCoverClass->isTraversable())
                continue;
            spots.push_back({grid.originX + (column + 0.5) * grid.pixelWidth,
                             grid.originY - (row + 0.5) * grid.pixelHeight});
        }
    }
    return spots;
}

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

// The window shown at 1400 x 900 with the NLCD test raster, zoomed to fit, ready for drawing on.
bool openForDrawing(ui::MainWindow& window) {
    window.setDialogsEnabled(false);
    window.setOpenSampleOnFirstStart(false);
    window.resize(1400, 900);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window) || !window.openRaster(dataPath("landcover/nlcd.tif")))
        return false;
    QApplication::processEvents();
    window.canvas()->zoomToFit();
    return true;
}

// The area left to plan on, in square metres: the pixels the area and no-go zones leave.
double areaToPlan(const ui::MainWindow& window) {
    std::int64_t inside = 0;
    for (const auto& [value, count] : window.document()->raster()->classPixelCounts)
        inside += count;
    const ClassGrid& grid = *window.document()->grid();
    return static_cast<double>(inside) * grid.pixelWidth * grid.pixelHeight;
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

  private slots:
    // An export is suggested batch mode's name (report.json, not plan.json) after the saved mission's, and a
    // report of mission survey.json is never suggested as survey.json, which would replace the mission.
    void exportNamesFollowBatchModeAndSpareTheMission() {
        const auto suggested = [](const std::string& key, const QString& mission) {
            return ui::suggestedExportFileName(*io::findExportFormat(key), mission);
        };
        QCOMPARE(suggested("report-json", QString()), QStringLiteral("report.json"));
        QCOMPARE(suggested("geojson", QString()), QStringLiteral("plan.geojson"));
        QCOMPARE(suggested("report-json", QStringLiteral("/data/survey.json")),
                 QStringLiteral("survey-report.json"));
        QCOMPARE(suggested("geojson", QStringLiteral("/data/survey.json")),
                 QStringLiteral("survey-plan.geojson"));
        QCOMPARE(suggested("qgc-plan", QStringLiteral("/data/survey.json")), QStringLiteral("survey.plan"));
        for (const io::ExportFormat& format : io::exportFormats())
            QVERIFY2(ui::suggestedExportFileName(format, QStringLiteral("/data/survey.json")) !=
                         "survey.json",
                     format.key.c_str());
    }
    // A battery plan's results: the Sorties column, its tooltip, and the charging time in the time's.
    void resultsShowTheSortiesOfBatteryPlans() {
        PlanningProblem problem = test::drawnProblem(std::vector<std::string>(20, std::string(40, '.')),
                                                     {{0.5, 0.5}, {39.5, 19.5}});
        problem.planner = defaultPlannerChoice("wavefront-battery");
        problem.planner.parameters.set("battery_s", 150.0);
        const Plan plan = makePlanner("wavefront-battery")->plan(problem, {});
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {QStringLiteral("west"), QStringLiteral("east")});
        QTableWidget* table = panel.robotTable();
        QVERIFY(!table->isColumnHidden(6));
        const auto* layer = sortieLayerOf(plan);
        QVERIFY(layer != nullptr);
        QCOMPARE(table->item(0, 6)->text(), QString::number(layer->robots()[0].sorties.size()));
        QVERIFY2(table->item(0, 6)->toolTip().contains("charges of 10 min each"),
                 qPrintable(table->item(0, 6)->toolTip()));
        QVERIFY2(table->item(0, 4)->toolTip().contains("charging"), qPrintable(table->item(0, 4)->toolTip()));
    }

    // Land a battery leaves beyond its reach is told apart from land no robot can reach: the row says "Not
    // covered" and how much lies beyond the batteries; a plan without sorties keeps "Unreachable".
    void resultsTellLandBeyondTheBatteries() {
        PlanningProblem problem =
            test::drawnProblem(std::vector<std::string>(2, std::string(100, '.')), {{0.5, 0.5}});
        problem.planner = defaultPlannerChoice("wavefront-battery");
        problem.planner.parameters.set("battery_s", 101.0);
        const Plan plan = makePlanner("wavefront-battery")->plan(problem, {});
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {});
        auto* value = panel.findChild<QLabel*>(QStringLiteral("unreachableLabel"));
        QVERIFY(value != nullptr);
        QCOMPARE(value->text(), QStringLiteral("0.0 ha, of which 0.0 ha beyond the batteries' reach"));
        auto* summary = value->parentWidget()->findChildren<QFormLayout*>().value(0);
        QVERIFY(summary != nullptr);
        auto* label = qobject_cast<QLabel*>(summary->labelForField(value));
        QVERIFY(label != nullptr);
        QCOMPARE(label->text(), QStringLiteral("Not covered"));
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const Plan other = makePlanner("mcpp-mlct")->plan(problem, {});
        panel.showPlan(&other, {});
        QCOMPARE(label->text(), QStringLiteral("Unreachable"));
        panel.showPlan(&plan, {});
        panel.showPlan(nullptr, {});
        QCOMPARE(label->text(), QStringLiteral("Unreachable"));
    }

    // A CPPIED plan shows its detection figures under the summary; another planner's plan hides the row.
    void resultsShowWhatADetectionPlanSees() {
        PlanningProblem problem = test::drawnProblem(std::vector<std::string>(12, std::string(16, '.')),
                                                     {{0.5, 0.5}, {15.5, 11.5}});
        problem.planner = defaultPlannerChoice("cppied");
        problem.planner.parameters.set("required_probability", 0.9);
        const Plan plan = makePlanner("cppied")->plan(problem, {});
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {QStringLiteral("west"), QStringLiteral("east")});
        auto* detection = panel.findChild<QLabel*>(QStringLiteral("detectionLabel"));
        QVERIFY(detection != nullptr);
        QVERIFY2(detection->text().contains("100.0 % of the cells at 0.9 or more"),
                 qPrintable(detection->text()));
        QVERIFY(!detection->isHidden());
        problem.planner = defaultPlannerChoice("mcpp-mlct");
        const Plan other = makePlanner("mcpp-mlct")->plan(problem, {});
        panel.showPlan(&other, {});
        QVERIFY(detection->isHidden());
    }

    // Two warnings (a robot walled in by the others' starts, a pocket no robot reaches) each get a mark, so
    // that the wrapped sentences do not read as one; a lone warning is shown as it is.
    void resultsMarkEachOfSeveralWarnings() {
        std::vector<std::string> rows(20, std::string(40, '.'));
        for (int row = 10; row < 16; ++row) // a ring of water round a cell of grass, 2 pixels wide
            for (int column = 30; column < 36; ++column)
                if (row < 12 || row >= 14 || column < 32 || column >= 34)
                    rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] = '#';
        const PlanningProblem problem = test::drawnProblem(rows, {{0.5, 0.5}, {2.5, 0.5}, {0.5, 2.5}});
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        QCOMPARE(plan.warnings().size(), std::size_t{2});
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {});
        auto* warnings = panel.findChild<QLabel*>(QStringLiteral("warningsLabel"));
        QVERIFY(warnings != nullptr);
        const QStringList lines = warnings->text().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 2);
        for (const QString& line : lines)
            QVERIFY2(line.startsWith(QStringLiteral("• ")), qPrintable(line));
        QVERIFY(warnings->text().contains(QStringLiteral("robot 1 covers less than half of a fair share")));
        std::vector<std::string> open(20, std::string(40, '.'));
        open[10].replace(30, 2, "##"); // nothing enclosed
        const Plan lone = makePlanner("mcpp-mlct")
                              ->plan(test::drawnProblem(open, {{0.5, 0.5}, {2.5, 0.5}, {0.5, 2.5}}), {});
        QCOMPARE(lone.warnings().size(), std::size_t{1});
        panel.showPlan(&lone, {});
        QVERIFY2(!warnings->text().startsWith(QStringLiteral("• ")), qPrintable(warnings->text()));
    }

    // In a small dock, a plan's long warnings scroll: every robot's row stays in view, the last done too.
    void resultsKeepEveryRobotsRowBesideLongWarnings() {
        std::vector<std::string> rows(20, std::string(40, '.'));
        for (int row = 10; row < 16; ++row) // a pocket no robot reaches, and starts crowded in a corner
            for (int column = 30; column < 36; ++column)
                if (row < 12 || row >= 14 || column < 32 || column >= 34)
                    rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] = '#';
        const Plan plan =
            makePlanner("mcpp-mlct")
                ->plan(test::drawnProblem(rows, {{0.5, 0.5}, {2.5, 0.5}, {0.5, 2.5}, {2.5, 2.5}}), {});
        QVERIFY(!plan.warnings().empty());
        ui::ResultsPanel panel;
        panel.resize(320, 560); // narrow: the warnings wrap to many lines
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.showPlan(&plan, {});
        QCoreApplication::processEvents();
        auto* warnings = panel.findChild<QLabel*>(QStringLiteral("warningsLabel"));
        QVERIFY(warnings != nullptr && warnings->height() > 6 * warnings->fontMetrics().height());
        const QTableWidget* table = panel.robotTable();
        QCOMPARE(table->rowCount(), 4);
        const int shown = table->viewport()->height() / table->rowHeight(0);
        QVERIFY2(shown >= 4,
                 qPrintable(QStringLiteral("%1 rows shown, %2 px").arg(shown).arg(table->height())));
    }

    // What the plan says for information (the speed it planned at) is shown beside the warnings; a plan
    // without any hides the row.
    void resultsShowThePlansNotes() {
        PlanningProblem problem =
            test::drawnProblem(std::vector<std::string>(8, std::string(8, '.')), {{0.5, 0.5}});
        problem.notes.push_back({IssueSeverity::Information, "cruise-speed", "every robot cruises at 9 m/s"});
        const Plan noted = makePlanner("mcpp-mlct")->plan(problem, {});
        ui::ResultsPanel panel;
        panel.showPlan(&noted, {});
        auto* notes = panel.findChild<QLabel*>(QStringLiteral("notesLabel"));
        QVERIFY(notes != nullptr);
        QVERIFY(!notes->isHidden());
        QVERIFY2(notes->text().contains(QStringLiteral("cruises at 9 m/s")), qPrintable(notes->text()));
        // With the map's CRS, a point a note names gets its degrees, as the warnings' points do.
        io::LoadedRaster raster;
        raster.georeference = io::GeoReference::fromDefinition("EPSG:32633").value();
        raster.grid = test::filledGrid(49, 49, 431000.0, 5400000.0, 10.0, 1);
        problem.notes.push_back(
            {IssueSeverity::Information, "take-off-outside", "takes off at (431385, 5399995)"});
        const Plan placed = makePlanner("mcpp-mlct")->plan(problem, {});
        panel.showPlan(&placed, {}, &raster);
        QVERIFY2(notes->text().contains(QStringLiteral("(431385, 5399995; longitude 14.06")),
                 qPrintable(notes->text()));
        // Robots a message numbers are named, as the messages panel names them (the table lists names only).
        Plan named = placed;
        named.issues.push_back({IssueSeverity::Information, "note", "robots 1 and 2 meet"});
        panel.showPlan(&named, {QStringLiteral("Ada"), QStringLiteral("Ben")});
        QVERIFY2(
            notes->text().contains(QStringLiteral("robots 1 and 2 meet (robot 1 is Ada; robot 2 is Ben)")),
            qPrintable(notes->text()));
        problem.notes.clear();
        const Plan plain = makePlanner("mcpp-mlct")->plan(problem, {});
        panel.showPlan(&plain, {});
        QVERIFY(notes->isHidden());
    }

    void waypointFilesSayWhichRobotsAreSplit() {
        std::vector<io::VehicleSettings> vehicles(3);
        const QStringList names{QStringLiteral("north"), QString(), QStringLiteral("south")};
        const QString whole =
            ui::ResultsPanel::waypointFilesText({{412, 1}, {380, 1}, {55, 1}}, vehicles, names);
        QCOMPARE(whole, QStringLiteral("one file per robot, the largest 412 of 700 items"));
        const QString split =
            ui::ResultsPanel::waypointFilesText({{21075, 31}, {380, 1}, {1400, 2}}, vehicles, names);
        QCOMPARE(split,
                 QStringLiteral("2 robots above the item limit (700), in parts: north in 31, south in 2"));
        vehicles[1].maxWaypoints = 0; // limits differ: none is named
        const QString unnamedLimit =
            ui::ResultsPanel::waypointFilesText({{412, 1}, {380, 1}, {55, 1}}, vehicles, names);
        QCOMPARE(unnamedLimit, QStringLiteral("one file per robot, the largest 412 items"));
        const QString second =
            ui::ResultsPanel::waypointFilesText({{380, 1}, {1500, 3}, {55, 1}}, vehicles, names);
        QCOMPARE(second, QStringLiteral("1 robot above the item limit, in parts: Robot 2 in 3"));
        // With a flight time, parts may come from it too, and flights out of reach are counted.
        vehicles[2].flightTimeSeconds = 1200.0;
        const QString flights =
            ui::ResultsPanel::waypointFilesText({{380, 1}, {380, 1}, {90, 6, 1900.0, 2}}, vehicles, names);
        QCOMPARE(flights, QStringLiteral("1 robot over the flight time, in parts: south in 6; "
                                         "2 parts longer than a flight (out of its reach)"));
        // Above the item limit too, but the flights make far more parts than the limit alone would.
        const QString flightsAboveLimit =
            ui::ResultsPanel::waypointFilesText({{380, 1}, {380, 1}, {2127, 223}}, vehicles, names);
        QCOMPARE(flightsAboveLimit, QStringLiteral("1 robot over the flight time, in parts: south in 223"));
        const QString limitAboveFlights =
            ui::ResultsPanel::waypointFilesText({{380, 1}, {380, 1}, {2127, 5}}, vehicles, names);
        QCOMPARE(limitAboveFlights, QStringLiteral("1 robot above the item limit, in parts: south in 5"));
        // Split for either reason, each robot says its own.
        const QString both =
            ui::ResultsPanel::waypointFilesText({{1500, 3}, {380, 1}, {90, 6}}, vehicles, names);
        QCOMPARE(both,
                 QStringLiteral("2 robots in parts: north in 3 (item limit), south in 6 (flight time)"));
        // A battery plan's sorties are its parts, whichever limit they are under: said so, not an item limit.
        const QString sorties = ui::ResultsPanel::waypointFilesText(
            {{1500, 5, 0.0, 0, 0.0, 5}, {380, 1}, {90, 1}}, vehicles, names);
        QCOMPARE(sorties, QStringLiteral("1 robot in sorties, a part or more each: north in 5"));
        const QString sortiesAndFlights = ui::ResultsPanel::waypointFilesText(
            {{1500, 5, 0.0, 0, 0.0, 5}, {380, 1}, {90, 6}}, vehicles, names);
        QCOMPARE(sortiesAndFlights,
                 QStringLiteral("2 robots in parts: north in 5 (sorties), south in 6 (flight time)"));
        // A rover's parts take what its path takes: the makespan already says when it is done.
        const QString roverDone = ui::ResultsPanel::waypointFilesText(
            {{380, 1, 0.0, 0, 900.0}, {380, 1}, {90, 6, 1900.0, 2, 9000.0}}, vehicles, names);
        QVERIFY2(roverDone.endsWith(QStringLiteral("(out of its reach)")), qPrintable(roverDone));
        // When the last robot is done: its flights and the turnarounds between them.
        vehicles[2].turnaroundSeconds = 180.0;
        const QString done = ui::ResultsPanel::waypointFilesText(
            {{380, 1, 0.0, 0, 900.0}, {380, 1}, {90, 6, 1900.0, 2, 9000.0}}, vehicles, names);
        QVERIFY2(done.endsWith(QStringLiteral("(out of its reach); all done in the field after 2 h 30 min")),
                 qPrintable(done));
        vehicles[2].turnaroundSeconds = 0.0;
        vehicles[2].type = io::VehicleType::Multirotor;
        const QString flown = ui::ResultsPanel::waypointFilesText(
            {{380, 1, 0.0, 0, 900.0}, {380, 1}, {90, 6, 1900.0, 2, 9000.0}}, vehicles, names);
        QVERIFY2(flown.endsWith(QStringLiteral("; all done in the field after 2 h 30 min")),
                 qPrintable(flown));
        // Flights longer than a battery lasts are warnings as soon as the plan is made, in the Results
        // panel's warnings beside the plan's own, not only when the waypoint files are written.
        const std::vector<io::MissionSize> tooLong{{380, 1}, {380, 1}, {90, 6, 1900.0, 2, 9000.0}};
        const QStringList warned = ui::ResultsPanel::flightsTooLongWarnings(tooLong, vehicles, names);
        QCOMPARE(warned.size(), 1);
        QCOMPARE(
            warned.front(),
            QStringLiteral("south: 2 of its 6 flights take up to 31 min 40 s with the flights to and from "
                           "its start, longer than its 20 min flight time: its region reaches beyond what "
                           "one flight from its start can cover. Add robots, start them nearer that land, "
                           "or plan with wavefront-battery and chargers."));
        QVERIFY(ui::ResultsPanel::flightsTooLongWarnings({{380, 1}, {380, 1}, {90, 6, 1100.0, 0}}, vehicles,
                                                         names)
                    .isEmpty());
        // A rover's battery runs: its own words, one part in the singular.
        std::vector<io::VehicleSettings> rover(1);
        rover[0].flightTimeSeconds = 1200.0;
        QCOMPARE(
            ui::ResultsPanel::flightsTooLongWarnings({{90, 4, 1500.0, 1}}, rover, names),
            QStringList{QStringLiteral(
                "north: 1 of its 4 mission parts takes up to 25 min, longer than its 20 min battery time: "
                "its path has stretches longer than one battery lasts. Add robots, or plan with "
                "wavefront-battery and chargers.")});
        ui::ResultsPanel panel;
        const PlanningProblem problem = test::drawnProblem(std::vector<std::string>(20, std::string(40, '.')),
                                                           {{0.5, 0.5}, {39.5, 0.5}, {20.5, 19.5}});
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, {});
        panel.showPlan(&plan, {});
        auto* warnings = panel.findChild<QLabel*>(QStringLiteral("warningsLabel"));
        QCOMPARE(warnings->text(), QStringLiteral("none"));
        panel.showWaypointFiles(tooLong, vehicles, names);
        QCOMPARE(warnings->text(), warned.front());
        panel.showWaypointFiles({{380, 1}, {380, 1}, {90, 6, 1100.0, 0}}, vehicles, names);
        QCOMPARE(warnings->text(), QStringLiteral("none"));
    }

    void robotLabelStepKeepsTheNumbersThatFit() {
        QCOMPARE(ui::ResultsPanel::robotLabelStep(20, 20), 1);
        QCOMPARE(ui::ResultsPanel::robotLabelStep(20, 19), 2);
        QCOMPARE(ui::ResultsPanel::robotLabelStep(40, 12), 5);
        QCOMPARE(ui::ResultsPanel::robotLabelStep(1000, 12), 100);
        QCOMPARE(ui::ResultsPanel::robotLabelStep(5, 0), 5);
    }

    // 40 robots in a narrow chart: every second, fifth or tenth bar numbered (and the first), each under its
    // own bar; in a wide one every bar numbered.
    void chartNumbersBarsThatFit() {
        Plan plan;
        plan.planner = "mcpp-mlct";
        plan.metrics.robots.resize(40);
        for (int robot = 0; robot < 40; ++robot) {
            plan.metrics.robots[static_cast<std::size_t>(robot)].robot = robot;
            plan.metrics.robots[static_cast<std::size_t>(robot)].timeSeconds = 600.0 + robot;
        }
        ui::ResultsPanel panel;
        panel.show();
        panel.showPlan(&plan, {});
        QChartView* view = panel.chartView();
        view->resize(400, 300);
        const auto axes = view->chart()->axes(Qt::Horizontal);
        QCOMPARE(axes.size(), 1);
        auto* positions = qobject_cast<QCategoryAxis*>(axes.front());
        QVERIFY(positions != nullptr);
        const QStringList labels = positions->categoriesLabels();
        QVERIFY2(labels.size() >= 5 && labels.size() <= 12, qPrintable(labels.join(QLatin1Char(' '))));
        QCOMPARE(labels.front(), QStringLiteral("1"));
        for (const QString& label : labels)
            QCOMPARE(positions->endValue(label), label.toDouble() - 1.0); // bar i stands at i
        QCOMPARE(view->chart()->series().front()->attachedAxes().count(), 2);
        view->resize(3000, 300);
        const auto wide = view->chart()->axes(Qt::Horizontal);
        QCOMPARE(wide.size(), 1);
        const auto* every = qobject_cast<QBarCategoryAxis*>(wide.front());
        QVERIFY(every != nullptr);
        QCOMPARE(every->count(), 40);
    }

    // Where a drone's flights keep it out longer than its path takes, the chart shows when each robot is
    // home; where none does, the paths' times.
    void chartShowsTimeInTheFieldWhereFlightsTakeLonger() {
        const Plan plan = twoRobotPlan();
        ui::ResultsPanel panel;
        panel.showPlan(&plan, {});
        QCOMPARE(panel.chartView()->chart()->title(), QStringLiteral("Time per robot"));
        io::MissionSize drone;
        drone.parts = 3;
        drone.fieldSeconds = 9000.0;
        io::MissionSize rover;
        rover.fieldSeconds = 7200.0;
        io::VehicleSettings multirotor;
        multirotor.type = io::VehicleType::Multirotor;
        panel.showWaypointFiles({drone, rover}, {multirotor, io::VehicleSettings{}}, {});
        QChart* chart = panel.chartView()->chart();
        QCOMPARE(chart->title(), QStringLiteral("Time in the field per robot"));
        const auto* bars = qobject_cast<QStackedBarSeries*>(chart->series().front());
        QVERIFY(bars != nullptr);
        QCOMPARE(bars->barSets().at(0)->at(0), 2.5); // hours: 9 000 s in the field, not its 1 h path
        QCOMPARE(bars->barSets().at(1)->at(1), 2.0);
        // The table says it too, beside each path's time.
        QTableWidget* table = panel.robotTable();
        constexpr int time = 4;
        QCOMPARE(table->horizontalHeaderItem(time)->text(), QStringLiteral("Home after"));
        QCOMPARE(table->item(0, time)->text(), QStringLiteral("2 h 30 min"));
        QVERIFY2(table->item(0, time)->toolTip().startsWith(QStringLiteral("Its path alone takes 1 h")),
                 qPrintable(table->item(0, time)->toolTip()));
        QCOMPARE(table->item(1, time)->text(), QStringLiteral("2 h"));
        panel.showPlan(&plan, {});
        QCOMPARE(table->horizontalHeaderItem(time)->text(), QStringLiteral("Time"));
        io::MissionSize onItsPath;
        onItsPath.fieldSeconds = 3600.0;
        panel.showWaypointFiles({onItsPath, rover}, {}, {}); // no robot out longer than its path
        QCOMPARE(panel.chartView()->chart()->title(), QStringLiteral("Time per robot"));
        QCOMPARE(table->horizontalHeaderItem(time)->text(), QStringLiteral("Time"));
    }

    // Where flights split the missions, the summary says when the last robot is home, the bound in the field
    // and how evenly the robots come home, the paths' figures in the tooltips; a plan without flights shows
    // the paths' again.
    void summaryGivesTimesInTheFieldWhereFlightsSplitMissions() {
        Plan plan = twoRobotPlan();
        plan.metrics.makespanSeconds = 7200.0;
        plan.metrics.lowerBoundSeconds = 5400.0;
        plan.metrics.ratio = 7200.0 / 5400.0;
        Plan flown = plan;
        flown.metrics.robots[0].fieldSeconds = 9000.0; // a drone, out longer than its path
        flown.metrics.robots[1].fieldSeconds = 7500.0; // a rover, out as long as its path
        flown.metrics.fieldMakespanSeconds = 9000.0;
        flown.metrics.fieldLowerBoundSeconds = 6000.0;
        ui::ResultsPanel panel;
        panel.showPlan(&flown, {});
        QCOMPARE(panel.makespanText(), ui::ResultsPanel::formatDuration(9000.0));
        QCOMPARE(panel.ratioText(), QStringLiteral("1.200 in the field"));
        auto* lowerBound = panel.findChild<QLabel*>(QStringLiteral("lowerBoundLabel"));
        QVERIFY(lowerBound != nullptr);
        QCOMPARE(lowerBound->text(), ui::ResultsPanel::formatDuration(6000.0));
        QVERIFY(lowerBound->toolTip().contains(ui::ResultsPanel::formatDuration(5400.0)));
        auto* summary = panel.findChild<QFormLayout*>(QStringLiteral("resultsSummary"));
        QVERIFY(summary != nullptr);
        const auto rowName = [&] {
            return qobject_cast<QLabel*>(summary->labelForField(lowerBound))->text();
        };
        QCOMPARE(rowName(), QStringLiteral("Bound in the field"));
        panel.showPlan(&plan, {});
        QCOMPARE(rowName(), QStringLiteral("Lower bound"));
        QCOMPARE(panel.makespanText(), ui::ResultsPanel::formatDuration(7200.0));
        QCOMPARE(panel.ratioText(), QStringLiteral("1.333"));
        QCOMPARE(lowerBound->text(), ui::ResultsPanel::formatDuration(5400.0));
        QVERIFY(lowerBound->toolTip().isEmpty());
        // A detection plan's ratio says what its bound counts, looser than the others'.
        Plan detection = plan;
        detection.metrics.boundOfDetectionPasses = true;
        panel.showPlan(&detection, {});
        QCOMPARE(panel.ratioText(),
                 QStringLiteral("1.333 (to the passes its targets need, each at the fastest class's speed)"));
    }

    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("mcpp"));
        QCoreApplication::setApplicationName(QStringLiteral("mcpp-ui-test"));
        QSettings().clear();
    }

    // Areas drawn on untitled missions go to the application's data folder (the test-mode one, as
    // initTestCase sets): the tests leave none there.
    void cleanupTestCase() {
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
             QStringLiteral("/drawn-areas"))
            .removeRecursively();
    }

    // A mission's starts given in longitude and latitude are saved so, moved or not; starts given in the
    // raster's CRS stay in its units, and a saved raster path is relative to the mission's folder.
    void savingKeepsTheCrsStartsWereGivenIn() {
        QTemporaryDir directory;
        const QString raster = dataPath("landcover/nlcd.tif");
        QVERIFY(writeFile(directory.filePath("given.json"),
                          QStringLiteral(R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "%1"},
                              "robots": [{"name": "north", "start": [-113.04, 37.32], "start_crs": "EPSG:4326",
                                          "charger": [-113.05, 37.31]},
                                         {"name": "south", "start": [320000, 4145000]}]})")
                              .arg(raster)
                              .toUtf8()));
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        QVERIFY2(window.openMission(directory.filePath("given.json")), qPrintable(window.lastError()));
        QString rasterSaved;
        const auto robotsSaved = [&](const QString& name) {
            const QString path = directory.filePath(name);
            if (!window.saveMission(path))
                return QJsonArray();
            QFile file(path);
            if (!file.open(QIODevice::ReadOnly))
                return QJsonArray();
            const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
            rasterSaved = root["raster"].toObject()["path"].toString();
            return root["robots"].toArray();
        };
        const QJsonArray saved = robotsSaved(QStringLiteral("saved.json"));
        QVERIFY2(saved.size() == 2, qPrintable(window.lastError()));
        QVERIFY2(QDir::isRelativePath(rasterSaved), qPrintable(rasterSaved));
        QCOMPARE(QFileInfo(directory.filePath(rasterSaved)).canonicalFilePath(),
                 QFileInfo(raster).canonicalFilePath());
        const QJsonObject north = saved[0].toObject();
        QCOMPARE(north["start_crs"].toString(), QStringLiteral("EPSG:4326"));
        QCOMPARE(north["start"].toArray()[0].toDouble(), -113.04);
        QCOMPARE(north["start"].toArray()[1].toDouble(), 37.32);
        QCOMPARE(north["charger"].toArray()[0].toDouble(), -113.05);
        QCOMPARE(north["charger"].toArray()[1].toDouble(), 37.31);
        const QJsonObject south = saved[1].toObject();
        QVERIFY(!south.contains("start_crs"));
        QCOMPARE(south["start"].toArray()[0].toDouble(), 320000.0);
        QCOMPARE(south["start"].toArray()[1].toDouble(), 4145000.0);

        // Moved on the map, the robot is saved in its CRS still, a kilometre east of where it was.
        const MapPoint start = window.document()->robots()[0].start;
        QVERIFY(window.robotTableModel()->moveRobot(0, {start.x + 1000.0, start.y}));
        const QJsonObject moved = robotsSaved(QStringLiteral("moved.json"))[0].toObject();
        QCOMPARE(moved["start_crs"].toString(), QStringLiteral("EPSG:4326"));
        const double eastward = moved["start"].toArray()[0].toDouble() + 113.04;
        QVERIFY2(eastward > 0.0108 && eastward < 0.0118, qPrintable(QString::number(eastward, 'g', 10)));
        QVERIFY2(std::abs(moved["start"].toArray()[1].toDouble() - 37.32) <
                     5e-4, // UTM north is not true north
                 qPrintable(QString::number(moved["start"].toArray()[1].toDouble(), 'g', 10)));
    }

    void refusesAnUnreadableRasterAndKeepsTheMission() {
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif"), QStringLiteral("nlcd-simplified")));
        const auto classes = window.document()->classes();
        QVERIFY(!window.openRaster(QStringLiteral("/no/such/raster.tif")));
        QVERIFY(window.lastError().contains(QStringLiteral("/no/such/raster.tif")));
        QVERIFY(!window.openMission(dataPath("landcover/nlcd.tif"))); // not a mission
        QVERIFY(window.lastError().contains(QStringLiteral("nlcd.tif")));
        QVERIFY(window.document()->hasMap());
        QVERIFY(window.document()->classes() == classes);
    }

    // Opened with no preset, as a user drops a file on the window: each real product is recognised, its
    // classes named, its water and built-up land walls, and a banner and the message log say what was
    // applied.
    void opensRealRastersWithTheirProductsTable_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QList<int>>("walls");
        QTest::newRow("NLCD groups") << "landcover/nlcd.tif"
                                     << "nlcd-simplified" << QList<int>{1, 2};
        QTest::newRow("CORINE Spain") << "landcover/corine-spain/clc.tif"
                                      << "corine" << QList<int>{111, 512};
        QTest::newRow("ESA WorldCover") << "landcover/worldcover2021_principe_crop.tif"
                                        << "esa-worldcover" << QList<int>{50, 80};
        QTest::newRow("Canada") << "landcover/nrcan_landcover2015_example.tif"
                                << "canada-landcover" << QList<int>{17, 18, 19};
        QTest::newRow("CORINE grid codes") << "landcover/corine2006_swiss_ls100.tif"
                                           << "corine-grid" << QList<int>{1, 2, 41};
    }

    void opensRealRastersWithTheirProductsTable() {
        QFETCH(QString, file);
        QFETCH(QString, preset);
        QFETCH(QList<int>, walls);
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        window.show();
        QVERIFY(window.openRaster(dataPath(file.toStdString())));
        QCOMPARE(window.presetCombo()->currentData().toString(), preset);
        QVERIFY(window.classTableBanner()->isVisible());
        QVERIFY(!window.classTableBanner()->isWarning());
        QVERIFY2(window.classTableBanner()->text().startsWith("Recognised"),
                 qPrintable(window.classTableBanner()->text()));
        QVERIFY(window.messageLog()->messages().contains(window.classTableBanner()->text()));
        const ClassTable& classes = window.document()->classes();
        for (const LandCoverClass& row : classes.classes())
            QVERIFY2(!QString::fromStdString(row.name).startsWith("Class "), row.name.c_str());
        for (const int value : walls) {
            QVERIFY(classes.find(value) != nullptr);
            QVERIFY(!classes.find(value)->isTraversable());
        }
        // Choosing another preset is the user's word: the note goes.
        QVERIFY(window.applyPreset(QStringLiteral("paper")));
        QVERIFY(!window.classTableBanner()->isVisible());
    }

    // A raster of 55 unnamed classes without palette or CRS (an ASCII grid): a warning banner, a colour of
    // its own for every class, and after planning the formats that need longitude and latitude greyed out.
    void unknownRasterWithoutCrsExplainsItself() {
        QTemporaryDir directory;
        QString grid = QStringLiteral("ncols 110\nnrows 50\nxllcorner 0\nyllcorner 0\ncellsize 2\n");
        for (int row = 0; row < 50; ++row) {
            for (int column = 0; column < 110; ++column)
                grid += QString::number(column / 2 + 1) + (column + 1 < 110 ? " " : "\n");
        }
        QVERIFY(writeFile(directory.filePath("unknown.asc"), grid.toUtf8()));
        QVERIFY(writeFile(directory.filePath("mission.json"),
                          R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "unknown.asc"},
                              "robots": [{"name": "one", "start": [111, 51]}]})"));
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        window.show();
        QVERIFY2(window.openMission(directory.filePath("mission.json")), qPrintable(window.lastError()));
        QVERIFY(window.classTableBanner()->isVisible());
        QVERIFY(window.classTableBanner()->isWarning());
        QVERIFY(window.classTableBanner()->text().contains("55 classes without names"));
        QCOMPARE(window.presetCombo()->currentData().toString(), QString());
        QSet<std::uint32_t> colours;
        for (const LandCoverClass& row : window.document()->classes().classes())
            colours.insert(row.colorRgb);
        QCOMPARE(colours.size(), 55);

        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        QVERIFY(window.startPlanning());
        // While it plans, the map says so rather than "Not planned yet. Press Plan".
        QVERIFY2(window.canvas()->bannerText().startsWith(QStringLiteral("Planning…")),
                 qPrintable(window.canvas()->bannerText()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY2(finished.first().first().toBool(), qPrintable(window.lastError()));
        QVERIFY2(window.canvas()->bannerText().isEmpty(), qPrintable(window.canvas()->bannerText()));
        for (const char* key : {"geojson", "kml", "gpx", "qgc-plan", "png", "report-json"}) {
            auto* action = window.findChild<QAction*>(QStringLiteral("export_%1").arg(QLatin1String(key)));
            QVERIFY2(action != nullptr, key);
            const io::ExportFormat* format = io::findExportFormat(key);
            QCOMPARE(action->isEnabled(), !format->needsLongitudeLatitude);
            QCOMPARE(action->toolTip().contains("no CRS"), format->needsLongitudeLatitude);
        }
    }

    void plansLikeAUser() {
        QTemporaryDir directory;
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));

        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif"), QStringLiteral("nlcd-simplified")));
        ui::MissionDocument* document = window.document();
        QVERIFY(document->classes().size() >= 2);
        QApplication::processEvents();
        window.canvas()->zoomToFit();
        // The raster spans 34 x 43 km: a drone's 200-800 m swaths keep the plan to seconds, as in the sample.
        for (int r = 0; r < window.classTableModel()->rowCount(); ++r)
            QVERIFY(window.classTableModel()->setData(
                window.classTableModel()->index(r, ui::ClassTableModel::FieldOfView),
                QString::number(200 << (r % 3))));

        // Three starts by clicking on the map with the Place start tool.
        auto* placeTool = window.findChild<QAction*>(QStringLiteral("placeStartToolAction"));
        QVERIFY(placeTool != nullptr);
        placeTool->trigger();
        const auto spots = passableSpots(*document, 3);
        QCOMPARE(spots.size(), std::size_t{3});
        for (const MapPoint& spot : spots)
            QTest::mouseClick(window.canvas(), Qt::LeftButton, {},
                              window.canvas()->devicePointOf(spot).toPoint());
        QCOMPARE(document->robots().size(), std::size_t{3});
        // The status line gives the start in degrees too (the raster lies in Utah: north and west).
        QVERIFY2(window.lastStatusMessage().startsWith(QStringLiteral("Added ")) &&
                     window.lastStatusMessage().contains(QStringLiteral("° N, ")) &&
                     window.lastStatusMessage().endsWith(QStringLiteral("° W.")),
                 qPrintable(window.lastStatusMessage()));

        // A click outside the map is refused with a message, and nothing is added.
        const QPointF outside = window.canvas()->devicePointOf(
            {document->grid()->originX - 500.0, document->grid()->originY + 500.0});
        if (window.canvas()->rect().contains(outside.toPoint())) {
            QTest::mouseClick(window.canvas(), Qt::LeftButton, {}, outside.toPoint());
            QCOMPARE(document->robots().size(), std::size_t{3});
            QVERIFY(window.lastStatusMessage().contains(QStringLiteral("outside")));
        }

        // Edit a speed in the class table.
        ui::ClassTableModel* classes = window.classTableModel();
        int row = -1;
        for (int r = 0; r < classes->rowCount() && row < 0; ++r)
            if (document->classes().classes()[static_cast<std::size_t>(r)].isTraversable())
                row = r;
        QVERIFY(row >= 0);
        QVERIFY(classes->setData(classes->index(row, ui::ClassTableModel::Speed), QStringLiteral("2.5")));
        QCOMPARE(document->classes().classes()[static_cast<std::size_t>(row)].speedMetresPerSecond, 2.5);
        QVERIFY(!classes->setData(classes->index(row, ui::ClassTableModel::Speed), QStringLiteral("-3")));

        // Plan off the GUI thread and wait.
        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        QElapsedTimer planningTime;
        planningTime.start();
        QVERIFY(window.startPlanning());
        QVERIFY(window.isPlanning());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY2(finished.first().first().toBool(), qPrintable(window.lastError()));
        qInfo("planned in %lld ms", static_cast<long long>(planningTime.elapsed()));
        QVERIFY(document->plan() != nullptr);
        QVERIFY(!document->planStale());
        // The size of the waypoint files follows, worked out beside the window.
        auto* waypointFiles = window.resultsPanel()->findChild<QLabel*>(QStringLiteral("waypointFilesLabel"));
        QVERIFY(waypointFiles != nullptr);
        QTRY_VERIFY(!waypointFiles->isHidden());
        QVERIFY2(waypointFiles->text().startsWith(QStringLiteral("one file per robot")) ||
                     waypointFiles->text().contains(QStringLiteral("in parts")),
                 qPrintable(waypointFiles->text()));
        // A cruise speed the whole fleet shares is planned with: setting one makes the plan out of date.
        const io::ExportSettings asPlanned = document->mission().exports;
        io::ExportSettings flown = asPlanned;
        flown.vehicle.cruiseSpeedMetresPerSecond = 9.0;
        document->setVehicles(flown, {});
        QVERIFY(document->planStale());
        document->setVehicles(asPlanned, {});
        QVERIFY(!document->planStale());

        // The legend follows: classes, then each robot by name with its time.
        const auto& legend = window.legendPanel()->sections();
        QCOMPARE(legend.size(), std::size_t{3});
        QCOMPARE(legend[0].items.size(), document->classes().size());
        QCOMPARE(legend[1].items.size(), document->robots().size());
        QVERIFY(legend[1].items[0].label.startsWith(QString::fromStdString(document->robots()[0].name)));

        // Results.
        QTableWidget* results = window.resultsPanel()->robotTable();
        QCOMPARE(results->rowCount(), 3);
        QVERIFY(window.resultsPanel()->makespanText() != QStringLiteral("–"));
        // Times count turns (turn_s auto), and the time says how much of it.
        QVERIFY(document->plan()->metrics.robots[0].turnSeconds > 0.0);
        QVERIFY(results->item(0, 4)->toolTip().contains("lost slowing down for turns"));
        QVERIFY(window.resultsPanel()->ratioText().toDouble() >= 0.99);
        QVERIFY(results->isColumnHidden(6)); // no sorties without batteries

        // Undo the speed edit, then the last start: the plan goes stale, visibly.
        window.undoStack()->undo();
        QVERIFY(document->classes().classes()[static_cast<std::size_t>(row)].speedMetresPerSecond != 2.5);
        QVERIFY(document->planStale());
        window.undoStack()->undo();
        QCOMPARE(document->robots().size(), std::size_t{2});
        auto* staleLabel = window.findChild<QLabel*>(QStringLiteral("resultsStaleLabel"));
        QVERIFY(staleLabel != nullptr && staleLabel->isVisible());
        window.undoStack()->redo();
        window.undoStack()->redo();
        QCOMPARE(document->robots().size(), std::size_t{3});
        QCOMPARE(document->classes().classes()[static_cast<std::size_t>(row)].speedMetresPerSecond, 2.5);

        // Export GeoJSON and read it back.
        const QString geojson = directory.filePath(QStringLiteral("plan.geojson"));
        QSignalSpy exported(&window, &ui::MainWindow::exportFinished);
        const auto exportAndWait = [&](const std::string& key, const QString& path) {
            if (!window.exportPlan(key, path))
                return false;
            // The export runs in the background and reports when it is done.
            if (exported.isEmpty() && !exported.wait(60000))
                return false;
            return exported.takeFirst().at(0).toBool();
        };
        QVERIFY2(exportAndWait("geojson", geojson), qPrintable(window.lastError()));
        QFile file(geojson);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QJsonParseError parseError;
        const QJsonDocument json = QJsonDocument::fromJson(file.readAll(), &parseError);
        QCOMPARE(parseError.error, QJsonParseError::NoError);
        QCOMPARE(json.object().value(QStringLiteral("type")).toString(), QStringLiteral("FeatureCollection"));
        QVERIFY(!json.object().value(QStringLiteral("features")).toArray().isEmpty());

        // While an export runs the window shows it: the stage, a bar, Cancel and a busy cursor. One file
        // has no count to show, so its bar is a busy one; files per robot are counted.
        auto* bar = window.findChild<QProgressBar*>(QStringLiteral("planningProgress"));
        auto* cancel = window.findChild<QPushButton*>(QStringLiteral("cancelPlanningButton"));
        QVERIFY(bar != nullptr && cancel != nullptr);
        const auto showsExport = [&](int countedFiles) {
            return bar->isVisible() && bar->minimum() == 0 && bar->maximum() == countedFiles &&
                   cancel->isVisible() && cancel->isEnabled() &&
                   QGuiApplication::overrideCursor() != nullptr &&
                   QGuiApplication::overrideCursor()->shape() == Qt::BusyCursor;
        };
        QVERIFY(window.exportPlan("png", directory.filePath(QStringLiteral("plan.png"))));
        QVERIFY(showsExport(0));
        QVERIFY(exported.wait(60000) && exported.takeFirst().at(0).toBool());
        QVERIFY(!bar->isVisible() && !cancel->isVisible() && QGuiApplication::overrideCursor() == nullptr);
        QVERIFY(window.exportPlan("waypoint-csv", directory.filePath(QStringLiteral("robot.csv"))));
        QVERIFY(showsExport(3));
        QVERIFY(exported.wait(60000) && exported.takeFirst().at(0).toBool());
        QCOMPARE(bar->value(), 3);
        QVERIFY(!bar->isVisible() && QGuiApplication::overrideCursor() == nullptr);
        QVERIFY(!QImage(directory.filePath(QStringLiteral("plan.png"))).isNull());
        // Waypoint files follow the robots' vehicles: no limit, one file per robot; a limit the mission is
        // above, consecutive parts instead.
        io::ExportSettings exports = window.document()->mission().exports;
        exports.vehicle.maxWaypoints = 0;
        window.document()->setVehicles(exports, {});
        QVERIFY(exportAndWait("qgc-plan", directory.filePath(QStringLiteral("mission.plan"))));
        QVERIFY(QFileInfo::exists(directory.filePath(QStringLiteral("mission-robot3.plan"))));
        exports.vehicle.maxWaypoints = 10;
        window.document()->setVehicles(exports, {});
        QVERIFY(exportAndWait("qgc-plan", directory.filePath(QStringLiteral("split.plan"))));
        QVERIFY(!QFileInfo::exists(directory.filePath(QStringLiteral("split-robot3.plan"))));
        const auto robot3Parts = [&] {
            QStringList parts =
                QDir(directory.path()).entryList({QStringLiteral("split-robot3_part_*.plan")});
            parts.sort();
            return parts;
        };
        const QStringList parts = robot3Parts();
        QVERIFY2(parts.size() >= 2, qPrintable(parts.join(QLatin1Char(' '))));
        // Numbered from 1, padded to one width: a file list shows them in the order they are flown.
        const QString last = QString::number(parts.size());
        QCOMPARE(parts.first(),
                 QStringLiteral("split-robot3_part_%1.plan").arg(1, last.size(), 10, QLatin1Char('0')));
        QCOMPARE(parts.last(), QStringLiteral("split-robot3_part_%1.plan").arg(last));
        const QString note = window.messageLog()->messages().last();
        QVERIFY2(note.contains(QStringLiteral("more than its autopilot's 10")) &&
                     note.contains(parts.first() + QStringLiteral(" to ") + parts.last()),
                 qPrintable(note));
        // The status bar counts the parts and names the first and last, not each of them.
        const QString status = window.lastStatusMessage();
        QVERIFY2(
            status.startsWith(QStringLiteral("Exported ")) &&
                status.contains(QStringLiteral(" files in ") + QDir::toNativeSeparators(directory.path())) &&
                status.endsWith(QStringLiteral(" to ") + parts.last() + QStringLiteral(")")) &&
                status.count(QStringLiteral(".plan")) == 2,
            qPrintable(status));
        // Exported whole to the same name again: the parts of the earlier export go.
        exports.vehicle.maxWaypoints = 0;
        window.document()->setVehicles(exports, {});
        QVERIFY(exportAndWait("qgc-plan", directory.filePath(QStringLiteral("split.plan"))));
        QVERIFY(QFileInfo::exists(directory.filePath(QStringLiteral("split-robot3.plan"))));
        QVERIFY2(robot3Parts().isEmpty(), qPrintable(robot3Parts().join(QLatin1Char(' '))));
        QVERIFY(!exportAndWait("geojson", QStringLiteral("/no/such/folder/plan.geojson")));
        QVERIFY(!window.isExporting());
        QVERIFY(window.lastError().contains(QStringLiteral("/no/such/folder/plan.geojson")));
        // The file is named once, not by the window and again by each writer it passed through.
        QVERIFY(!exportAndWait("png", QStringLiteral("/no/such/folder/plan.png")));
        QCOMPARE(window.lastError().count(QStringLiteral("/no/such/folder/plan.png")), 1);
        QCOMPARE(window.lastError().count(QStringLiteral("/no/such/folder/plan.geojson")), 0);

        // Save, reopen, and find the same robots and edited speed.
        const QString missionPath = directory.filePath(QStringLiteral("mission.json"));
        QVERIFY2(window.saveMission(missionPath), qPrintable(window.lastError()));
        QVERIFY(!window.isMissionModified());
        ui::MainWindow reopened;
        reopened.setDialogsEnabled(false);
        reopened.setOpenSampleOnFirstStart(false);
        QVERIFY2(reopened.openMission(missionPath), qPrintable(reopened.lastError()));
        QCOMPARE(reopened.document()->robots().size(), std::size_t{3});
        QCOMPARE(reopened.document()->classes().classes()[static_cast<std::size_t>(row)].speedMetresPerSecond,
                 2.5);

        // The plan was saved beside the mission and comes back without planning, up to date.
        QVERIFY(QFileInfo::exists(directory.filePath(QStringLiteral("mission.mcpp-plan"))));
        QVERIFY(reopened.lastStatusMessage().contains(QStringLiteral("Restored its saved plan")));
        QVERIFY(reopened.document()->plan() != nullptr);
        QVERIFY(!reopened.document()->planStale());
        QCOMPARE(reopened.document()->plan()->metrics.makespanSeconds,
                 document->plan()->metrics.makespanSeconds);
        QCOMPARE(reopened.document()->plan()->paths.size(), document->plan()->paths.size());
        QCOMPARE(reopened.resultsPanel()->robotTable()->rowCount(), 3);
        QVERIFY(!reopened.isMissionModified());
        // A new plan of a saved mission is a change to save.
        QSignalSpy replanned(&reopened, &ui::MainWindow::planningFinished);
        QVERIFY(reopened.startPlanning());
        QTRY_COMPARE_WITH_TIMEOUT(replanned.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY(reopened.isMissionModified());

        // A start moved in the file since: the saved plan is for other inputs and is not shown.
        auto edited = io::loadMission(missionPath.toStdString());
        QVERIFY(edited.ok());
        edited.value().robots[0].start.x += 0.5; // half a metre: the same pixel, another start
        QVERIFY(io::saveMission(edited.value(), missionPath.toStdString()).ok());
        ui::MainWindow changed;
        changed.setDialogsEnabled(false);
        changed.setOpenSampleOnFirstStart(false);
        QVERIFY2(changed.openMission(missionPath), qPrintable(changed.lastError()));
        QVERIFY(changed.document()->plan() == nullptr);
        QVERIFY(changed.lastStatusMessage().contains(QStringLiteral("made from other inputs")));
    }

    // Planning can be cancelled. NLCD's groups at their preset's fields of view (5 m in forest) over
    // 1430 km2 are said to be large as the planning starts, with the factor Scale FOVs would take; with the
    // fields of view widened, they are not.
    void cancelsPlanning_data() {
        QTest::addColumn<bool>("widened");
        QTest::newRow("widened fields of view") << true;
        QTest::newRow("the preset's: a large mission") << false;
    }

    void cancelsPlanning() {
        QFETCH(bool, widened);
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif"), QStringLiteral("nlcd-simplified")));
        if (widened)
            widenFieldsOfView(*window.classTableModel(), *window.document());
        for (const MapPoint& spot : passableSpots(*window.document(), 2))
            QVERIFY(window.robotTableModel()->addRobot(spot));
        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        QVERIFY(window.startPlanning());
        window.cancelPlanning();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        // Either the planner stopped, or it had already finished: both leave a usable window.
        QVERIFY(!window.isPlanning());
        const QString said =
            window.messageLog()->messages().filter(QStringLiteral("A large mission")).join('|');
        if (widened) {
            QVERIFY2(said.isEmpty(), qPrintable(said));
            return;
        }
        QVERIFY2(said.startsWith(QStringLiteral("A large mission: covering 1430 km2 of passable land")),
                 qPrintable(window.messageLog()->messages().join('\n')));
        QVERIFY2(
            said.contains(QStringLiteral("Scaling every FOV by 1.4 (Edit selected… > Scale FOVs) brings it")),
            qPrintable(said));
    }

    // A drone whose flight is too short for its climb and descent is refused before planning or comparing,
    // as batch mode refuses it, naming the robot and where the window changes it.
    void refusesAFlightTooShortForTheClimb() {
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        io::Mission mission = test::twoRobotMission();
        mission.robots[1].vehicle.type = io::VehicleType::Multirotor;
        mission.robots[1].vehicle.altitudeMetres = 120.0;
        mission.robots[1].vehicle.flightTimeSeconds = 60.0;
        window.document()->reset(test::grassRaster(), mission, QString());
        QVERIFY(!window.startPlanning());
        QVERIFY(!window.isPlanning());
        QVERIFY2(
            window.lastError().startsWith(QStringLiteral("west: a flight of 1 min leaves no time to survey")),
            qPrintable(window.lastError()));
        QVERIFY2(window.lastError().contains(QStringLiteral("Robot vehicles")),
                 qPrintable(window.lastError()));
        mission.robots[1].vehicle.flightTimeSeconds = 75.0; // another figure: compare says it, not plan
        window.document()->reset(test::grassRaster(), mission, QString());
        QVERIFY(!window.startComparison({"mcpp-mlct"}));
        QVERIFY2(window.lastError().startsWith(QStringLiteral("west: a flight of 1 min 15 s")),
                 qPrintable(window.lastError()));

        mission.robots[1].vehicle.flightTimeSeconds = 600.0; // long enough: plans
        window.document()->reset(test::grassRaster(), mission, QString());
        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        QVERIFY2(window.startPlanning(), qPrintable(window.lastError()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY2(finished.first().first().toBool(), qPrintable(window.lastError()));
        // The plan's warnings and notes are kept whole in the Messages panel, as every message is.
        const Plan* plan = window.document()->plan();
        QVERIFY(plan != nullptr && !plan->issues.empty());
        const QStringList messages = window.messageLog()->messages();
        for (const PlanIssue& issue : plan->issues)
            QVERIFY2(std::any_of(messages.begin(), messages.end(),
                                 [&](const QString& message) {
                                     return message.contains(QString::fromStdString(issue.message));
                                 }),
                     issue.message.c_str());
        // The legend says when the drone is done in the field (its climbs, descents and trips from its
        // start come on top of its path), once worked out beside the window; the rover's line does not.
        const auto robotLine = [&](std::size_t robot) {
            const auto& sections = window.legendPanel()->sections();
            return sections.size() > 1 && robot < sections[1].items.size() ? sections[1].items[robot].label
                                                                           : QString();
        };
        QTRY_VERIFY2(robotLine(1).contains(QStringLiteral("; in the field ")), qPrintable(robotLine(1)));
        QVERIFY2(!robotLine(0).contains(QStringLiteral("in the field")), qPrintable(robotLine(0)));
    }

    // Rovers crawling for weeks over the whole map: the Messages and Results panels say what to change in
    // the window.
    void weeksOfWorkSayWhatToChange() {
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        io::Mission mission = test::twoRobotMission();
        mission.classes = ClassTable({LandCoverClass{1, "Grass", 0x80c080, 0.0002, 10.0, true}});
        window.document()->reset(test::grassRaster(), mission, QString());
        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        QVERIFY2(window.startPlanning(), qPrintable(window.lastError()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY2(finished.first().first().toBool(), qPrintable(window.lastError()));
        const QStringList advice =
            window.messageLog()->messages().filter(QStringLiteral("Note: The robots need"));
        QCOMPARE(advice.size(), 1);
        QVERIFY2(advice.first().contains(QStringLiteral("Plan ▸ Draw area of interest")),
                 qPrintable(advice.first()));
        QVERIFY2(
            advice.first().contains(QStringLiteral("set their vehicle and cruise speed in Plan ▸ Robot "
                                                   "vehicles… (the class table's speeds, 0.0002 m/s, are "
                                                   "a ground robot's)")),
            qPrintable(advice.first()));
        // Where the user looks after planning too: the Results panel's notes.
        auto* notes = window.resultsPanel()->findChild<QLabel*>(QStringLiteral("notesLabel"));
        QVERIFY(notes != nullptr && !notes->isHidden());
        QVERIFY2(notes->text().contains(QStringLiteral("Plan ▸ Robot vehicles…")), qPrintable(notes->text()));
    }

    // Starts the window's own checks pass but the planner refuses (two in one cell of its grid): the
    // message names the robot as the robot table does and gives the advice in the window's terms.
    void refusesStartsSharingACellWithAdvice() {
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        io::Mission mission = test::twoRobotMission();
        mission.robots[1].start = {mission.robots[0].start.x + 1.0, mission.robots[0].start.y};
        window.document()->reset(test::grassRaster(), mission, QString());
        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        QVERIFY2(window.startPlanning(), qPrintable(window.lastError()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY(!finished.first().first().toBool());
        const QString error = window.lastError();
        QVERIFY2(error.startsWith(QStringLiteral("west's start: ")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("place the starts farther apart, or let the planner start the "
                                               "robot from the nearest free cell (tick \"Move blocked starts "
                                               "to the nearest free cell\" in the Planner panel)")),
                 qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral(" across) (robot 1 is east); each robot sets off")),
                 qPrintable(error));

        // Compare names the refusal the same way, row by row.
        QSignalSpy compared(&window, &ui::MainWindow::comparisonFinished);
        QVERIFY2(window.startComparison({"mcpp-mlct", "darp"}), qPrintable(window.lastError()));
        QTRY_COMPARE_WITH_TIMEOUT(compared.count(), 1, kPlanningTimeoutMilliseconds);
        QTableWidget* table = window.comparisonPanel()->table();
        QCOMPARE(table->rowCount(), 2);
        for (int row = 0; row < table->rowCount(); ++row) {
            const QString tip = table->item(row, table->columnCount() - 1)->toolTip();
            QVERIFY2(tip.startsWith(QStringLiteral("west's start: ")), qPrintable(tip));
            QVERIFY2(tip.contains(QStringLiteral("(robot 1 is east)")), qPrintable(tip));
        }
    }

    // Opening another map while planners are compared drops the comparison: its rows leave the panel (no
    // row left "planning…") and the banner no longer says a comparison is under way.
    void anotherMapDropsARunningComparison() {
        const std::unique_ptr<ui::MainWindow> owned = sampleWindow();
        if (!owned)
            QSKIP("samples/zion-nlcd/mission.json is not there yet");
        ui::MainWindow& window = *owned;
        QVERIFY2(window.document()->hasMap(), qPrintable(window.lastError()));
        QSignalSpy finished(&window, &ui::MainWindow::comparisonFinished);
        QVERIFY2(window.startComparison({"mcpp-mlct", "darp", "mstc"}), qPrintable(window.lastError()));
        QCOMPARE(window.comparisonPanel()->table()->rowCount(), 3);
        const QString raster = QFileInfo(ui::findSampleMission()).dir().filePath(QStringLiteral("nlcd.tif"));
        QVERIFY2(window.openRaster(raster), qPrintable(window.lastError()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY(!finished.first().first().toBool());
        QCOMPARE(window.comparisonPanel()->table()->rowCount(), 0);
        QVERIFY2(!window.canvas()->bannerText().startsWith(QStringLiteral("Comparing")),
                 qPrintable(window.canvas()->bannerText()));
    }

    // The Compare action: planners run one after another in the background, the panel lists one row each
    // (one-robot planners cannot take part with several robots), the table sorts, and selecting a row
    // shows that plan: the map, the results and the exports are then about it.
    void comparesPlanners() {
        const std::unique_ptr<ui::MainWindow> owned = sampleWindow();
        if (!owned)
            QSKIP("samples/zion-nlcd/mission.json is not there yet");
        ui::MainWindow& window = *owned;
        QVERIFY2(window.document()->hasMap(), qPrintable(window.lastError()));
        QCoreApplication::processEvents();
        ui::ComparisonPanel* panel = window.comparisonPanel();
        auto* spiral = panel->findChild<QCheckBox*>(QStringLiteral("compare_spiral-stc"));
        QVERIFY(spiral != nullptr && !spiral->isEnabled()); // five robots
        // Checked at first: the planners that cover all the land they reach; the battery planner, whose
        // reach the map may dwarf, is offered unchecked and says why.
        const std::vector<std::string> byDefault = panel->checkedPlanners();
        QVERIFY(std::find(byDefault.begin(), byDefault.end(), "darp") != byDefault.end());
        QVERIFY(std::find(byDefault.begin(), byDefault.end(), "wavefront-battery") == byDefault.end());
        auto* battery = panel->findChild<QCheckBox*>(QStringLiteral("compare_wavefront-battery"));
        QVERIFY(battery != nullptr && battery->isEnabled() && !battery->isChecked());
        QVERIFY2(battery->toolTip().contains(QStringLiteral("uncovered")), qPrintable(battery->toolTip()));
        panel->setCheckedPlanners({"mcpp-mlct", "darp", "mstc", "spiral-stc", "wavefront-battery"});
        QCOMPARE(panel->checkedPlanners(),
                 (std::vector<std::string>{"mcpp-mlct", "darp", "mstc", "wavefront-battery"}));

        QSignalSpy finished(&window, &ui::MainWindow::comparisonFinished);
        // Each planner's row is filled in as it is done, the others listed as to come.
        QStringList statesAfterFirst;
        connect(&window, &ui::MainWindow::comparisonProgressed, this, [&](int done) {
            if (done != 1)
                return;
            QTableWidget* table = panel->table();
            for (int row = 0; row < table->rowCount(); ++row)
                statesAfterFirst << table->item(row, table->columnCount() - 1)->text();
        });
        auto* compare = window.findChild<QAction*>(QStringLiteral("compareAction"));
        QVERIFY(compare != nullptr && compare->isEnabled());
        compare->trigger();
        QVERIFY(window.isComparing() || finished.count() == 1);
        // At once, every planner listed and the map saying what is under way.
        QCOMPARE(panel->table()->rowCount(), 4);
        QVERIFY2(window.canvas()->bannerText().startsWith(QStringLiteral("Comparing planners…")),
                 qPrintable(window.canvas()->bannerText()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY(finished.takeFirst().at(0).toBool());
        QCOMPARE(statesAfterFirst.size(), 4);
        QCOMPARE(statesAfterFirst.filter(QStringLiteral("planned")).size(), 1);
        QCOMPARE(statesAfterFirst.filter(QStringLiteral("planning…")).size(), 1);
        QCOMPARE(statesAfterFirst.filter(QStringLiteral("waiting")).size(), 2);

        QTableWidget* table = panel->table();
        QCOMPARE(table->rowCount(), 4);
        // Each compared plan's warnings are kept in the messages panel, named by planner (MSTC's pieces
        // from start to start are uneven).
        const QStringList mstcWarnings =
            window.messageLog()->messages().filter(QStringLiteral("Warning: mstc: "));
        QVERIFY2(!mstcWarnings.isEmpty(), qPrintable(window.messageLog()->messages().join('\n')));
        // One every plan carries (the mission's own) once, under no planner's name, one some carry once,
        // under theirs: no warning twice.
        QStringList warnings = window.messageLog()->messages().filter(QStringLiteral("Warning: "));
        for (QString& warning : warnings)
            warning = warning.mid(warning.indexOf(QStringLiteral("Warning: ")));
        QCOMPARE(QSet<QString>(warnings.begin(), warnings.end()).size(), warnings.size());
        QVERIFY(!panel->sheet()->pixmap().isNull());
        // No plan shown yet: the map says how to show one, not only to plan.
        QVERIFY(window.document()->plan() == nullptr);
        QVERIFY2(
            window.canvas()->bannerText().contains(QStringLiteral("select a row under Compare planners")),
            qPrintable(window.canvas()->bannerText()));
        // Sorted by ratio, by value, each shown with its three decimals (1.000, not 1).
        int ratioColumn = -1;
        for (int column = 0; column < table->columnCount(); ++column)
            if (table->horizontalHeaderItem(column)->text() == QStringLiteral("Ratio"))
                ratioColumn = column;
        QVERIFY(ratioColumn >= 0);
        table->sortItems(ratioColumn, Qt::AscendingOrder);
        for (int row = 0; row < 4; ++row) {
            const QString ratio = table->item(row, ratioColumn)->text();
            QVERIFY2(ratio.size() > 2 && ratio.indexOf(QLatin1Char('.')) == ratio.size() - 4,
                     qPrintable(ratio));
            if (row > 0)
                QVERIFY(table->item(row - 1, ratioColumn)->text().toDouble() <= ratio.toDouble());
        }
        // Each planned row's state says "planned", or, where it has no time against the first, why ("covers
        // less"), and how many warnings, where a plan has some.
        int againstFirstColumn = -1;
        for (int column = 0; column < table->columnCount(); ++column)
            if (table->horizontalHeaderItem(column)->text() == QStringLiteral("x 1st"))
                againstFirstColumn = column;
        QVERIFY(againstFirstColumn >= 0);
        for (int row = 0; row < 4; ++row) {
            const QString state = table->item(row, table->columnCount() - 1)->text();
            const bool timedAgainstFirst = table->item(row, againstFirstColumn) != nullptr;
            QVERIFY2(state.startsWith(QStringLiteral("planned")) == timedAgainstFirst, qPrintable(state));
            QVERIFY2(timedAgainstFirst || state.startsWith(QStringLiteral("covers less")) ||
                         state.startsWith(QStringLiteral("flights too long")) ||
                         state.startsWith(QStringLiteral("at the class table's speeds")),
                     qPrintable(state));
        }

        const int darp = panel->rowOfPlanner("darp");
        QVERIFY(darp >= 0);
        table->selectRow(darp);
        QVERIFY(window.document()->plan() != nullptr);
        QCOMPARE(window.document()->plan()->planner, std::string("darp"));
        QCOMPARE(window.document()->plannerChoice().planner, std::string("darp"));
        QVERIFY(!window.document()->planStale());
        QVERIFY2(window.canvas()->bannerText().isEmpty(), qPrintable(window.canvas()->bannerText()));
        // A battery planner's plan depends on the robots' batteries, which only it counts: shown, it is not
        // out of date either.
        table->selectRow(panel->rowOfPlanner("wavefront-battery"));
        QCOMPARE(window.document()->plan()->planner, std::string("wavefront-battery"));
        QVERIFY(!window.document()->planStale());
        table->selectRow(panel->rowOfPlanner("darp"));
        QCOMPARE(window.document()->plan()->planner, std::string("darp"));

        // Exporting exports the plan shown.
        QTemporaryDir directory;
        QSignalSpy exported(&window, &ui::MainWindow::exportFinished);
        QVERIFY(window.exportPlan("report-json", directory.filePath(QStringLiteral("report.json"))));
        QTRY_COMPARE_WITH_TIMEOUT(exported.count(), 1, kPlanningTimeoutMilliseconds);
        QFile report(directory.filePath(QStringLiteral("report.json")));
        QVERIFY(report.open(QIODevice::ReadOnly));
        QCOMPARE(
            QJsonDocument::fromJson(report.readAll()).object().value(QStringLiteral("planner")).toString(),
            QStringLiteral("darp"));
    }

    // Drones whose flights cannot reach all of the regions DARP gives them: its row counts the flights too
    // long among its warnings and names them when hovered (MCPP-MLCT's, which keeps each drone within its
    // reach, has none and is ranked first), Messages says them once under its planner's name, and showing the
    // plan does not say them again.
    void comparedPlansSayFlightsTheirBatteriesCannotFly() {
        const std::unique_ptr<ui::MainWindow> owned = sampleWindow();
        if (!owned)
            QSKIP("samples/zion-nlcd/mission.json is not there yet");
        ui::MainWindow& window = *owned;
        QVERIFY2(window.document()->hasMap(), qPrintable(window.lastError()));
        io::Mission mission = window.document()->mission();
        // The land beyond every drone's reach is left out. DARP shares the land within some drone's reach by
        // balance, and some of it lies beyond the reach of the drone given it; MCPP-MLCT gives that land to
        // drones that reach it.
        for (io::RobotSpec& robot : mission.robots) {
            robot.vehicle.type = io::VehicleType::Multirotor;
            robot.vehicle.altitudeMetres = 30.0;
            robot.vehicle.flightTimeSeconds = 3600.0; // about 18 km out and back at 10 m/s
            robot.vehicle.cruiseSpeedMetresPerSecond = 10.0;
        }
        mission.robots.front().vehicle.flightTimeSeconds = 300.0; // about 1.3 km
        window.document()->reset(window.document()->sharedRaster(), mission, QString());
        QSignalSpy finished(&window, &ui::MainWindow::comparisonFinished);
        QVERIFY2(window.startComparison({"mcpp-mlct", "darp"}), qPrintable(window.lastError()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY(finished.first().first().toBool());
        const QString tooLong = QStringLiteral(" with the flights to and from its start, longer than its ");
        QTableWidget* table = window.comparisonPanel()->table();
        QCOMPARE(table->rowCount(), 2);
        for (int row = 0; row < table->rowCount(); ++row) {
            const QTableWidgetItem* state = table->item(row, table->columnCount() - 1);
            QVERIFY2(state->text().contains(QStringLiteral("warning")), qPrintable(state->text()));
            const bool darp = row == window.comparisonPanel()->rowOfPlanner("darp");
            QVERIFY2(state->toolTip().contains(tooLong) == darp, qPrintable(state->toolTip()));
            // Ranked as batch mode ranks them: DARP's flights no drone can fly, MCPP-MLCT's first (in bold).
            QCOMPARE(table->item(row, 0)->font().bold(), !darp);
        }
        const auto flightWarnings = [&window, &tooLong](const QString& planner) {
            return window.messageLog()
                ->messages()
                .filter(QStringLiteral("Warning: ") + planner + ": ")
                .filter(tooLong);
        };
        const qsizetype darpSaid = flightWarnings(QStringLiteral("darp")).size();
        QVERIFY2(darpSaid > 0, qPrintable(window.messageLog()->messages().join('\n')));
        QCOMPARE(flightWarnings(QStringLiteral("mcpp-mlct")).size(), 0);
        const qsizetype allSaid = window.messageLog()->messages().filter(tooLong).size();
        // Shown: its waypoint files are sized again beside the window; what they find was said already.
        table->selectRow(window.comparisonPanel()->rowOfPlanner("darp"));
        QCOMPARE(window.document()->plan()->planner, std::string("darp"));
        const auto* waypointFiles =
            window.resultsPanel()->findChild<QLabel*>(QStringLiteral("waypointFilesLabel"));
        QVERIFY(waypointFiles != nullptr);
        QTRY_VERIFY_WITH_TIMEOUT(waypointFiles->text().contains(QStringLiteral("out of its reach")),
                                 kPlanningTimeoutMilliseconds);
        QTest::qWait(200);
        QCOMPARE(window.messageLog()->messages().filter(tooLong).size(), allSaid);
    }

    void toolbarAndAboutComeFromTheResources() {
        ui::MainWindow window;
        window.setOpenSampleOnFirstStart(false);
        auto* toolbar = window.findChild<QToolBar*>(QStringLiteral("mainToolBar"));
        QVERIFY(toolbar != nullptr);
        int withIcon = 0;
        for (QAction* action : toolbar->actions()) {
            if (action->isSeparator())
                continue;
            QVERIFY2(!action->icon().pixmap(24, 24).isNull(), qPrintable(action->text() + " has no icon"));
            ++withIcon;
        }
        QVERIFY(withIcon >= 10);
        // Undo keeps its label in the toolbar (the buttons after it stay put) and names the step in its
        // tooltip, as the Edit menu does in its text.
        QAction* undo = nullptr;
        for (QAction* action : toolbar->actions())
            if (action->text() == QStringLiteral("Undo"))
                undo = action;
        QVERIFY(undo != nullptr);
        QVERIFY(!undo->isEnabled());
        window.setDialogsEnabled(false);
        const QString sample = ui::findSampleMission();
        if (!sample.isEmpty()) {
            QVERIFY2(window.openMission(sample), qPrintable(window.lastError()));
            auto* stack = window.findChild<QUndoStack*>();
            QVERIFY(stack != nullptr);
            stack->push(new QUndoCommand(QStringLiteral("Move centre")));
            QVERIFY(undo->isEnabled());
            QCOMPARE(undo->text(), QStringLiteral("Undo"));
            QCOMPARE(undo->toolTip(), QStringLiteral("Undo Move centre"));
        }
        QVERIFY(!window.windowIcon().pixmap(48, 48).isNull());
        QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7"));
        const QString about = ui::aboutText();
        QVERIFY2(about.contains(QStringLiteral("9.8.7")), qPrintable(about));
        QVERIFY(about.contains(QStringLiteral("Copernicus")) &&
                about.contains(QStringLiteral("public domain")));
        QVERIFY(!about.contains(QStringLiteral("%1")) && !about.contains(QStringLiteral("%3")));
    }

    void opensTheSampleMission() {
        const QString sample = ui::findSampleMission();
        if (sample.isEmpty())
            QSKIP("samples/zion-nlcd/mission.json is not there yet");
        const std::unique_ptr<ui::MainWindow> owned = quietWindow();
        ui::MainWindow& window = *owned;
        QVERIFY2(window.openMission(sample), qPrintable(window.lastError()));
        QVERIFY(!window.document()->robots().empty());
        QCOMPARE(window.document()->missionPath(), QFileInfo(sample).absoluteFilePath());
    }

    // From the Help menu (and on a first start) the sample is an untitled copy: saving asks where, and
    // neither the recent files nor the dialogs' folders point into the bundled samples.
    void theSampleOpensAsAnUntitledCopy() {
        const QString sample = ui::findSampleMission();
        if (sample.isEmpty())
            QSKIP("samples/zion-nlcd/mission.json is not there yet");
        QSettings().clear();
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        auto* action = window.findChild<QAction*>(QStringLiteral("openSampleAction"));
        QVERIFY(action != nullptr);
        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        action->trigger();
        QVERIFY(window.document()->hasMap());
        QVERIFY(window.document()->missionPath().isEmpty());
        QVERIFY(window.windowTitle().contains(QStringLiteral("unsaved")));
        QVERIFY(!QSettings().contains(QStringLiteral("folders/mission")));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
    }

    // A new map starts from the planner's default settings; the planner itself stays.
    void aNewRasterStartsFromDefaultSettings() {
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif")));
        PlannerChoice tuned = switchPlanner(window.document()->plannerChoice(), "darp");
        tuned.parameters.set("convergence_tolerance", ParameterValue(0.05));
        QVERIFY(!(tuned == defaultPlannerChoice("darp")));
        window.document()->setPlannerChoice(tuned);
        QVERIFY(window.openRaster(dataPath("landcover/corine2006_swiss_ls100.tif")));
        QCOMPARE(window.document()->plannerChoice().planner, std::string("darp"));
        QVERIFY(window.document()->plannerChoice() == defaultPlannerChoice("darp"));
    }

    // A preset too fine for the machine's memory is caught on opening, not after Plan: the banner says so
    // and its button scales every FOV to the smallest that fits, as one undoable edit.
    void offersToScaleFieldsOfViewThatAreTooFine() {
        const std::int64_t budget = memoryBudgetBytes();
        setMemoryBudgetBytes(100'000'000);
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        window.show();
        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif"))); // 34 x 43 km, forests at 5 m
        ui::ClassTableBanner* banner = window.classTableBanner();
        QVERIFY(banner->hasSizeWarning());
        QVERIFY(banner->isWarning());
        QVERIFY2(banner->text().contains(QStringLiteral("Too fine to plan with MCPP-MLCT")),
                 qPrintable(banner->text()));
        auto* fit = banner->findChild<QPushButton*>(QStringLiteral("classTableFitButton"));
        QVERIFY(fit != nullptr && fit->isVisible());
        const double forestBefore = window.document()->classes().find(4)->fieldOfViewMetres;
        const int steps = window.undoStack()->count();
        fit->click();
        QVERIFY2(!banner->hasSizeWarning(), qPrintable(banner->text()));
        QCOMPARE(window.undoStack()->count(), steps + 1);
        const double forestAfter = window.document()->classes().find(4)->fieldOfViewMetres;
        QVERIFY(forestAfter > 5.0 * forestBefore);
        // The decomposition itself, held to the planner's figure, takes the scaled table.
        DecompositionOptions options;
        options.bytesPerBottomCell =
            findPlannerDescription(window.document()->plannerChoice().planner)->bytesPerBottomCell;
        QVERIFY(QuadTreeBuilder{}
                    .build(*window.document()->grid(), window.document()->classes(), options)
                    .activeCount() > 0);
        window.undoStack()->undo();
        QVERIFY(banner->hasSizeWarning());
        // A planner not measured at scale needs more per cell, and a grid planner plans on the uniform grid
        // of 2 x the smallest FOV (no top cells to round up to): the warning follows the planner chosen.
        const QString mlctWarning = banner->text();
        window.document()->setPlannerChoice(switchPlanner(window.document()->plannerChoice(), "darp"));
        QVERIFY(banner->hasSizeWarning());
        QVERIFY2(banner->text() != mlctWarning, qPrintable(banner->text()));
        QVERIFY2(banner->text().contains(QStringLiteral("with DARP")), qPrintable(banner->text()));
        const ClassGrid& grid = *window.document()->grid();
        const double gridCells = std::ceil(grid.width() / (2.0 * forestBefore) - 1e-9) *
                                 std::ceil(grid.height() / (2.0 * forestBefore) - 1e-9);
        const QString darpNeed =
            QStringLiteral("%1 GB of memory").arg(gridCells * unmeasuredBytesPerBottomCell / 1e9, 0, 'f', 1);
        QVERIFY2(banner->text().contains(darpNeed), qPrintable(banner->text() + " / " + darpNeed));
        setMemoryBudgetBytes(budget);
    }

    // An area from a vector file limits the task area; the robots stay, the mission saves it relative to
    // itself, and clearing it gives the whole map back.
    void areaOfInterestLimitsThePlan() {
        QTemporaryDir directory;
        const QString area = directory.filePath("area.geojson");
        QVERIFY(writeFile(area, R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":
            "urn:ogc:def:crs:EPSG::26912"}},"features":[{"type":"Feature","properties":{},"geometry":{"type":
            "Polygon","coordinates":[[[305000,4130000],[325000,4130000],[325000,4150000],[305000,4150000],
            [305000,4130000]]]}}]})"));
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif")));
        const auto insideCount = [&window] {
            std::int64_t inside = 0;
            for (const auto& [value, count] : window.document()->raster()->classPixelCounts)
                inside += count;
            return inside;
        };
        const std::int64_t whole = insideCount();
        QVERIFY(window.robotTableModel()->addRobot({315000, 4140000}));
        QVERIFY2(window.setAreaFiles(area, QString()), qPrintable(window.lastError()));
        const std::int64_t limited = insideCount();
        const ClassGrid& grid = *window.document()->grid();
        const double limitedArea = static_cast<double>(limited) * grid.pixelWidth * grid.pixelHeight;
        QVERIFY2(std::abs(limitedArea - 4e8) / 4e8 < 0.01, qPrintable(QString::number(limitedArea)));
        QCOMPARE(window.document()->robots().size(), std::size_t{1});
        QVERIFY(window.isMissionModified());

        const QString saved = directory.filePath("mission.json");
        QVERIFY(window.saveMission(saved));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
        QCOMPARE(json.value("area").toObject().value("include").toString(), QStringLiteral("area.geojson"));

        QSignalSpy finished(&window, &ui::MainWindow::planningFinished);
        for (int row = 0; row < window.classTableModel()->rowCount(); ++row)
            QVERIFY(window.classTableModel()->setData(
                window.classTableModel()->index(row, ui::ClassTableModel::FieldOfView),
                QStringLiteral("200")));
        QVERIFY(window.startPlanning());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kPlanningTimeoutMilliseconds);
        QVERIFY2(finished.first().first().toBool(), qPrintable(window.lastError()));
        for (const Waypoint& waypoint : window.document()->plan()->paths[0].waypoints) {
            QVERIFY(waypoint.x > 305000 - 400 && waypoint.x < 325000 + 400);
            QVERIFY(waypoint.y > 4130000 - 400 && waypoint.y < 4150000 + 400);
        }

        QVERIFY(window.setAreaFiles({}, {}));
        QCOMPARE(insideCount(), whole);
        // An area reaching past the raster's west edge (x 301 903): the window says how much is left out.
        const QString past = directory.filePath("past.geojson");
        QVERIFY(writeFile(past, R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":
            "urn:ogc:def:crs:EPSG::26912"}},"features":[{"type":"Feature","properties":{},"geometry":{"type":
            "Polygon","coordinates":[[[296903.344,4130000],[306903.344,4130000],[306903.344,4135000],
            [296903.344,4135000],[296903.344,4130000]]]}}]})"));
        QVERIFY2(window.setAreaFiles(past, QString()), qPrintable(window.lastError()));
        const QString status = window.statusBar()->currentMessage();
        QVERIFY2(status.contains(QStringLiteral("Area of interest: planning on ")) &&
                     status.contains(QStringLiteral(", 25 km2 lies off the raster and is left out")),
                 qPrintable(status));
        QVERIFY(window.setAreaFiles({}, {}));
        QVERIFY(!window.setAreaFiles(directory.filePath("absent.gpkg"), {}));
        QVERIFY(window.lastError().contains(QStringLiteral("absent.gpkg")));
        QCOMPARE(insideCount(), whole); // a refused area leaves the map as it was
    }

    // Plan > Draw area of interest and Draw no-go zone: clicked corners and a dragged rectangle limit the map
    // like area files do, and travel with the mission when it is saved.
    void areasDrawnOnTheMapLimitThePlan() {
        QTemporaryDir directory;
        ui::MainWindow window;
        QVERIFY(openForDrawing(window));
        ui::MapCanvas* canvas = window.canvas();
        const auto insideArea = [&window] { return areaToPlan(window); };
        const auto at = [canvas](double x, double y) { return canvas->devicePointOf({x, y}).toPoint(); };

        // A 20 x 20 km square by its corners, finished with Enter.
        window.findChild<QAction*>(QStringLiteral("drawAreaAction"))->trigger();
        QCOMPARE(canvas->tool(), ui::MapCanvas::Tool::DrawArea);
        for (const auto& [x, y] : std::vector<std::pair<double, double>>{
                 {305000, 4130000}, {325000, 4130000}, {325000, 4150000}, {305000, 4150000}})
            QTest::mouseClick(canvas, Qt::LeftButton, {}, at(x, y));
        QTest::keyClick(canvas, Qt::Key_Return);
        QCOMPARE(canvas->tool(), ui::MapCanvas::Tool::Pan);
        const QString drawnArea = QString::fromStdString(window.document()->mission().area.includePath);
        QVERIFY2(QRegularExpression(QStringLiteral("-area(-[0-9]+)?\\.geojson$")).match(drawnArea).hasMatch(),
                 qPrintable(drawnArea));
        const double square = insideArea();
        QVERIFY2(std::abs(square - 4e8) / 4e8 < 0.05, qPrintable(QString::number(square)));

        // A 5 x 5 km no-go rectangle dragged inside it.
        window.findChild<QAction*>(QStringLiteral("drawNoGoAction"))->trigger();
        QTest::mousePress(canvas, Qt::LeftButton, {}, at(310000, 4140000));
        QTest::mouseMove(canvas, at(312500, 4137500));
        QTest::mouseMove(canvas, at(315000, 4135000));
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, at(315000, 4135000));
        QVERIFY(!window.document()->mission().area.excludePath.empty());
        const double cut = square - insideArea();
        QVERIFY2(std::abs(cut - 2.5e7) / 2.5e7 < 0.1, qPrintable(QString::number(cut)));

        // An area of interest off the map is refused and changes no file in use.
        const auto dragRectangle = [canvas](QPoint from, QPoint to) {
            QTest::mousePress(canvas, Qt::LeftButton, {}, from);
            QTest::mouseMove(canvas, (from + to) / 2);
            QTest::mouseMove(canvas, to);
            QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
        };
        const io::AreaOfInterest before = window.document()->mission().area;
        // A small square beside the map, on whichever side the view leaves room once zoomed out a step.
        canvas->zoomOut();
        const ClassGrid& grid = *window.document()->grid();
        const double middleX = grid.originX + grid.width() / 2.0;
        const double middleY = grid.minY() + grid.height() / 2.0;
        // 30 pixels a side on screen, well over the 10 pixels a drag must cover to count as a rectangle.
        const double metresPerPixel =
            grid.width() / std::max(1.0, static_cast<double>(at(grid.originX + grid.width(), middleY).x() -
                                                             at(grid.originX, middleY).x()));
        const double side = 30.0 * metresPerPixel;
        std::pair<QPoint, QPoint> offMap;
        for (const auto& [x, y] :
             std::vector<std::pair<double, double>>{{grid.originX - 2.0 * side, middleY},
                                                    {grid.originX + grid.width() + side, middleY},
                                                    {middleX, grid.originY + side},
                                                    {middleX, grid.minY() - 2.0 * side}}) {
            const QPoint from = at(x, y + side);
            const QPoint to = at(x + side, y);
            if (canvas->rect().contains(from) && canvas->rect().contains(to))
                offMap = {from, to};
        }
        QVERIFY(offMap.first != offMap.second);
        window.findChild<QAction*>(QStringLiteral("drawAreaAction"))->trigger();
        dragRectangle(offMap.first, offMap.second);
        QVERIFY2(window.lastError().contains(QStringLiteral("leaves no pixel")),
                 qPrintable(window.lastError()));
        QVERIFY(window.document()->mission().area == before);
        QCOMPARE(insideArea(), square - cut);
        QVERIFY(QDir(QFileInfo(QString::fromStdString(before.excludePath)).absolutePath())
                    .entryList({QStringLiteral("*.trial")}, QDir::Files)
                    .isEmpty());

        // Saved, the drawn files go beside the mission and the mission names them there; a file of the user's
        // with the name the area would take is left as it was.
        QVERIFY(writeFile(directory.filePath("survey-area.geojson"), "the user's own notes"));
        QVERIFY(window.robotTableModel()->addRobot({320000, 4145000}));
        const QString saved = directory.filePath("survey.json");
        QVERIFY2(window.saveMission(saved), qPrintable(window.lastError()));
        QFile own(directory.filePath("survey-area.geojson"));
        QVERIFY(own.open(QIODevice::ReadOnly));
        QCOMPARE(own.readAll(), QByteArray("the user's own notes"));
        QVERIFY(QFileInfo::exists(directory.filePath("survey-area-2.geojson")));
        QVERIFY(QFileInfo::exists(directory.filePath("survey-no-go.geojson")));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject area = QJsonDocument::fromJson(file.readAll()).object().value("area").toObject();
        QCOMPARE(area.value("include").toString(), QStringLiteral("survey-area-2.geojson"));
        QCOMPARE(area.value("exclude").toString(), QStringLiteral("survey-no-go.geojson"));

        // A second no-go zone adds to the first, in a file of its own (the saved one stays as it was).
        window.findChild<QAction*>(QStringLiteral("drawNoGoAction"))->trigger();
        dragRectangle(at(318000, 4148000), at(323000, 4143000));
        QCOMPARE(QFileInfo(QString::fromStdString(window.document()->mission().area.excludePath)).fileName(),
                 QStringLiteral("survey-no-go-2.geojson"));
        const double bothCut = square - insideArea();
        QVERIFY2(std::abs(bothCut - 5e7) / 5e7 < 0.1, qPrintable(QString::number(bothCut)));
        QVERIFY(window.saveMission(saved));
        ui::MainWindow reopened;
        reopened.setDialogsEnabled(false);
        reopened.setOpenSampleOnFirstStart(false);
        QVERIFY2(reopened.openMission(saved), qPrintable(reopened.lastError()));
        std::int64_t inside = 0;
        for (const auto& [value, count] : reopened.document()->raster()->classPixelCounts)
            inside += count;
        QCOMPARE(static_cast<double>(inside) * reopened.document()->grid()->pixelWidth *
                     reopened.document()->grid()->pixelHeight,
                 insideArea());
    }

    // At 1600 x 1000 every layer toggle shows in the Layers dock without scrolling (in one column they took
    // nine rows, and "Area edges" was found by scrolling).
    void everyLayerToggleShowsWithoutScrolling() {
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QApplication::processEvents();
        auto* panel = window.findChild<QWidget*>(QStringLiteral("layersPanel"));
        QVERIFY(panel != nullptr);
        QWidget* viewport = panel->parentWidget();
        const QList<QCheckBox*> toggles = panel->findChildren<QCheckBox*>();
        QCOMPARE(toggles.size(), 9);
        for (const QCheckBox* toggle : toggles) {
            const QRect shown(toggle->mapTo(viewport, QPoint(0, 0)), toggle->size());
            QVERIFY2(viewport->rect().contains(shown),
                     qPrintable(QStringLiteral("%1 at %2,%3 %4 x %5 in a view of %6 x %7")
                                    .arg(toggle->text())
                                    .arg(shown.x())
                                    .arg(shown.y())
                                    .arg(shown.width())
                                    .arg(shown.height())
                                    .arg(viewport->width())
                                    .arg(viewport->height())));
        }
    }

    // Each drawn zone is one undo step: undone one by one, the map comes back zone by zone (each zone drawn
    // goes to a file of its own), and redone they all come back.
    void drawnZonesAreUndoneOneByOne() {
        ui::MainWindow window;
        QVERIFY(openForDrawing(window));
        ui::MapCanvas* canvas = window.canvas();
        const auto insideArea = [&window] { return areaToPlan(window); };
        const auto at = [canvas](double x, double y) { return canvas->devicePointOf({x, y}).toPoint(); };
        const auto drag = [&](const char* action, QPoint from, QPoint to) {
            window.findChild<QAction*>(QString::fromLatin1(action))->trigger();
            QTest::mousePress(canvas, Qt::LeftButton, {}, from);
            QTest::mouseMove(canvas, (from + to) / 2);
            QTest::mouseMove(canvas, to);
            QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
        };
        auto* stack = window.findChild<QUndoStack*>();
        QVERIFY(stack != nullptr);
        const double wholeMap = insideArea();
        drag("drawAreaAction", at(305000, 4150000), at(325000, 4130000));
        const double square = insideArea();
        drag("drawNoGoAction", at(310000, 4140000), at(315000, 4135000));
        const double oneZone = insideArea();
        const std::string zonesFile = window.document()->mission().area.excludePath;
        drag("drawNoGoAction", at(318000, 4148000), at(323000, 4143000));
        const double twoZones = insideArea();
        const std::string bothZonesFile = window.document()->mission().area.excludePath;
        QVERIFY(bothZonesFile != zonesFile); // a file of its own: the first zone's file stays as it was
        QVERIFY2(
            square < 0.9 * wholeMap && oneZone < square && twoZones < oneZone,
            qPrintable(QStringLiteral("%1 %2 %3 %4").arg(wholeMap).arg(square).arg(oneZone).arg(twoZones)));
        QCOMPARE(stack->count(), 3);
        QCOMPARE(stack->undoText(), QStringLiteral("Draw no-go zone"));
        QVERIFY(window.isMissionModified());

        stack->undo();
        QCOMPARE(window.document()->mission().area.excludePath, zonesFile);
        QCOMPARE(insideArea(), oneZone); // the file holds the first zone only again
        stack->undo();
        QVERIFY(window.document()->mission().area.excludePath.empty());
        QCOMPARE(insideArea(), square);
        stack->undo();
        QVERIFY(window.document()->mission().area.empty());
        QCOMPARE(insideArea(), wholeMap);
        QVERIFY(!window.isMissionModified());

        for (int step = 0; step < 3; ++step)
            stack->redo();
        QCOMPARE(window.document()->mission().area.excludePath, bothZonesFile);
        QCOMPARE(insideArea(), twoZones);

        // Clearing the area is a step too.
        window.findChild<QAction*>(QStringLiteral("clearAreaAction"))->trigger();
        QCOMPARE(insideArea(), wholeMap);
        stack->undo();
        QCOMPARE(insideArea(), twoZones);

        // A step whose file has gone away says so, leaves the map as it is and leaves the stack; the map is
        // then not the one saved, even where the stack's index comes back to the saved one.
        stack->undo();
        stack->setClean(); // as if saved with the first zone
        stack->redo();
        QVERIFY(QFile::remove(QString::fromStdString(zonesFile)));
        stack->undo();
        QCOMPARE(window.document()->mission().area.excludePath, bothZonesFile);
        QCOMPARE(insideArea(), twoZones);
        QVERIFY2(window.lastError().contains(QFileInfo(QString::fromStdString(zonesFile)).fileName()),
                 qPrintable(window.lastError()));
        QCOMPARE(stack->count(), 3);
        QCOMPARE(stack->undoText(), QStringLiteral("Draw no-go zone")); // the first zone's step
        QVERIFY(window.isMissionModified());
        // So does a step redone whose file has gone, and Redo then names the step after it.
        stack->undo();
        QCOMPARE(insideArea(), square);
        stack->redo();
        QCOMPARE(insideArea(), square);
        QCOMPARE(stack->count(), 2);
        auto* redoAction = window.findChild<QAction*>(QStringLiteral("redoAction"));
        QTRY_COMPARE(redoAction->text(), QStringLiteral("&Redo Clear area and no-go zones"));
        // The last step redone in vain: Redo greys out, and a mission saved just before it stays saved.
        drag("drawNoGoAction", at(310000, 4140000), at(315000, 4135000));
        QCOMPARE(stack->count(), 2); // the new zone's step replaced the clearing one
        const std::string newZoneFile = window.document()->mission().area.excludePath;
        stack->undo();
        stack->setClean();
        QVERIFY(QFile::remove(QString::fromStdString(newZoneFile)));
        stack->redo();
        QCOMPARE(insideArea(), square);
        QCOMPARE(stack->count(), 1);
        QTRY_VERIFY(!redoAction->isEnabled());
        QVERIFY(!window.isMissionModified());
    }

    // A class table loaded from a CSV is neither a preset nor the legend: the preset box says so.
    void presetBoxNamesALoadedTable() {
        QTemporaryDir directory;
        ui::MainWindow window;
        window.setDialogsEnabled(false);
        window.setOpenSampleOnFirstStart(false);
        QVERIFY(window.openRaster(dataPath("landcover/nlcd.tif")));
        QCOMPARE(window.presetCombo()->currentData().toString(), QStringLiteral("nlcd-simplified"));
        const QString legend = directory.filePath("legend.csv");
        QVERIFY(writeFile(legend, "value,name\n1,Water\n"));
        QVERIFY(!window.loadClassTable(legend));
        QVERIFY2(window.lastStatusMessage().contains(QStringLiteral("a legend of names does not")),
                 qPrintable(window.lastStatusMessage()));
        const QString csv = directory.filePath("own.csv");
        QVERIFY(writeFile(csv, "value,name,speed_mps,fov_m,passable\n1,Water,0,10,false\n2,Town,0,10,false\n"
                               "3,Rock,2,20,true\n4,Wood,0.4,5,true\n5,Scrub,1,10,true\n6,Meadow,2,20,true\n"
                               "7,Fields,1,10,true\n8,Marsh,0.2,5,true\n"));
        QVERIFY2(window.loadClassTable(csv), qPrintable(window.lastError()));
        // The legend's error gives way to what was loaded.
        QCOMPARE(window.lastStatusMessage(),
                 QStringLiteral("Loaded the class table %1 (8 classes).").arg(QDir::toNativeSeparators(csv)));
        QVERIFY(window.presetCombo()->currentText().startsWith(QStringLiteral("Own table")));
        window.undoStack()->undo();
        QCOMPARE(window.presetCombo()->currentData().toString(), QStringLiteral("nlcd-simplified"));
        // The preset's table edited (every FOV scaled, as the memory warning offers) is no longer the preset.
        ui::ClassBulkEdit scaled;
        scaled.fieldOfViewFactor = 2.0;
        QVERIFY(window.classTableModel()->editRows({0, 1, 2}, scaled));
        QVERIFY(window.presetCombo()->currentText().startsWith(QStringLiteral("Own table")));
        QCOMPARE(window.document()->mission().preset, std::string("nlcd-simplified")); // where it came from
        window.undoStack()->undo();
        QCOMPARE(window.presetCombo()->currentData().toString(), QStringLiteral("nlcd-simplified"));
        // One field of view over every class (a mission's classes.fov_m, a drone's footprint) keeps it the
        // preset the banner says was applied; another FOV on some classes only does not.
        ui::ClassBulkEdit footprint;
        footprint.fieldOfView = 40.0;
        QList<int> everyRow;
        for (int row = 0; row < window.classTableModel()->rowCount(); ++row)
            everyRow.append(row);
        QVERIFY(window.classTableModel()->editRows(everyRow, footprint));
        QCOMPARE(window.presetCombo()->currentData().toString(), QStringLiteral("nlcd-simplified"));
        footprint.fieldOfView = 60.0;
        QVERIFY(window.classTableModel()->editRows({0}, footprint));
        QVERIFY(window.presetCombo()->currentText().startsWith(QStringLiteral("Own table")));
    }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
