#include "core/model/ClassTable.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"
#include "tests/support/TestData.hpp"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <memory>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

namespace {

struct RunResult {
    int exitCode = -1;
    QString standardOutput;
    QString standardError;
};

QString samplePath(const QString& relative) {
    return QString::fromStdString(mcpp::test::sourcePath("samples/" + relative.toStdString()));
}

QJsonObject readJsonObject(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QJsonParseError error;
    const auto document = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError)
        return {};
    return document.object();
}

// A sample mission with its raster's path made absolute, to be written elsewhere and changed.
QJsonObject sampleMissionAnywhere(const QString& folder, const QString& rasterFile) {
    QJsonObject mission = readJsonObject(samplePath(folder + QStringLiteral("/mission.json")));
    QJsonObject raster = mission.value("raster").toObject();
    raster.insert("path", samplePath(folder + QLatin1Char('/') + rasterFile));
    mission.insert("raster", raster);
    return mission;
}

// Batch mode's name for a part of a robot's split mission, without the extension: "robot_2_part_3", the
// part's number padded with zeros to the width of the last one's ("robot_2_part_03" of 12).
QString partStem(int robot, int part, int parts) {
    const int width = static_cast<int>(QString::number(parts).size());
    return QStringLiteral("robot_%1_part_%2").arg(robot + 1).arg(part, width, 10, QLatin1Char('0'));
}

bool writeText(const QString& path, const QByteArray& text) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size();
}

bool nearlyEqual(double a, double b, double relative = 1e-6) {
    return std::abs(a - b) <= relative * std::max({1.0, std::abs(a), std::abs(b)});
}

// The synthetic sample's lake and nodata corner, in its CRS (EPSG:32633); see make_synthetic_map.py.
const QString syntheticOnLake = QStringLiteral("431300,5301110");
const QString syntheticOnNodata = QStringLiteral("431470,5301310");

} // namespace

class TestBatchEndToEnd : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void samplesAreValidMissions_data();
    void samplesAreValidMissions();
    void syntheticSampleNeedsThreeLevels();
    void missionFileWritesEveryOutput();
    void flagMissionWithLongitudeLatitudeStarts();
    void rerunWithFewerRobotsRemovesTheirFiles();
    void anAreaPastTheRastersEdgeIsAWarningInTheReport();
    void missingAsObstacleTurnsTheErrorIntoAWarning();
    void readmeSampleRuns();
    void missionsAboveTheItemLimitAreSplit();
    void droneFlagsPlanAtTheCruiseSpeed();
    void fovFlagGivesEveryClassOneFootprint();
    void aLargeMissionIsSaidBeforePlanning();
    void aRobotWalledInIsSaid();
    void outputsWritesOnlyWhatIsAsked();
    void batteryPlansWriteEachSortie();
    void aTurnaroundIsTheTimeAtTheCharger();
    void aChargerAwayFromTheStartIsWhereSortiesEnd();
    void aDroneLandsItsFirstSortieAtAChargerAway();
    void anAircraftOnTheLakeTakesOffThere();
    void detectionPlansWriteTheDetectionRaster();
    void exportsReadBackUnchangedInSubstance();
    void eventsArePlayedAndComparedWithTheStaticPlan();
    void rasterAloneGetsTheRecognisedProductsTable();
    void outputsAreTheSameWhateverTheThreadCount();
    void comparePlannersOnOneMission();
    void comparisonGivesTimesInTheField();
    void aComparisonSaysTheMissionsWarningsOnce();
    void aNoteThatDoesNotHoldForAPlanIsNotSaid();
    void weeksOfWorkSuggestAnArea();
    void everyPlannerRunsFromTheCommandLine_data();
    void everyPlannerRunsFromTheCommandLine();
    void badInputExitsTwoWithOneLine_data();
    void badInputExitsTwoWithOneLine();
    void warningsNameTheRobotsTheyNumber();

  private:
    RunResult
    runMcpp(const QStringList& arguments, int timeoutMilliseconds = 600000,
            const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) const;
    void checkOutputs(const QString& directory, int robots, const RunResult& run,
                      const QString& planner = QStringLiteral("mcpp-mlct")) const;
    QStringList syntheticFlags() const;

    QString executable_;
    QTemporaryDir scratch_;
};

void TestBatchEndToEnd::initTestCase() {
    executable_ = qEnvironmentVariable("MCPP_EXECUTABLE");
    QVERIFY2(!executable_.isEmpty(), "MCPP_EXECUTABLE is not set; run through ctest");
    QVERIFY2(QFileInfo(executable_).isExecutable(), qPrintable(executable_));
    QVERIFY(scratch_.isValid());
}

RunResult TestBatchEndToEnd::runMcpp(const QStringList& arguments, int timeoutMilliseconds,
                                     const QProcessEnvironment& environment) const {
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(executable_, arguments);
    RunResult result;
    if (!process.waitForFinished(timeoutMilliseconds)) {
        process.kill();
        process.waitForFinished();
        result.standardError = QStringLiteral("timed out");
        return result;
    }
    result.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    result.standardOutput = QString::fromUtf8(process.readAllStandardOutput());
    result.standardError = QString::fromUtf8(process.readAllStandardError());
    return result;
}

QStringList TestBatchEndToEnd::syntheticFlags() const {
    return {"--batch", "--raster", samplePath("synthetic/synthetic.asc"), "--classes",
            samplePath("synthetic/classes.csv")};
}

// Writers run side by side; each file must come out the same byte for byte with one thread or several
// (GeoPackage timestamps pinned; report.json compared without its timings).
void TestBatchEndToEnd::outputsAreTheSameWhateverTheThreadCount() {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("OGR_CURRENT_DATE", "2026-01-01T00:00:00Z");
    QStringList folders;
    for (const char* threads : {"1", "2", "4"}) {
        const QString out = scratch_.filePath(QStringLiteral("threads-%1").arg(QLatin1String(threads)));
        const auto run = runMcpp(
            {"--batch", samplePath("zion-nlcd/mission.json"), "--out", out, "--threads", threads, "--quiet"},
            600000, environment);
        QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
        folders << out;
    }
    const QStringList names = QDir(folders.front()).entryList(QDir::Files, QDir::Name);
    QVERIFY(names.size() > 10);
    for (const QString& folder : folders.mid(1)) {
        QCOMPARE(QDir(folder).entryList(QDir::Files, QDir::Name), names);
        for (const QString& name : names) {
            QFile first(QDir(folders.front()).filePath(name)), other(QDir(folder).filePath(name));
            QVERIFY(first.open(QIODevice::ReadOnly) && other.open(QIODevice::ReadOnly));
            if (name != "report.json") {
                QVERIFY2(first.readAll() == other.readAll(), qPrintable(folder + "/" + name));
                continue;
            }
            QJsonObject a = QJsonDocument::fromJson(first.readAll()).object();
            QJsonObject b = QJsonDocument::fromJson(other.readAll()).object();
            for (const char* timings : {"process_ms", "timings_ms"}) {
                a.remove(timings);
                b.remove(timings);
            }
            QVERIFY(!a.isEmpty());
            QCOMPARE(a, b);
        }
    }
}

// Drones on flights compared: each planner's row gives when its last robot is home and the bound in the
// field, as its report.json does, in comparison.json and comparison.csv, and the summary says it; each
// plan's warnings (here an event both planners leave out) are said as for one planner.
void TestBatchEndToEnd::comparisonGivesTimesInTheField() {
    const QString out = scratch_.filePath(QStringLiteral("compare-drones"));
    const auto run =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "mcpp-mlct,darp", "--vehicle",
                 "multirotor", "--cruise-speed", "6", "--fov-scale", "2", "--flight-time", "3min",
                 "--turnaround", "2min", "--event", "60:1:0.5", "--out", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    const QDir folder(out);
    const auto planners = readJsonObject(folder.filePath("comparison.json")).value("planners").toArray();
    QCOMPARE(planners.size(), 2);
    QFile csv(folder.filePath("comparison.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
    const QStringList header = lines.front().split(',');
    int warningsSaid = 0;
    for (int i = 0; i < planners.size(); ++i) {
        const auto row = planners.at(i).toObject();
        const QString name = row.value("planner").toString();
        const auto report = readJsonObject(folder.filePath(name + "/report.json"));
        const QStringList fields = lines.at(i + 1).split(',');
        for (const char* key : {"field_makespan_s", "field_lower_bound_s", "field_spread"}) {
            QVERIFY2(report.value(key).toDouble() > 0.0, key);
            QCOMPARE(row.value(key).toDouble(), report.value(key).toDouble());
            QVERIFY2(
                nearlyEqual(fields.at(header.indexOf(key)).toDouble(), report.value(key).toDouble(), 1e-12),
                key);
        }
        QVERIFY2(run.standardOutput.contains(QStringLiteral("the last robot home after ") +
                                             QString::fromStdString(mcpp::formatDuration(
                                                 report.value("field_makespan_s").toDouble()))),
                 qPrintable(run.standardOutput));
        // Flights longer than a battery, the robots' sum of report.json's, in both files.
        int overBattery = 0;
        for (const QJsonValue& robot : report.value("robots").toArray())
            overBattery += robot.toObject().value("mission_parts_over_flight_time").toInt();
        QCOMPARE(row.value("flights_over_battery").toInt(-1), overBattery);
        QCOMPARE(fields.at(header.indexOf("flights_over_battery")), QString::number(overBattery));
        // Each plan's warnings are said as it is made, named by its planner, as for one planner.
        const auto warnings = report.value("warnings").toArray();
        warningsSaid += static_cast<int>(warnings.size());
        for (const auto& warning : warnings)
            QVERIFY2(run.standardError.contains("mcpp: warning: " + name + ": " + warning.toString()),
                     qPrintable(name + ": " + warning.toString()));
    }
    QVERIFY(warningsSaid > 0); // the event, left out by both
    // The mission's own notes (on standard output), which both plans carry, are said once, under no name.
    const QString altitudeNote = QStringLiteral(
        "mcpp: aircraft fly at their altitude above home (where they take off), not above the ground");
    QVERIFY2(run.standardOutput.count(altitudeNote) == 1, qPrintable(run.standardOutput));
    QCOMPARE(run.standardOutput.count(QStringLiteral("every robot cruises at 6 m/s")), 1);
}

// A warning of the mission itself (aircraft without a cruise speed, land beyond every drone's reach), which
// every compared plan carries, is said once and under no planner's name.
void TestBatchEndToEnd::aComparisonSaysTheMissionsWarningsOnce() {
    const auto run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "mcpp-mlct,darp",
                              "--vehicle", "multirotor", "--out", scratch_.filePath("compare-aircraft")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    const QString warning = QStringLiteral("mcpp: warning: aircraft fly at the class table's speeds");
    QCOMPARE(run.standardError.count(warning), 1);
    QVERIFY(!run.standardError.contains(QStringLiteral("darp: aircraft fly")));
    QVERIFY(!run.standardError.contains(QStringLiteral("mcpp-mlct: aircraft fly")));
    // The land beyond every drone's reach (3 min flights at 2 m/s work 150 m out), which both plans leave
    // out alike, is said once too, under no name.
    const auto drones =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "mcpp-mlct,darp", "--vehicle",
                 "multirotor", "--cruise-speed", "2", "--flight-time", "3min", "--out",
                 scratch_.filePath("compare-drones-reach")});
    QVERIFY2(drones.exitCode == 0, qPrintable(drones.standardError));
    const QString beyond = QStringLiteral("of passable land lies too far from every start for one flight");
    QCOMPARE(drones.standardError.count(beyond), 1);
    const QStringList lines = drones.standardError.split('\n').filter(beyond);
    QCOMPARE(lines.size(), 1);
    QVERIFY2(QRegularExpression(QStringLiteral("^mcpp: warning: [0-9]")).match(lines.front()).hasMatch(),
             qPrintable(lines.front()));
    for (const char* planner : {"mcpp-mlct", "darp"}) {
        bool reported = false;
        const auto report = readJsonObject(scratch_.filePath(
            QStringLiteral("compare-drones-reach/%1/report.json").arg(QLatin1String(planner))));
        for (const QJsonValue& issue : report.value("issues").toArray())
            reported = reported ||
                       issue.toObject().value("code").toString() == QStringLiteral("beyond-flight-reach");
        QVERIFY2(reported, planner); // each plan's report still says it
        // The land left out is drawn with the land no robot covers: plan.geojson's unreachable polygons hold
        // as much of it as the report counts, to a sub-cell's rounding along their edges.
        double drawn = 0.0;
        const auto geoJson = readJsonObject(scratch_.filePath(
            QStringLiteral("compare-drones-reach/%1/plan.geojson").arg(QLatin1String(planner))));
        for (const QJsonValue& feature : geoJson.value("features").toArray()) {
            const QJsonObject properties = feature.toObject().value("properties").toObject();
            if (properties.value("kind").toString() == QStringLiteral("unreachable"))
                drawn += properties.value("area_m2").toDouble();
        }
        const double counted = report.value("unreachable_area_m2").toDouble();
        QVERIFY2(counted > 0.0 && std::abs(drawn - counted) <= 0.02 * counted,
                 qPrintable(
                     QStringLiteral("%1: %2 m2 drawn, %3 m2 counted").arg(planner).arg(drawn).arg(counted)));
    }
}

// Robots of their own cruise speeds: MCPP-MLCT times each at its own and the mission's note says so, once;
// CPPIED times all at the class table's, warns, and leaves the note out of its report.
void TestBatchEndToEnd::aNoteThatDoesNotHoldForAPlanIsNotSaid() {
    auto mission = sampleMissionAnywhere("synthetic", "synthetic.asc");
    auto robots = mission.value("robots").toArray();
    auto first = robots.at(0).toObject();
    first.insert("cruise_speed_mps", 4.0);
    robots.replace(0, first);
    mission.insert("robots", robots);
    const QString path = scratch_.filePath("own-speeds.json");
    QVERIFY(writeText(path, QJsonDocument(mission).toJson()));
    const QString out = scratch_.filePath("own-speeds");
    const auto run = runMcpp({"--batch", path, "--compare", "mcpp-mlct,cppied", "--out", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    const QString note = QStringLiteral("and each is timed at its own");
    QVERIFY2(run.standardOutput.contains(QStringLiteral("mcpp: the robots' cruise speeds differ")) &&
                 run.standardOutput.count(note) == 1,
             qPrintable(run.standardOutput));
    QVERIFY2(
        run.standardError.contains(QStringLiteral("cppied: CPPIED times every robot at the class table's")),
        qPrintable(run.standardError));
    // CPPIED's ratio is to a bound of another kind, which its line names; MCPP-MLCT's line does not.
    const QString kind =
        QStringLiteral("to its own bound (a bound of the passes its targets need, each at the "
                       "fastest class's speed: looser than other plans' bounds)");
    QCOMPARE(run.standardOutput.count(kind), 1);
    for (const QString& line : run.standardOutput.split('\n'))
        if (line.contains(kind))
            QVERIFY2(line.contains(QStringLiteral(". cppied: covered")), qPrintable(line));
    bool noted = false;
    for (const QJsonValue& issue : readJsonObject(out + "/cppied/report.json").value("issues").toArray())
        noted = noted || issue.toObject().value("code").toString() == QStringLiteral("cruise-speeds-differ");
    QVERIFY(!noted);
    // The files name the kind of each bound too: report.json, and comparison.csv and .json by planner.
    QCOMPARE(readJsonObject(out + "/cppied/report.json").value("lower_bound_kind").toString(),
             QStringLiteral("detection_passes"));
    QCOMPARE(readJsonObject(out + "/mcpp-mlct/report.json").value("lower_bound_kind").toString(),
             QStringLiteral("coverage_work"));
    QMap<QString, QString> kindOf;
    for (const QJsonValue& row : readJsonObject(out + "/comparison.json").value("planners").toArray())
        kindOf.insert(row.toObject().value("planner").toString(),
                      row.toObject().value("lower_bound_kind").toString());
    QCOMPARE(kindOf.value("cppied"), QStringLiteral("detection_passes"));
    QCOMPARE(kindOf.value("mcpp-mlct"), QStringLiteral("coverage_work"));
    QFile csv(out + "/comparison.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    const qsizetype column = lines.front().split(',').indexOf(QStringLiteral("lower_bound_kind"));
    QVERIFY2(column > 0, qPrintable(lines.front()));
    for (int row = 1; row < lines.size(); ++row) {
        const QStringList fields = lines.at(row).split(',');
        QCOMPARE(fields.at(column), kindOf.value(fields.front()));
    }
}

// --compare: each planner's own outputs in its folder, one row each in comparison.csv and .json with the
// figures of that planner's report.json, the one-robot planner skipped for a three-robot mission, a sheet.
void TestBatchEndToEnd::comparePlannersOnOneMission() {
    const QString out = scratch_.filePath(QStringLiteral("compare"));
    const auto run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare",
                              "mcpp-mlct,darp,mstc,spiral-stc", "--out", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY2(run.standardError.contains(QStringLiteral("planner 2 of 4: darp")),
             qPrintable(run.standardError));
    // The summary counts the planners that ran and gives each one's covered share first.
    QVERIFY2(
        run.standardOutput.contains(QStringLiteral("mcpp: compared 3 planners on 3 robots, 1 skipped\n")),
        qPrintable(run.standardOutput));
    const QDir folder(out);
    const auto comparison = readJsonObject(folder.filePath("comparison.json"));
    const auto planners = comparison.value("planners").toArray();
    QCOMPARE(planners.size(), 4);
    // The summary lists the planned rows by rank, as comparison.json numbers them: the first is done
    // soonest (all three cover the same land here), each line after it timed against it.
    double firstMakespan = 0.0;
    for (int rank = 1; rank <= 3; ++rank) {
        QJsonObject ranked;
        for (const auto& planner : planners)
            if (planner.toObject().value("rank").toInt() == rank)
                ranked = planner.toObject();
        const QString name = ranked.value("planner").toString();
        QVERIFY2(!name.isEmpty(), qPrintable(QString::number(rank)));
        const QString line = QStringLiteral("mcpp:   %1. %2: covered ").arg(rank).arg(name);
        QVERIFY2(run.standardOutput.contains(line), qPrintable(run.standardOutput));
        const double makespan = ranked.value("makespan_s").toDouble();
        QVERIFY(makespan >= firstMakespan);
        firstMakespan = rank == 1 ? makespan : firstMakespan;
        if (rank > 1)
            QVERIFY2(run.standardOutput.indexOf(line) >
                         run.standardOutput.indexOf(QStringLiteral("mcpp:   %1. ").arg(rank - 1)),
                     qPrintable(run.standardOutput));
    }
    QVERIFY2(run.standardOutput.contains(QStringLiteral("mcpp:   spiral-stc: skipped (")),
             qPrintable(run.standardOutput));
    QFile csv(folder.filePath("comparison.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 5);
    const QStringList header = lines.front().split(',');
    // Every column a plain name a script can use unquoted, stages included ("straight_borders_ms").
    static const QRegularExpression plainName(QStringLiteral("^[a-z0-9_]+$"));
    for (const QString& column : header)
        QVERIFY2(plainName.match(column).hasMatch(), qPrintable(column));
    QVERIFY2(header.contains(QStringLiteral("paths_ms")), qPrintable(lines.front()));
    for (int i = 0; i < planners.size(); ++i) {
        const auto row = planners.at(i).toObject();
        const QString name = row.value("planner").toString();
        const QStringList fields = lines.at(i + 1).split(',');
        QCOMPARE(fields.at(header.indexOf("planner")), name);
        if (name == "spiral-stc") {
            QCOMPARE(row.value("outcome").toString(), QStringLiteral("skipped"));
            QVERIFY(!QFileInfo::exists(folder.filePath(name)));
            continue;
        }
        QCOMPARE(row.value("outcome").toString(), QStringLiteral("planned"));
        QCOMPARE(fields.at(header.indexOf("rank")), QString::number(row.value("rank").toInt()));
        // All three cover the same land: each is timed against the first.
        QVERIFY2(nearlyEqual(fields.at(header.indexOf("time_vs_first")).toDouble(),
                             row.value("time_vs_first").toDouble(), 1e-12),
                 qPrintable(lines.at(i + 1)));
        QVERIFY(row.value("rank").toInt() == 1 ? row.value("time_vs_first").toDouble() == 1.0
                                               : row.value("time_vs_first").toDouble() >= 1.0);
        const auto report = readJsonObject(folder.filePath(name + "/report.json"));
        QCOMPARE(report.value("planner").toString(), name);
        for (const char* key : {"makespan_s", "lower_bound_s", "ratio", "covered_fraction",
                                "repeated_fraction", "unreachable_area_m2"}) {
            QCOMPARE(row.value(key).toDouble(), report.value(key).toDouble());
            QVERIFY2(
                nearlyEqual(fields.at(header.indexOf(key)).toDouble(), report.value(key).toDouble(), 1e-12),
                key);
        }
        const auto robots = row.value("robots").toArray();
        const auto reportRobots = report.value("robots").toArray();
        QCOMPARE(robots.size(), reportRobots.size());
        int turns = 0;
        for (int robot = 0; robot < robots.size(); ++robot) {
            QCOMPARE(robots.at(robot).toObject().value("time_s").toDouble(),
                     reportRobots.at(robot).toObject().value("time_s").toDouble());
            turns += reportRobots.at(robot).toObject().value("turns").toInt();
        }
        QCOMPARE(row.value("turns").toInt(), turns);
        QVERIFY(row.value("planning_ms").toDouble() > 0.0);
        // Each planner's own peak, not the process's so far: a Qt and GDAL process holds tens of megabytes,
        // and none of these small plans takes gigabytes (under the sanitizers either).
        const double peak = row.value("peak_memory_mb").toDouble();
        QVERIFY2(peak > 10.0 && peak < 4000.0, qPrintable(QString::number(peak)));
        QVERIFY(QFileInfo(folder.filePath(name + "/plan.geojson")).size() > 0);
    }
    const QImage sheet(folder.filePath("comparison.png"));
    QVERIFY(!sheet.isNull());
    QVERIFY(sheet.width() >= 1000 && sheet.height() >= 1000);
    // Coloured bars of the chart: robot colours appear below the maps.
    bool sawRobotColour = false;
    for (int y = sheet.height() - 300; y < sheet.height() && !sawRobotColour; y += 4)
        for (int x = 0; x < sheet.width() && !sawRobotColour; x += 4)
            sawRobotColour = sheet.pixelColor(x, y) == QColor(0xe6194b);
    QVERIFY(sawRobotColour);

    // A planner that cannot plan the mission keeps its row with the reason; the others still run (exit 3).
    // Here DARP refuses a tolerance outside its range, which MCPP-MLCT does not have.
    const QString partly = scratch_.filePath(QStringLiteral("compare-partly"));
    const auto someFailed =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "mcpp-mlct,darp", "--param",
                 "convergence_tolerance=0.9", "--out", partly});
    QCOMPARE(someFailed.exitCode, 3);
    const auto partlyRows =
        readJsonObject(QDir(partly).filePath("comparison.json")).value("planners").toArray();
    QCOMPARE(partlyRows.size(), 2);
    QCOMPARE(partlyRows.at(0).toObject().value("outcome").toString(), QStringLiteral("planned"));
    QCOMPARE(partlyRows.at(1).toObject().value("outcome").toString(), QStringLiteral("failed"));
    QVERIFY(partlyRows.at(1).toObject().value("message").toString().contains(
        QStringLiteral("convergence_tolerance")));
    QVERIFY(QFileInfo(QDir(partly).filePath("mcpp-mlct/report.json")).exists());
    QVERIFY(QFileInfo(QDir(partly).filePath("comparison.png")).exists());
    // When no planner can plan, the mission is at fault: exit 2, as for one planner.
    const auto noneCould =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "darp", "--param",
                 "convergence_tolerance=0.9", "--out", scratch_.filePath("compare-none")});
    QCOMPARE(noneCould.exitCode, 2);
    // A start off the map is the mission's fault whatever the planner: said once, where the user can find
    // it (how far off and which way, and in degrees), before any planner runs.
    const auto offTheMap =
        runMcpp(syntheticFlags() + QStringList{"--start", "431040,5301040", "--start", "431100,5299000",
                                               "--compare", "mcpp-mlct,darp", "--out", out + "-off"});
    QCOMPARE(offTheMap.exitCode, 2);
    QCOMPARE(offTheMap.standardError.count(QStringLiteral("outside the raster")), 1);
    QVERIFY2(offTheMap.standardError.contains(QStringLiteral("--start 2: (431100, 5299000; longitude ")),
             qPrintable(offTheMap.standardError));
    QVERIFY2(offTheMap.standardError.contains(QStringLiteral("m south of it")),
             qPrintable(offTheMap.standardError));
    QVERIFY(!offTheMap.standardError.contains(QStringLiteral("planner 1 of 2")));
    QVERIFY(!QFileInfo::exists(out + "-off"));

    // Unknown names and --planner beside --compare are refused before any work.
    auto refused =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "darp,nosuch", "--out", out});
    QCOMPARE(refused.exitCode, 2);
    QVERIFY(refused.standardError.contains(QStringLiteral("nosuch")));
    refused = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "darp", "--planner",
                       "mstc", "--out", out});
    QCOMPARE(refused.exitCode, 2);
}

// Robots crawling over the whole raster for weeks: the summary says how to plan part of it instead.
void TestBatchEndToEnd::weeksOfWorkSuggestAnArea() {
    const QString slow = scratch_.filePath(QStringLiteral("slow.csv"));
    QVERIFY(writeText(slow,
                      "value,name,speed_mps,fov_m,passable,color\n1,Dense forest,0.0008,5,true,#2e7d32\n"
                      "2,Shrubland,0.0015,10,true,#a5a05a\n3,Grassland,0.003,20,true,#d4e157\n"
                      "4,Lake,0,10,false,#4f8fd6\n"));
    const QStringList robot{"--start", "431040,5301040"};
    auto run =
        runMcpp(QStringList{"--batch", "--raster", samplePath("synthetic/synthetic.asc"), "--classes", slow} +
                robot + QStringList{"--out", scratch_.filePath("slow")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY2(run.standardOutput.contains(
                 QStringLiteral("for all the raster's land: to plan part of it, give the area's "
                                "polygons (--area FILE")),
             qPrintable(run.standardOutput));
    // Rovers at the class table's speeds: a drone user is told how to plan at a drone's pace.
    QVERIFY2(run.standardOutput.contains(QStringLiteral(
                 "if the robots fly, give --vehicle multirotor (or fixed-wing) and --cruise-speed M/S (the "
                 "class table's speeds, 0.0008 to 0.003 m/s, are a ground robot's)")),
             qPrintable(run.standardOutput));
    // Aircraft at their own speed, still weeks over the whole raster: only the area is advised.
    run = runMcpp(
        QStringList{"--batch", "--raster", samplePath("synthetic/synthetic.asc"), "--classes", slow} + robot +
        QStringList{"--vehicle", "multirotor", "--cruise-speed", "0.001", "--out",
                    scratch_.filePath("slow-drone")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY2(run.standardOutput.contains(QStringLiteral("for all the raster's land")),
             qPrintable(run.standardOutput));
    QVERIFY2(!run.standardOutput.contains(QStringLiteral("if the robots fly")),
             qPrintable(run.standardOutput));
    // At the sample's own speeds the plan takes hours: nothing to suggest.
    run = runMcpp(syntheticFlags() + robot + QStringList{"--out", scratch_.filePath("quick")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY(!run.standardOutput.contains(QStringLiteral("for all the raster's land")));
}

void TestBatchEndToEnd::samplesAreValidMissions_data() {
    QTest::addColumn<QString>("folder");
    QTest::newRow("zion-nlcd") << "zion-nlcd";
    QTest::newRow("spain-corine") << "spain-corine";
    QTest::newRow("synthetic") << "synthetic";
}

// Every sample must load, carry the same table as its CSV, have 3-6 robots and start them on passable land.
void TestBatchEndToEnd::samplesAreValidMissions() {
    QFETCH(QString, folder);
    const auto missionPath = samplePath(folder + "/mission.json").toStdString();
    auto mission = mcpp::io::loadMission(missionPath);
    QVERIFY2(mission.ok(), mission.ok() ? "" : mission.error().c_str());
    QVERIFY(mission.value().robots.size() >= 3 && mission.value().robots.size() <= 6);
    QVERIFY(QFileInfo::exists(samplePath(folder + "/SOURCE.md")));

    auto csv = mcpp::io::loadClassTableCsv(samplePath(folder + "/classes.csv").toStdString());
    QVERIFY2(csv.ok(), csv.ok() ? "" : csv.error().c_str());
    QVERIFY(csv.value() == mission.value().classes);

    auto raster = mcpp::io::loadLandCoverRaster(mcpp::io::resolveRasterPath(mission.value(), missionPath));
    QVERIFY2(raster.ok(), raster.ok() ? "" : raster.error().c_str());
    const auto reconciled =
        mcpp::io::reconcileRasterWithTable(raster.value(), mission.value().classes, false);
    QVERIFY2(reconciled.ok(), reconciled.error().c_str());
    const auto& grid = raster.value().grid;
    for (const auto& robot : mission.value().robots) {
        QVERIFY(robot.startCrs.empty());
        const int column = static_cast<int>(std::floor((robot.start.x - grid.originX) / grid.pixelWidth));
        const int row = static_cast<int>(std::floor((grid.originY - robot.start.y) / grid.pixelHeight));
        QVERIFY2(column >= 0 && row >= 0 && column < grid.columns && row < grid.rows, robot.name.c_str());
        QVERIFY2(!grid.isOutside(column, row), robot.name.c_str());
        const auto* landCover = mission.value().classes.find(grid.valueAt(column, row));
        QVERIFY2(landCover != nullptr && landCover->isTraversable(), robot.name.c_str());
    }
}

// The synthetic map exists to exercise the hierarchy: 5, 10 and 20 m fields of view give three levels, and
// each level must hold active cells.
void TestBatchEndToEnd::syntheticSampleNeedsThreeLevels() {
    const auto missionPath = samplePath("synthetic/mission.json").toStdString();
    auto mission = mcpp::io::loadMission(missionPath);
    QVERIFY(mission.ok());
    auto raster = mcpp::io::loadLandCoverRaster(mcpp::io::resolveRasterPath(mission.value(), missionPath));
    QVERIFY(raster.ok());
    mcpp::PlanningProblem problem;
    problem.grid = raster.value().grid;
    problem.classes = mission.value().classes;
    problem.planner = mission.value().planner;
    for (const auto& robot : mission.value().robots)
        problem.starts.push_back(robot.start);
    const auto planner = mcpp::makePlanner(problem.planner.planner);
    QVERIFY(planner != nullptr);
    const auto plan = planner->plan(problem, mcpp::ProgressReporter());
    QCOMPARE(plan.cells.frame().levels, 3);
    QCOMPARE(plan.cells.frame().bottomCellSize, 10.0);
    QSet<int> levelsWithActiveCells;
    for (const auto& cell : plan.cells.cells()) {
        levelsWithActiveCells.insert(cell.level);
    }
    QCOMPARE(levelsWithActiveCells, (QSet<int>{1, 2, 3}));
}

void TestBatchEndToEnd::checkOutputs(const QString& directory, int robots, const RunResult& run,
                                     const QString& planner) const {
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    const QString planned = robots == 1 ? QStringLiteral("mcpp: planned 1 robot ")
                                        : QStringLiteral("mcpp: planned %1 robots").arg(robots);
    QVERIFY2(run.standardOutput.contains(planned), qPrintable(run.standardOutput));
    const QDir out(directory);
    QStringList expected{"plan.geojson", "report.json", "plan.png", "regions.tif", "plan.gpkg"};
    // Only a planner that models detection writes the detection raster.
    const bool detection = mcpp::makePlanner(planner.toStdString())->name() == "cppied";
    if (detection)
        expected << "detection.tif";
    QCOMPARE(QFileInfo::exists(out.filePath("detection.tif")), detection);
    const auto reportRobots = readJsonObject(out.filePath("report.json")).value("robots").toArray();
    QCOMPARE(reportRobots.size(), robots);
    for (int robot = 0; robot < robots; ++robot) {
        expected << QStringLiteral("robot_%1.csv").arg(robot + 1);
        // An autopilot mission above its item limit comes in parts instead of one file.
        const int parts = reportRobots[robot].toObject().value("mission_parts").toInt();
        QVERIFY(parts >= 1);
        for (const char* extension : {".plan", ".waypoints"}) {
            const QString whole = QStringLiteral("robot_%1%2").arg(robot + 1).arg(QLatin1String(extension));
            if (parts == 1) {
                expected << whole;
                continue;
            }
            QVERIFY2(!QFileInfo::exists(out.filePath(whole)), qPrintable(whole));
            for (int part = 1; part <= parts; ++part)
                expected << partStem(robot, part, parts) + QLatin1String(extension);
        }
    }
    for (const auto& name : expected) {
        QVERIFY2(QFileInfo(out.filePath(name)).size() > 0, qPrintable(name));
    }
    QVERIFY(!QFileInfo::exists(out.filePath(QStringLiteral("robot_%1.csv").arg(robots + 1))));

    // plan.geojson: a WGS84 FeatureCollection with one region, path and start per robot.
    const auto geoJson = readJsonObject(out.filePath("plan.geojson"));
    QCOMPARE(geoJson.value("type").toString(), QStringLiteral("FeatureCollection"));
    const auto features = geoJson.value("features").toArray();
    QVERIFY(!features.isEmpty());
    QMap<QString, QSet<int>> robotsByKind;
    for (const auto& value : features) {
        const auto feature = value.toObject();
        QCOMPARE(feature.value("type").toString(), QStringLiteral("Feature"));
        const auto properties = feature.value("properties").toObject();
        const auto kind = properties.value("kind").toString();
        const auto geometryType = feature.value("geometry").toObject().value("type").toString();
        if (kind == "region") {
            QVERIFY(geometryType == "MultiPolygon" || geometryType == "Polygon");
            QVERIFY(properties.value("area_m2").toDouble() > 0.0);
            QVERIFY(properties.value("cells").toInt() > 0);
            QVERIFY(properties.value("cost_s").toDouble() > 0.0);
            QVERIFY(properties.value("time_s").toDouble() > 0.0);
        } else if (kind == "path") {
            QCOMPARE(geometryType, QStringLiteral("LineString"));
            QVERIFY(properties.value("length_m").toDouble() > 0.0);
            QVERIFY(properties.value("time_s").toDouble() > 0.0);
            QVERIFY(properties.value("turns").toInt() >= 0);
            const auto coordinates = feature.value("geometry").toObject().value("coordinates").toArray();
            QVERIFY(coordinates.size() >= 2);
            const auto first = coordinates.first().toArray();
            QVERIFY(std::abs(first.at(0).toDouble()) <= 180.0 && std::abs(first.at(1).toDouble()) <= 90.0);
        } else if (kind == "start") {
            QCOMPARE(geometryType, QStringLiteral("Point"));
        } else if (kind == "charger") { // of a robot flying sorties from a charger away from its start
            QCOMPARE(geometryType, QStringLiteral("Point"));
            const int robot = properties.value("robot").toInt(-1);
            QVERIFY(robot >= 1 && robot <= robots);
            continue;
        } else if (kind == "taken_over") { // plans simulated with events: what each robot took over
            QVERIFY(geometryType == QStringLiteral("Polygon") ||
                    geometryType == QStringLiteral("MultiPolygon"));
            QVERIFY(properties.value("area_m2").toDouble() > 0.0);
            QVERIFY(properties.value("cells").toInt() > 0);
            const int robot = properties.value("robot").toInt(-1);
            QVERIFY(robot >= 1 && robot <= robots);
            continue;
        } else {
            QCOMPARE(kind, QStringLiteral("unreachable"));
            continue;
        }
        robotsByKind[kind].insert(properties.value("robot").toInt(-1));
    }
    // Robots are numbered from 1 in every file, as on the map.
    QSet<int> everyRobot;
    for (int robot = 1; robot <= robots; ++robot)
        everyRobot.insert(robot);
    for (const char* kind : {"region", "path", "start"})
        QCOMPARE(robotsByKind.value(kind), everyRobot);

    // report.json: per robot figures and the fleet's, with ratio = makespan / lower bound.
    const auto report = readJsonObject(out.filePath("report.json"));
    const auto robotReports = report.value("robots").toArray();
    QCOMPARE(robotReports.size(), robots);
    double longest = 0.0;
    for (int robot = 0; robot < robots; ++robot) {
        const auto item = robotReports.at(robot).toObject();
        QCOMPARE(item.value("robot").toInt(-1), robot + 1);
        QVERIFY(!item.value("name").toString().isEmpty());
        QVERIFY(item.value("cells").toInt() > 0);
        QVERIFY(item.value("length_m").toDouble() > 0.0);
        longest = std::max(longest, item.value("time_s").toDouble());
    }
    const double makespan = report.value("makespan_s").toDouble();
    const double lowerBound = report.value("lower_bound_s").toDouble();
    QVERIFY(lowerBound > 0.0);
    QVERIFY(nearlyEqual(makespan, longest));
    QVERIFY2(nearlyEqual(report.value("ratio").toDouble(), makespan / lowerBound),
             qPrintable(QStringLiteral("ratio %1, makespan %2, lower bound %3")
                            .arg(report.value("ratio").toDouble())
                            .arg(makespan)
                            .arg(lowerBound)));
    const double covered = report.value("covered_fraction").toDouble();
    QVERIFY(covered > 0.5 && covered <= 1.0 + 1e-9);
    QCOMPARE(report.value("planner").toString(), planner);
    // The class table the plan used, as a mission file holds it.
    const auto classes = report.value("classes").toArray();
    QVERIFY(!classes.isEmpty());
    QSet<int> values;
    for (const QJsonValue& entry : classes) {
        const QJsonObject row = entry.toObject();
        values.insert(row.value("value").toInt(-1));
        QVERIFY(row.value("color").toString().startsWith(QLatin1Char('#')));
        QVERIFY(row.value("speed_mps").toDouble(-1.0) >= 0.0);
        QVERIFY(row.value("fov_m").toDouble() > 0.0);
        QVERIFY(row.value("passable").isBool());
    }
    QCOMPARE(values.size(), classes.size());     // one row a class
    for (int robot = 0; robot < robots; ++robot) // the whole mission as one flight is at least its path
        QVERIFY(robotReports.at(robot).toObject().value("mission_one_flight_s").toDouble() >=
                robotReports.at(robot).toObject().value("mission_time_s").toDouble() - 1e-6);
    // What the run took, written last so it includes the other files.
    const auto process = report.value("process_ms").toObject();
    for (const char* step : {"read_raster", "plan", "write_outputs"})
        QVERIFY2(process.value(step).toDouble(-1.0) >= 0.0, step);

    // Waypoint files have the structure their readers expect.
    for (int robot = 0; robot < robots; ++robot) {
        const int parts = reportRobots[robot].toObject().value("mission_parts").toInt();
        const QString stem =
            parts > 1 ? partStem(robot, 1, parts) : QStringLiteral("robot_%1").arg(robot + 1);
        const auto plan = readJsonObject(out.filePath(stem + ".plan"));
        QCOMPARE(plan.value("fileType").toString(), QStringLiteral("Plan"));
        QFile waypoints(out.filePath(stem + ".waypoints"));
        QVERIFY(waypoints.open(QIODevice::ReadOnly));
        QCOMPARE(waypoints.readLine().trimmed(), QByteArray("QGC WPL 110"));
        QFile csv(out.filePath(QStringLiteral("robot_%1.csv").arg(robot + 1)));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QVERIFY(csv.readAll().count('\n') >= 3); // header and at least two waypoints
    }
    const QImage image(out.filePath("plan.png"));
    QVERIFY(!image.isNull());
    QVERIFY(image.width() > 100 && image.height() > 100);
}

void TestBatchEndToEnd::missionFileWritesEveryOutput() {
    const QString out = scratch_.filePath("mission-run/nested/out"); // folders are created as needed
    const auto run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--out", out});
    checkOutputs(out, 3, run);
    if (QTest::currentTestFailed())
        return;
    // Progress goes to stderr as short "mcpp: <stage> <percent>%" lines.
    const auto lines = run.standardError.split('\n', Qt::SkipEmptyParts);
    QVERIFY(!lines.isEmpty());
    QVERIFY(lines.size() < 200);
    for (const auto& line : lines)
        QVERIFY2(line.startsWith(QStringLiteral("mcpp: ")), qPrintable(line));
    QVERIFY(run.standardError.contains(QStringLiteral("writing outputs 100%")));
}

void TestBatchEndToEnd::flagMissionWithLongitudeLatitudeStarts() {
    // The synthetic mission's three starts, converted to WGS84 longitude, latitude with gdaltransform.
    const QString out = scratch_.filePath("flag-run");
    auto arguments = syntheticFlags();
    arguments << "--start"
              << "14.0780530,47.8589976"
              << "--start"
              << "14.0805547,47.8611771"
              << "--start"
              << "14.0831295,47.8592182"
              << "--start-crs"
              << "EPSG:4326"
              << "--open-paths"
              << "--planner"
              << "mcpp-mlct"
              << "--band"
              << "1"
              << "--out" << out;
    auto run = runMcpp(arguments);
    checkOutputs(out, 3, run);
    if (QTest::currentTestFailed())
        return;
    QVERIFY(!run.standardError.isEmpty());

    // --quiet silences progress and the summary.
    arguments << "--quiet";
    run = runMcpp(arguments);
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.standardError.isEmpty(), qPrintable(run.standardError));
    QVERIFY2(run.standardOutput.isEmpty(), qPrintable(run.standardOutput));
}

// An area drawn partly off the raster: what it leaves to plan is news on standard output, the part off the
// raster a warning on standard error and in report.json, where a script reading the outputs finds it.
void TestBatchEndToEnd::anAreaPastTheRastersEdgeIsAWarningInTheReport() {
    const QString area = scratch_.filePath("past-the-edge.geojson");
    QFile file(area);
    QVERIFY(file.open(QIODevice::WriteOnly));
    // 200 x 200 m, its eastern 100 m past the raster's edge at x 431480.
    file.write("{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\"properties\":{\"name\":"
               "\"urn:ogc:def:crs:EPSG::32633\"}},\"features\":[{\"type\":\"Feature\",\"properties\":{},"
               "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[431380,5301050],[431580,5301050],"
               "[431580,5301250],[431380,5301250],[431380,5301050]]]}}]}");
    file.close();
    const QString out = scratch_.filePath("past-the-edge");
    auto run = runMcpp(syntheticFlags() << "--area" << area << "--start"
                                        << "431420,5301100"
                                        << "--out" << out);
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY2(run.standardOutput.contains("mcpp: area of interest: planning on "),
             qPrintable(run.standardOutput));
    const QString warning =
        QStringLiteral("area of interest: of the 4 ha in past-the-edge.geojson, 2 ha lies off the raster");
    QVERIFY2(run.standardError.contains("mcpp: warning: " + warning), qPrintable(run.standardError));
    const auto report = readJsonObject(out + "/report.json");
    const auto said = [&](const QJsonArray& list, const std::function<QString(const QJsonValue&)>& text) {
        return std::any_of(list.begin(), list.end(),
                           [&](const QJsonValue& item) { return text(item).contains(warning); });
    };
    QVERIFY(said(report.value("warnings").toArray(), [](const QJsonValue& item) { return item.toString(); }));
    QVERIFY(said(report.value("issues").toArray(), [](const QJsonValue& item) {
        const QJsonObject issue = item.toObject();
        return issue.value("code").toString() == "input" && issue.value("severity").toString() == "warning"
                   ? issue.value("message").toString()
                   : QString();
    }));
}

void TestBatchEndToEnd::rerunWithFewerRobotsRemovesTheirFiles() {
    const QString out = scratch_.filePath("rerun");
    auto run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--out", out, "--quiet"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(QFileInfo::exists(out + "/robot_3.plan"));
    // Ten robots: numbered robot_01 to robot_10, so that a file list sorts them; the three unpadded go.
    QStringList tenRobots = syntheticFlags();
    for (const char* x : {"431040", "431140", "431240", "431340", "431420"})
        for (const char* y : {"5301040", "5301260"})
            tenRobots << "--start" << QStringLiteral("%1,%2").arg(QLatin1String(x), QLatin1String(y));
    run = runMcpp(tenRobots << "--out" << out << "--quiet");
    QCOMPARE(run.exitCode, 0);
    const auto robotFiles = [&] {
        QStringList names = QDir(out).entryList({QStringLiteral("robot_*")}, QDir::Files);
        names.sort();
        return names;
    };
    QCOMPARE(robotFiles().size(), 3 * 10);
    QCOMPARE(robotFiles().first(), QStringLiteral("robot_01.csv"));
    QCOMPARE(robotFiles().last(), QStringLiteral("robot_10.waypoints"));
    auto arguments = syntheticFlags();
    arguments << "--start"
              << "431040,5301040"
              << "--start"
              << "431420,5301060"
              << "--out" << out;
    run = runMcpp(arguments);
    checkOutputs(out, 2, run);
    QCOMPARE(robotFiles().join(QLatin1Char(' ')),
             QStringLiteral("robot_1.csv robot_1.plan robot_1.waypoints robot_2.csv robot_2.plan "
                            "robot_2.waypoints"));
}

void TestBatchEndToEnd::missingAsObstacleTurnsTheErrorIntoAWarning() {
    // Shrubland (2) has no row: an error without the flag (see badInputExitsTwoWithOneLine), a warning with
    // it.
    const QString table = scratch_.filePath("without-shrubland.csv");
    QVERIFY(writeText(
        table,
        "value,name,speed_mps,fov_m,passable\n1,Forest,1,5,true\n3,Grass,3,20,true\n4,Lake,0,10,false\n"));
    const QString out = scratch_.filePath("missing-as-obstacle");
    const auto run = runMcpp({"--batch", "--raster", samplePath("synthetic/synthetic.asc"), "--classes",
                              table, "--start", "431040,5301040", "--start", "431420,5301060",
                              "--missing-as-obstacle", "--purity", "0.05", "--out", out});
    checkOutputs(out, 2, run);
    QVERIFY2(run.standardError.contains(QStringLiteral("mcpp: warning: class 2")),
             qPrintable(run.standardError));
}

// No --classes or --preset: the Canada land cover is recognised (codes and CRS, or its file name), its
// preset applies and says so, and its water is a wall a robot cannot start on; another product's preset
// is named beside the start it refuses.
void TestBatchEndToEnd::rasterAloneGetsTheRecognisedProductsTable() {
    const QString raster =
        QString::fromStdString(mcpp::test::testDataPath("landcover/nrcan_landcover2015_example.tif"));
    const QString out = scratch_.filePath("recognised");
    const auto run = runMcpp({"--batch", "--raster", raster, "--start", "-1484495,729105", "--out", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY(QFileInfo(out + "/plan.geojson").size() > 0);
    QVERIFY2(run.standardOutput.contains("mcpp: Recognised Land Cover of Canada"),
             qPrintable(run.standardOutput));
    QVERIFY(run.standardOutput.contains("applied preset canada-landcover"));

    const auto onWater = runMcpp({"--batch", "--raster", raster, "--start", "-1482755,729735", "--out",
                                  scratch_.filePath("recognised-water")});
    QCOMPARE(onWater.exitCode, 2);
    QVERIFY2(onWater.standardError.contains("Water"), qPrintable(onWater.standardError));

    // Another product's preset reads its forest as urban fabric, an obstacle: the start is refused, and
    // the warning of the wrong preset comes first, as the likely reason.
    const auto wrongPreset =
        runMcpp({"--batch", "--raster", raster, "--preset", "corine-grid", "--start", "-1492970,729450",
                 "--out", scratch_.filePath("recognised-wrong-preset")});
    QCOMPARE(wrongPreset.exitCode, 2);
    const qsizetype choose = wrongPreset.standardError.indexOf("Choose the preset canada-landcover");
    const qsizetype refused = wrongPreset.standardError.indexOf("is on an obstacle: class 1");
    QVERIFY2(choose >= 0 && refused > choose, qPrintable(wrongPreset.standardError));
}

void TestBatchEndToEnd::readmeSampleRuns() {
    // The README's headless command, on the real NLCD sample.
    const QString out = scratch_.filePath("zion");
    const auto run = runMcpp({"--batch", samplePath("zion-nlcd/mission.json"), "--out", out});
    checkOutputs(out, 5, run);
}

// --max-waypoints splits each mission into parts that hold at most that many items and join up end to
// start; a run without the limit in the same folder leaves whole files and no stale part.
void TestBatchEndToEnd::missionsAboveTheItemLimitAreSplit() {
    const QString out = scratch_.filePath("split");
    const int limit = 40;
    // First whole files, then parts in the same folder: the whole files of the first run go.
    auto run =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--max-waypoints", "0", "--out", out});
    QCOMPARE(run.exitCode, 0);
    QVERIFY(QFileInfo::exists(out + "/robot_1.plan"));
    run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--max-waypoints", QString::number(limit),
                   "--out", out});
    checkOutputs(out, 3, run);
    if (QTest::currentTestFailed())
        return;
    const auto robots = readJsonObject(out + "/report.json").value("robots").toArray();
    int splitRobots = 0;
    for (qsizetype robot = 0; robot < robots.size(); ++robot) {
        const QJsonObject figures = robots[robot].toObject();
        QCOMPARE(figures.value("max_waypoints").toInt(), limit);
        const int parts = figures.value("mission_parts").toInt();
        QVERIFY(figures.value("mission_items").toInt() > (parts > 1 ? limit : 0));
        if (parts == 1)
            continue;
        ++splitRobots;
        QVERIFY(!QFileInfo::exists(QStringLiteral("%1/robot_%2.plan").arg(out).arg(robot + 1)));
        QVERIFY(!QFileInfo::exists(QStringLiteral("%1/robot_%2.waypoints").arg(out).arg(robot + 1)));
        QVERIFY2(run.standardOutput.contains(partStem(robot, parts, parts)), qPrintable(run.standardOutput));
        QJsonArray previousEnd;
        for (int part = 1; part <= parts; ++part) {
            const auto plan =
                readJsonObject(QStringLiteral("%1/%2.plan").arg(out, partStem(robot, part, parts)));
            const QJsonArray items = plan.value("mission").toObject().value("items").toArray();
            QVERIFY(items.size() + 1 <= limit);                          // with the home position
            QCOMPARE(items[0].toObject().value("command").toInt(), 178); // the speed the part starts at
            QJsonArray start, end;
            for (const QJsonValue& item : items) {
                if (item.toObject().value("command").toInt() != 16)
                    continue;
                if (start.isEmpty())
                    start = item.toObject().value("params").toArray();
                end = item.toObject().value("params").toArray();
            }
            if (part > 1) {
                QCOMPARE(start[4].toDouble(), previousEnd[4].toDouble());
                QCOMPARE(start[5].toDouble(), previousEnd[5].toDouble());
            }
            previousEnd = end;
        }
    }
    QVERIFY(splitRobots > 0);
    // Without a battery time the limit is the only reason for the parts: nothing more to say.
    QVERIFY2(!run.standardOutput.contains(QStringLiteral("makes that many")), qPrintable(run.standardOutput));

    // A limit far below what the battery time needs is named, with the parts the battery alone would make.
    run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--max-waypoints", "10", "--flight-time",
                   "10min", "--out", scratch_.filePath("split-small-limit")});
    QCOMPARE(run.exitCode, 0);
    const QRegularExpression fewer(
        QStringLiteral("written in (\\d+) parts[^\\n]*its item limit \\(10\\), not its "
                       "battery time, makes that many: (\\d+) parts without it"));
    const QRegularExpressionMatch said = fewer.match(run.standardOutput);
    QVERIFY2(said.hasMatch(), qPrintable(run.standardOutput));
    QVERIFY(said.captured(1).toInt() >= 2 * said.captured(2).toInt());

    run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--max-waypoints", "0", "--out", out});
    checkOutputs(out, 3, run);
    const QStringList parts = QDir(out).entryList({QStringLiteral("*_part_*")});
    QVERIFY2(parts.isEmpty(), qPrintable(parts.join(", ")));
}

// --fov: a camera's footprint is the same over every land cover, so every class gets it and the cells follow
// (the sample's table has fields of view of 5 to 20 m: one of 40 m makes fewer cells).
void TestBatchEndToEnd::fovFlagGivesEveryClassOneFootprint() {
    const QString ground = scratch_.filePath("fov-ground");
    const QString footprint = scratch_.filePath("fov-footprint");
    auto run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--out", ground});
    QCOMPARE(run.exitCode, 0);
    run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--fov", "40", "--out", footprint});
    checkOutputs(footprint, 3, run);
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(run.standardOutput.contains(QStringLiteral("every class's field of view set to 40 m (--fov)")),
             qPrintable(run.standardOutput));
    const QJsonObject report = readJsonObject(footprint + "/report.json");
    const QJsonArray classes = report.value("classes").toArray();
    QVERIFY(!classes.isEmpty());
    for (const QJsonValue& landCover : classes)
        QCOMPARE(landCover.toObject().value("fov_m").toDouble(), 40.0);
    const auto cellsOf = [](const QJsonObject& plan) {
        int cells = 0;
        for (const QJsonValue& robot : plan.value("robots").toArray())
            cells += robot.toObject().value("cells").toInt();
        return cells;
    };
    QVERIFY(cellsOf(report) < cellsOf(readJsonObject(ground + "/report.json")));
}

// A mission whose paths pass over 20 million places is said to be large before any planning, with the FOV
// that brings it down in the flag the user gave; the run is stopped once it is said. One the memory guard
// refuses gets the guard's one line only (test_bad_input_batch), and the sample as it is gets neither.
void TestBatchEndToEnd::aLargeMissionIsSaidBeforePlanning() {
    // 14.4 ha at 8 cm: 23 million places on 6 million smallest cells, which fit in any machine's memory.
    QProcess process;
    process.start(executable_, {"--batch", samplePath("synthetic/mission.json"), "--fov", "0.08", "--out",
                                scratch_.filePath("large")});
    // Both lines are on standard error; waiting on standard output (buffered in a pipe) would see nothing
    // until the run ends, so the wait is on standard error, bounded as a whole.
    process.setReadChannel(QProcess::StandardError);
    const QDeadlineTimer deadline(std::chrono::minutes(3));
    QString said;
    while (!said.contains(QStringLiteral("mcpp: quadtree")) && !deadline.hasExpired() &&
           process.waitForReadyRead(static_cast<int>(deadline.remainingTime())))
        said += QString::fromUtf8(process.readAllStandardError());
    process.kill();
    process.waitForFinished();
    const qsizetype warning =
        said.indexOf(QStringLiteral("mcpp: warning: a large mission: covering 14.4 ha of passable land at "
                                    "fields of view down to 0.08 m"));
    QVERIFY2(warning >= 0, qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("about 23 million places: planning may take minutes")),
             qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("--fov 0.088 brings it to about 19 million places")),
             qPrintable(said));
    QVERIFY2(said.indexOf(QStringLiteral("mcpp: quadtree")) > warning, qPrintable(said));
    const auto sample = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare", "all", "--out",
                                 scratch_.filePath("not-large")});
    QCOMPARE(sample.exitCode, 0);
    QVERIFY2(!sample.standardError.contains(QStringLiteral("large mission")),
             qPrintable(sample.standardError));
}

// A robot that starts in a part of the map walls cut off covers only that part: said on standard output, as
// the plan's figures (its short time, the lower bound counted per part) depend on it, not only in
// report.json.
void TestBatchEndToEnd::aRobotWalledInIsSaid() {
    const QDir folder(scratch_.filePath(QStringLiteral("walled")));
    QVERIFY(folder.mkpath(QStringLiteral(".")));
    // 30 x 8 pixels of 10 m, grass with a wall of water from top to bottom in columns 4 and 5.
    QString grid = QStringLiteral("ncols 30\nnrows 8\nxllcorner 0\nyllcorner 0\ncellsize 10\n");
    for (int row = 0; row < 8; ++row) {
        for (int column = 0; column < 30; ++column)
            grid += column == 4 || column == 5 ? QStringLiteral("2 ") : QStringLiteral("1 ");
        grid += '\n';
    }
    QFile raster(folder.filePath(QStringLiteral("walled.asc")));
    QVERIFY(raster.open(QIODevice::WriteOnly));
    raster.write(grid.toUtf8());
    raster.close();
    QFile classes(folder.filePath(QStringLiteral("classes.csv")));
    QVERIFY(classes.open(QIODevice::WriteOnly));
    classes.write("value,name,speed_mps,fov_m,passable\n1,Grass,1,5,true\n2,Water,0,5,false\n");
    classes.close();
    const auto run = runMcpp({"--batch", "--raster", raster.fileName(), "--classes", classes.fileName(),
                              "--start", "15,45", "--start", "150,45", "--start", "285,5", "--out",
                              folder.filePath(QStringLiteral("out"))});
    QCOMPARE(run.exitCode, 0);
    // Its 3 200 m2 are under half of an even share (22 400 m2 over three robots): a warning, saying what to
    // do.
    QVERIFY2(
        run.standardError.contains(QStringLiteral(
            "mcpp: warning: robot 1 starts in a part of the map cut off from the rest (3200 m2, 42.9% of "
            "an even share of the land) and can cover only that part; the lower bound counts each part "
            "with its own robots; it stands idle most of the mission: start it in the largest part to "
            "share the work")),
        qPrintable(run.standardOutput + run.standardError));
    // The wall moved east: robot 1 alone in the larger part sets the bound, so the others' balance is
    // given apart, in report.json and, where it differs from the ratio, in the summary.
    grid = QStringLiteral("ncols 30\nnrows 8\nxllcorner 0\nyllcorner 0\ncellsize 10\n");
    for (int row = 0; row < 8; ++row) {
        for (int column = 0; column < 30; ++column)
            grid += column == 22 || column == 23 ? QStringLiteral("2 ") : QStringLiteral("1 ");
        grid += '\n';
    }
    QVERIFY(raster.open(QIODevice::WriteOnly | QIODevice::Truncate));
    raster.write(grid.toUtf8());
    raster.close();
    const QString lone = folder.filePath(QStringLiteral("lone"));
    const auto loneRun =
        runMcpp({"--batch", "--raster", raster.fileName(), "--classes", classes.fileName(), "--start",
                 "15,45", "--start", "245,45", "--start", "285,5", "--out", lone});
    QCOMPARE(loneRun.exitCode, 0);
    // Robots 2 and 3 share the small part, a third of an even share each: warned of, robot 1 not.
    QVERIFY2(loneRun.standardError.contains(QStringLiteral(
                 "mcpp: warning: robot 2 starts in a part of the map cut off from the rest (4800 "
                 "m2, 32.1% of an even share of the land) and can cover only that part with 1 "
                 "other robot(s)")),
             qPrintable(loneRun.standardError));
    QVERIFY2(!loneRun.standardError.contains(QStringLiteral("robot 1 starts in a part")),
             qPrintable(loneRun.standardError));
    const QJsonObject report = readJsonObject(QDir(lone).filePath(QStringLiteral("report.json")));
    QVERIFY2(report.contains(QStringLiteral("shared_parts_ratio")), qPrintable(loneRun.standardOutput));
    const double shared = report.value(QStringLiteral("shared_parts_ratio")).toDouble();
    const double ratio = report.value(QStringLiteral("ratio")).toDouble();
    QVERIFY(shared >= 1.0 - 1e-9 && std::abs(ratio - 1.0) < 0.01);
    QCOMPARE(loneRun.standardOutput.contains(QStringLiteral("set by robots alone in parts of their own; the "
                                                            "robots sharing parts: ")),
             std::abs(shared - ratio) >= 0.0005);
}

// --outputs: only the outputs asked for and report.json, formats the batch leaves out by default (KML)
// included; in a comparison, in every planner's folder.
void TestBatchEndToEnd::outputsWritesOnlyWhatIsAsked() {
    const QString out = scratch_.filePath(QStringLiteral("some-outputs"));
    const auto run =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--outputs", "kml,geojson", "--out", out});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(QDir(out).entryList(QDir::Files, QDir::Name),
             (QStringList{"plan.geojson", "plan.kml", "report.json"}));
    QFile kml(QDir(out).filePath(QStringLiteral("plan.kml")));
    QVERIFY(kml.open(QIODevice::ReadOnly));
    const QByteArray text = kml.readAll();
    QVERIFY2(text.startsWith("<?xml") && text.contains("<coordinates>"), text.left(200).constData());
    const QString compared = scratch_.filePath(QStringLiteral("some-outputs-compared"));
    const auto comparison = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--compare",
                                     "mcpp-mlct,darp", "--outputs", "png", "--out", compared});
    QCOMPARE(comparison.exitCode, 0);
    for (const char* planner : {"mcpp-mlct", "darp"})
        QCOMPARE(QDir(compared + "/" + QString::fromUtf8(planner)).entryList(QDir::Files, QDir::Name),
                 (QStringList{"plan.png", "report.json"}));
    QVERIFY(QFileInfo::exists(compared + "/comparison.csv"));
    // A KML leaving the waypoint files' parts out (drones of a 30 m footprint on 20 min flights over Zion:
    // thousands of parts) says so, and report.json keeps what it said among its issues.
    const QString flights = scratch_.filePath(QStringLiteral("many-flights"));
    const auto many = runMcpp({"--batch", samplePath("zion-nlcd/mission.json"), "--vehicle", "multirotor",
                               "--cruise-speed", "10", "--flight-time", "20min", "--fov", "30", "--outputs",
                               "kml,qgc-plan", "--out", flights});
    QVERIFY2(many.exitCode == 0, qPrintable(many.standardError));
    const QString said = QStringLiteral("plan.kml leaves out the ");
    QVERIFY2(many.standardOutput.contains(said), qPrintable(many.standardOutput));
    // The land beyond every drone's reach is left out, so no flight is longer than the battery.
    QVERIFY2(many.standardError.contains(QStringLiteral("lies too far from every start for one flight")),
             qPrintable(many.standardError));
    QVERIFY2(!many.standardError.contains(QStringLiteral("longer than its 20 min flight time:")),
             qPrintable(many.standardError));
    bool reported = false;
    for (const QJsonValue& issue : readJsonObject(flights + "/report.json").value("issues").toArray())
        reported = reported || (issue.toObject().value("code").toString() == QStringLiteral("output") &&
                                issue.toObject().value("message").toString().startsWith(said));
    QVERIFY(reported);
    // One drone of short flights beside drones reaching the whole map. MCPP-MLCT gives the land beyond its
    // reach to the others: no flight is longer than a battery, and the bound in the field counts the trips.
    // DARP shares by balance alone: the drone is given land beyond its reach, its flights there are longer
    // than its battery, and the bound says it leaves their trips out.
    auto mixed = sampleMissionAnywhere("zion-nlcd", "nlcd.tif");
    auto robots = mixed.value("robots").toArray();
    for (qsizetype robot = 0; robot < robots.size(); ++robot) {
        auto drone = robots.at(robot).toObject();
        drone.insert("vehicle", "multirotor");
        drone.insert("cruise_speed_mps", 10);
        drone.insert("flight_time_s", robot == 0 ? 300 : 3600);
        robots.replace(robot, drone);
    }
    mixed.insert("robots", robots);
    auto classes = mixed.value("classes").toObject();
    classes.insert("fov_m", 60); // a camera's footprint
    mixed.insert("classes", classes);
    const QString mixedPath = scratch_.filePath(QStringLiteral("mixed-flights.json"));
    QVERIFY(writeText(mixedPath, QJsonDocument(mixed).toJson()));
    const QString tripsLeftOut =
        QStringLiteral(" in the field (the work and the turnarounds alone: with flights longer than a "
                       "battery, the trips out to the work and back are left out of this bound)");
    const QString tooLong = QStringLiteral(" with the flights to and from its start, longer than its ");
    const auto kept = runMcpp({"--batch", mixedPath, "--outputs", "qgc-plan", "--out",
                               scratch_.filePath(QStringLiteral("mixed-flights"))});
    QVERIFY2(kept.exitCode == 0, qPrintable(kept.standardError));
    QVERIFY2(!kept.standardError.contains(tooLong), qPrintable(kept.standardError));
    QVERIFY2(
        kept.standardOutput.contains(QStringLiteral("no plan making these turns brings the last robot home")),
        qPrintable(kept.standardOutput));
    QVERIFY2(!kept.standardOutput.contains(tripsLeftOut), qPrintable(kept.standardOutput));
    const auto shared = runMcpp({"--batch", mixedPath, "--planner", "darp", "--outputs", "qgc-plan", "--out",
                                 scratch_.filePath(QStringLiteral("mixed-flights-darp"))});
    QVERIFY2(shared.exitCode == 0, qPrintable(shared.standardError));
    QVERIFY2(shared.standardError.contains(tooLong), qPrintable(shared.standardError));
    QVERIFY2(shared.standardOutput.contains(tripsLeftOut), qPrintable(shared.standardOutput));
    // Compared, DARP's plan reads as no drone can fly it: after MCPP-MLCT's, whatever its time, and said why.
    const QString comparedPath = scratch_.filePath(QStringLiteral("mixed-flights-compared"));
    const auto comparedRun = runMcpp({"--batch", mixedPath, "--compare", "darp,mcpp-mlct", "--outputs",
                                      "qgc-plan", "--out", comparedPath});
    QVERIFY2(comparedRun.exitCode == 0, qPrintable(comparedRun.standardError));
    QVERIFY2(comparedRun.standardOutput.contains(QStringLiteral("mcpp:   1. mcpp-mlct: ")),
             qPrintable(comparedRun.standardOutput));
    const QStringList darpLine =
        comparedRun.standardOutput.split('\n').filter(QStringLiteral("mcpp:   2. darp: "));
    QCOMPARE(darpLine.size(), 1);
    QVERIFY2(darpLine.front().contains(QStringLiteral(" longer than a battery (not set beside plans whose "
                                                      "flights fit)")),
             qPrintable(darpLine.front()));
    const auto rows =
        readJsonObject(QDir(comparedPath).filePath("comparison.json")).value("planners").toArray();
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows.at(0).toObject().value("ranked_apart").toString(), QStringLiteral("flights_over_battery"));
    QCOMPARE(rows.at(0).toObject().value("rank").toInt(), 2);
    QVERIFY(rows.at(0).toObject().value("flights_over_battery").toInt() > 0);
    QCOMPARE(rows.at(1).toObject().value("flights_over_battery").toInt(-1), 0);
    QCOMPARE(rows.at(1).toObject().value("rank").toInt(), 1);
}

// --vehicle, --altitude, --cruise-speed, --fov-scale, --flight-time and --turnaround: the plan's times are at
// the cruise speed, cells are sized by the scaled fields of view, and the waypoint files are flights that
// take off and return to launch within the flight time, with the turnarounds between them in the field time.
void TestBatchEndToEnd::droneFlagsPlanAtTheCruiseSpeed() {
    const QString ground = scratch_.filePath("ground");
    const QString drone = scratch_.filePath("drone");
    auto run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--out", ground});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(!run.standardOutput.contains(QStringLiteral("every robot flies")),
             qPrintable(run.standardOutput));
    run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--vehicle", "multirotor", "--altitude",
                   "45", "--cruise-speed", "6", "--fov-scale", "2", "--flight-time", "3min", "--turnaround",
                   "2min", "--out", drone});
    checkOutputs(drone, 3, run);
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(run.standardOutput.contains(QStringLiteral("every robot cruises at 6 m/s")),
             qPrintable(run.standardOutput));
    QVERIFY2(run.standardOutput.contains(QStringLiteral("field of view times 2")),
             qPrintable(run.standardOutput));
    QVERIFY2(run.standardOutput.contains(QStringLiteral("with 2 min between parts, done after")),
             qPrintable(run.standardOutput));
    // The lake the class table makes an obstacle is named for drones, with its share of the map: a ground
    // robot's table, which they may mean to fly over.
    const QRegularExpression lake(
        QStringLiteral("every robot flies, yet the class table makes Lake \\([0-9.]+ (ha|m2|km2), "
                       "[0-9.]+% of the map\\) an obstacle: the aircraft neither cover nor cross it"));
    QVERIFY2(lake.match(run.standardOutput).hasMatch(), qPrintable(run.standardOutput));
    const QJsonObject report = readJsonObject(drone + "/report.json");
    bool obstacleNoted = false;
    for (const QJsonValue& issue : report.value("issues").toArray())
        obstacleNoted = obstacleNoted || issue.toObject().value("code").toString() ==
                                             QStringLiteral("impassable-under-aircraft");
    QVERIFY(obstacleNoted);
    int cells = 0;
    double lastDone = 0.0;
    for (const QJsonValue& value : report.value("robots").toArray()) {
        const QJsonObject robot = value.toObject();
        QCOMPARE(robot.value("vehicle").toString(), QStringLiteral("multirotor"));
        cells += robot.value("cells").toInt();
        // Each robot's files are flights of at most 3 minutes, trips from the start and back included.
        QCOMPARE(robot.value("flight_time_s").toDouble(), 180.0);
        const QJsonArray flights = robot.value("mission_part_seconds").toArray();
        QVERIFY2(flights.size() > 1, qPrintable(QString::number(flights.size())));
        QCOMPARE(robot.value("mission_parts").toInt(), flights.size());
        double flown = 0.0;
        for (const QJsonValue& flight : flights) {
            QVERIFY2(flight.toDouble() > 0.0 && flight.toDouble() <= 180.0,
                     qPrintable(QString::number(flight.toDouble())));
            flown += flight.toDouble();
        }
        // Done in the field after the flights and two minutes on the ground between each two.
        QCOMPARE(robot.value("turnaround_s").toDouble(), 120.0);
        const double field = flown + 120.0 * static_cast<double>(flights.size() - 1);
        QVERIFY2(std::abs(robot.value("mission_field_s").toDouble() - field) <= 1e-9 * field,
                 qPrintable(QStringLiteral("%1 s, %2 s expected")
                                .arg(robot.value("mission_field_s").toDouble())
                                .arg(field)));
        lastDone = std::max(lastDone, field);
        // Time is length at 6 m/s and the time lost at turns (connector time is part of the length's).
        const double flying = robot.value("time_s").toDouble() - robot.value("turn_time_s").toDouble();
        const double expected = robot.value("length_m").toDouble() / 6.0;
        QVERIFY2(std::abs(flying - expected) <= 1e-6 * expected,
                 qPrintable(QStringLiteral("%1 s flying, %2 s expected").arg(flying).arg(expected)));
    }
    // The summary gives when the last robot is done: later than the plan's makespan.
    QVERIFY2(
        run.standardOutput.contains(QStringLiteral("done in the field after ") +
                                    QString::fromStdString(mcpp::formatDuration(lastDone))) &&
            run.standardOutput.contains(QStringLiteral(" flights and the turnarounds between them included")),
        qPrintable(run.standardOutput));
    QVERIFY(lastDone > report.value("makespan_s").toDouble());
    // The report gives the same last robot home, a lower bound in the field below it and above the paths'
    // (each flight's climb and descent), and how evenly the robots come home; the summary the bound.
    QVERIFY2(std::abs(report.value("field_makespan_s").toDouble() - lastDone) <= 1e-9 * lastDone,
             qPrintable(QString::number(report.value("field_makespan_s").toDouble())));
    const double fieldBound = report.value("field_lower_bound_s").toDouble();
    QVERIFY2(fieldBound > report.value("lower_bound_s").toDouble() && fieldBound <= lastDone,
             qPrintable(QStringLiteral("%1 s against %2 s").arg(fieldBound).arg(lastDone)));
    QVERIFY(report.value("field_spread").toDouble() >= 1.0);
    // The summary leads with what the team waits for; the paths' figures follow.
    QVERIFY2(run.standardOutput.contains(
                 QStringLiteral(" robots with mcpp-mlct: the last robot home after ") +
                 QString::fromStdString(mcpp::formatDuration(lastDone)) + ", last / first home " +
                 QString::number(report.value("field_spread").toDouble(), 'f', 3) + " (the paths: makespan "),
             qPrintable(run.standardOutput));
    QVERIFY2(run.standardOutput.contains(QStringLiteral("brings the last robot home before ") +
                                         QString::fromStdString(mcpp::formatDuration(fieldBound)) +
                                         " in the field\n"),
             qPrintable(run.standardOutput));
    int groundCells = 0;
    for (const QJsonValue& value : readJsonObject(ground + "/report.json").value("robots").toArray())
        groundCells += value.toObject().value("cells").toInt();
    QVERIFY2(cells * 3 < groundCells,
             qPrintable(QStringLiteral("%1 cells, %2 on the ground").arg(cells).arg(groundCells)));
    bool noted = false;
    for (const QJsonValue& issue : report.value("issues").toArray())
        noted = noted || issue.toObject().value("code").toString() == QStringLiteral("cruise-speed");
    QVERIFY(noted);
    const int droneParts = report.value("robots").toArray()[0].toObject().value("mission_parts").toInt();
    const QJsonArray items = readJsonObject(drone + "/" + partStem(0, 1, droneParts) + ".plan")
                                 .value("mission")
                                 .toObject()
                                 .value("items")
                                 .toArray();
    QCOMPARE(items.first().toObject().value("command").toInt(), 22);
    QCOMPARE(items.first().toObject().value("params").toArray()[6].toDouble(), 45.0);
    QCOMPARE(items.last().toObject().value("command").toInt(), 20);
}

// The first and last waypoint (command 16) of a QGroundControl plan, as [latitude, longitude].
QPair<QPointF, QPointF> planEnds(const QJsonObject& plan) {
    QPointF first;
    QPointF last;
    bool seen = false;
    for (const QJsonValue& item : plan.value("mission").toObject().value("items").toArray()) {
        if (item.toObject().value("command").toInt() != 16)
            continue;
        const QJsonArray params = item.toObject().value("params").toArray();
        last = QPointF(params[4].toDouble(), params[5].toDouble());
        if (!seen)
            first = last;
        seen = true;
    }
    return {first, last};
}

// A battery plan: sorties within the battery, their times adding up to the robot's with the charges, and
// the time in the field the waypoint files' parts with the same charges; with the charger at the start, each
// sortie is a part of the robot's mission, from the charger and back, and no file holds the whole path or a
// sortie twice; a rerun on a battery that lasts leaves no part behind.
void TestBatchEndToEnd::batteryPlansWriteEachSortie() {
    const QString out = scratch_.filePath("battery");
    const double battery = 600.0;
    const double recharge = 60.0;
    auto run =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--planner", "wavefront-battery", "--param",
                 "battery_s=600", "--param", "recharge_s=60", "--max-waypoints", "0", "--out", out});
    checkOutputs(out, 3, run, QStringLiteral("wavefront-battery"));
    if (QTest::currentTestFailed())
        return;
    const auto robots = readJsonObject(out + "/report.json").value("robots").toArray();
    for (qsizetype robot = 0; robot < robots.size(); ++robot) {
        const QJsonObject figures = robots[robot].toObject();
        const int sorties = figures.value("sorties").toInt();
        QVERIFY2(sorties > 1, qPrintable(QString::number(sorties)));
        QCOMPARE(figures.value("charges").toInt(), sorties - 1);
        QCOMPARE(figures.value("charging_s").toDouble(), (sorties - 1) * recharge);
        QCOMPARE(figures.value("mission_parts").toInt(), sorties);
        const QJsonArray times = figures.value("sortie_times_s").toArray();
        QCOMPARE(times.size(), sorties);
        double flying = 0.0;
        for (const QJsonValue& time : times) {
            QVERIFY(time.toDouble() <= battery * (1.0 + 1e-9));
            flying += time.toDouble();
        }
        QVERIFY(nearlyEqual(figures.value("time_s").toDouble(), flying + (sorties - 1) * recharge));
        // In the field, the waypoint files' parts with the same charges between them.
        double parts = 0.0;
        for (const QJsonValue& part : figures.value("mission_part_seconds").toArray())
            parts += part.toDouble();
        QVERIFY(parts > 0.0);
        QVERIFY2(nearlyEqual(figures.value("mission_field_s").toDouble(), parts + (sorties - 1) * recharge),
                 qPrintable(QString::number(figures.value("mission_field_s").toDouble())));
        QVERIFY2(run.standardOutput.contains(QStringLiteral("makes %1 sorties from its charger at its start, "
                                                            "one part each")
                                                 .arg(sorties)),
                 qPrintable(run.standardOutput));
        QVERIFY2(run.standardOutput.contains(partStem(robot, sorties, sorties) + QStringLiteral(".plan")),
                 qPrintable(run.standardOutput));
        QVERIFY(!QFileInfo::exists(QStringLiteral("%1/robot_%2.plan").arg(out).arg(robot + 1)));
        const auto start =
            planEnds(readJsonObject(QStringLiteral("%1/%2.plan").arg(out, partStem(robot, 1, sorties))))
                .first;
        for (int sortie = 1; sortie <= sorties; ++sortie) {
            const QString file = QStringLiteral("%1/%2.plan").arg(out, partStem(robot, sortie, sorties));
            QVERIFY2(QFileInfo::exists(file), qPrintable(file));
            const auto ends = planEnds(readJsonObject(file));
            QCOMPARE(ends.first, start); // the charger
            QCOMPARE(ends.second, start);
            QVERIFY(QFileInfo::exists(
                QStringLiteral("%1/%2.waypoints").arg(out, partStem(robot, sortie, sorties))));
        }
        QVERIFY(
            !QFileInfo::exists(QStringLiteral("%1/%2.plan").arg(out, partStem(robot, sorties + 1, sorties))));
    }
    const QStringList twice = QDir(out).entryList({QStringLiteral("*_sortie_*")});
    QVERIFY2(twice.isEmpty(), qPrintable(twice.join(", ")));
    // Chargers at the starts: the starts say where they are, and the vector files hold no chargers.
    GDALAllRegister();
    GDALDataset* package =
        GDALDataset::FromHandle(GDALOpenEx((out + "/plan.gpkg").toStdString().c_str(),
                                           GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    QVERIFY(package != nullptr);
    const bool chargersLayer = package->GetLayerByName("chargers") != nullptr;
    GDALClose(package);
    QVERIFY(!chargersLayer);
    for (const QJsonValue& feature : readJsonObject(out + "/plan.geojson").value("features").toArray())
        QVERIFY(feature.toObject().value("properties").toObject().value("kind").toString() != "charger");
    run = runMcpp({"--batch", samplePath("synthetic/mission.json"), "--planner", "wavefront-battery",
                   "--param", "battery_s=1000000", "--max-waypoints", "0", "--out", out});
    checkOutputs(out, 3, run, QStringLiteral("wavefront-battery"));
    const QStringList stale = QDir(out).entryList({QStringLiteral("*_part_*"), QStringLiteral("*_sortie_*")});
    QVERIFY2(stale.isEmpty(), qPrintable(stale.join(", ")));
    QVERIFY(QFileInfo::exists(out + "/robot_1.plan"));
}

// A drone with a charger away from its start takes off at the start for its first sortie and lands at the
// charger (no return to launch, which would fly back to the start); every later sortie takes off from the
// charger and returns to it, and each fits one flight.
void TestBatchEndToEnd::aDroneLandsItsFirstSortieAtAChargerAway() {
    const QString out = scratch_.filePath("charger-drone");
    const auto run = runMcpp({"--batch",
                              "--raster",
                              samplePath("synthetic/synthetic.asc"),
                              "--classes",
                              samplePath("synthetic/classes.csv"),
                              "--start",
                              "431040,5301040",
                              "--charger",
                              "431100,5301150",
                              "--planner",
                              "wavefront-battery",
                              "--vehicle",
                              "multirotor",
                              "--cruise-speed",
                              "2",
                              "--flight-time",
                              "5min",
                              "--altitude",
                              "20",
                              "--max-waypoints",
                              "0",
                              "--out",
                              out});
    checkOutputs(out, 1, run, QStringLiteral("wavefront-battery"));
    if (QTest::currentTestFailed())
        return;
    const int sorties =
        readJsonObject(out + "/report.json").value("robots").toArray()[0].toObject().value("sorties").toInt();
    QVERIFY2(sorties > 1, qPrintable(QString::number(sorties)));
    QVERIFY2(run.standardOutput.contains(
                 QStringLiteral("flies %1 sorties from its charger, the first from its start, one part each")
                     .arg(sorties)),
             qPrintable(run.standardOutput));
    QVERIFY2(!run.standardError.contains(QStringLiteral("longer than its")), qPrintable(run.standardError));
    const auto planOf = [&](int sortie) {
        return readJsonObject(QStringLiteral("%1/%2.plan").arg(out, partStem(0, sortie, sorties)))
            .value("mission")
            .toObject();
    };
    const auto homeOf = [](const QJsonObject& plan) {
        const QJsonArray home = plan.value("plannedHomePosition").toArray();
        return QPointF(home[0].toDouble(), home[1].toDouble());
    };
    const QPointF start = homeOf(planOf(1));
    const QPointF charger = planEnds(QJsonObject{{"mission", planOf(1)}}).second;
    QVERIFY(start != charger);
    for (int sortie = 1; sortie <= sorties; ++sortie) {
        const QJsonObject plan = planOf(sortie);
        const QJsonObject last = plan.value("items").toArray().last().toObject();
        if (sortie == 1) {
            QCOMPARE(last.value("command").toInt(), 21); // MAV_CMD_NAV_LAND, at the charger
            const QJsonArray params = last.value("params").toArray();
            QCOMPARE(QPointF(params[4].toDouble(), params[5].toDouble()), charger);
        } else {
            QCOMPARE(last.value("command").toInt(), 20); // MAV_CMD_NAV_RETURN_TO_LAUNCH
            QCOMPARE(homeOf(plan), charger);
        }
    }
    // The QGC WPL file of the first sortie lands at the charger too.
    QFile list(QStringLiteral("%1/%2.waypoints").arg(out, partStem(0, 1, sorties)));
    QVERIFY(list.open(QIODevice::ReadOnly));
    const QStringList rows = QString::fromUtf8(list.readAll()).trimmed().split(QLatin1Char('\n'));
    const QStringList landing = rows.last().split(QLatin1Char('\t'));
    QCOMPARE(landing.value(3), QStringLiteral("21"));
    QVERIFY(std::abs(landing.value(8).toDouble() - charger.x()) < 1e-7);
    QVERIFY(std::abs(landing.value(9).toDouble() - charger.y()) < 1e-7);
}

// A vehicle's turnaround is the battery planner's time at the charger, as the waypoint files' time in the
// field counts it between flights, in place of recharge_s, and a note says so.
void TestBatchEndToEnd::aTurnaroundIsTheTimeAtTheCharger() {
    const QString out = scratch_.filePath("turnaround");
    const double turnaround = 90.0;
    const auto run =
        runMcpp({"--batch", samplePath("synthetic/mission.json"), "--planner", "wavefront-battery", "--param",
                 "battery_s=600", "--param", "recharge_s=60", "--turnaround", "90s", "--out", out});
    checkOutputs(out, 3, run, QStringLiteral("wavefront-battery"));
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(run.standardOutput.contains(
                 QStringLiteral("between sorties, robots charge for their vehicle's turnaround: 1 min 30 s")),
             qPrintable(run.standardOutput));
    for (const QJsonValue& robot : readJsonObject(out + "/report.json").value("robots").toArray()) {
        const QJsonObject figures = robot.toObject();
        const int charges = figures.value("charges").toInt();
        QVERIFY(charges > 0);
        QCOMPARE(figures.value("charging_s").toDouble(), charges * turnaround);
    }
}

// A charger away from the start (robots[0].charger): the first sortie begins at the start, every sortie
// ends at the charger and the next begins there; each sortie is a part of the robot's mission, and no file
// holds the whole route or a sortie twice.
void TestBatchEndToEnd::aChargerAwayFromTheStartIsWhereSortiesEnd() {
    auto mission = sampleMissionAnywhere("synthetic", "synthetic.asc");
    auto robots = mission.value("robots").toArray();
    auto first = robots.at(0).toObject();
    first.insert("charger", QJsonArray{431100, 5301150});
    robots.replace(0, first);
    mission.insert("robots", robots);
    const QString path = scratch_.filePath("charger.json");
    QVERIFY(writeText(path, QJsonDocument(mission).toJson()));
    const QString out = scratch_.filePath("charger");
    auto run = runMcpp({"--batch", path, "--planner", "wavefront-battery", "--param", "battery_s=600",
                        "--max-waypoints", "0", "--out", out});
    checkOutputs(out, 3, run, QStringLiteral("wavefront-battery"));
    if (QTest::currentTestFailed())
        return;
    const int sorties =
        readJsonObject(out + "/report.json").value("robots").toArray()[0].toObject().value("sorties").toInt();
    QVERIFY2(sorties > 1, qPrintable(QString::number(sorties)));
    const auto partEnds = [&](const QString& folder, int part) {
        return planEnds(readJsonObject(QStringLiteral("%1/%2.plan").arg(folder, partStem(0, part, sorties))));
    };
    const auto whole = std::make_pair(partEnds(out, 1).first, partEnds(out, sorties).second);
    QVERIFY(whole.first != whole.second); // from the start to the charger
    // The sample's robots are rovers: they make sorties, they do not fly them.
    const QString said = run.standardOutput + run.standardError;
    QVERIFY2(said.contains(QStringLiteral("makes %1 sorties from its charger, the first from its start, one "
                                          "part each")
                               .arg(sorties)),
             qPrintable(said));
    QVERIFY2(!said.contains(QStringLiteral(" fl")), qPrintable(said));
    for (int sortie = 1; sortie <= sorties; ++sortie) {
        const auto ends = partEnds(out, sortie);
        QCOMPARE(ends.first, sortie == 1 ? whole.first : whole.second);
        QCOMPARE(ends.second, whole.second);
    }
    QVERIFY(!QFileInfo::exists(out + "/robot_1.plan"));
    QVERIFY(!QFileInfo::exists(QStringLiteral("%1/%2.plan").arg(out, partStem(0, sorties + 1, sorties))));
    const QStringList twice = QDir(out).entryList({QStringLiteral("*_sortie_*")});
    QVERIFY2(twice.isEmpty(), qPrintable(twice.join(", ")));
    // The charger is in the vector files, where a GIS user looks for it: the GeoPackage's chargers layer at
    // the coordinates given, and a feature of its own in the GeoJSON.
    GDALAllRegister();
    GDALDataset* package =
        GDALDataset::FromHandle(GDALOpenEx((out + "/plan.gpkg").toStdString().c_str(),
                                           GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    QVERIFY(package != nullptr);
    OGRLayer* chargers = package->GetLayerByName("chargers");
    const bool oneCharger = chargers != nullptr && chargers->GetFeatureCount() == 1;
    OGRFeature* charger = oneCharger ? chargers->GetNextFeature() : nullptr;
    const OGRPoint* chargerPoint = charger != nullptr ? charger->GetGeometryRef()->toPoint() : nullptr;
    const bool atTheCharger = chargerPoint != nullptr && charger->GetFieldAsInteger("robot") == 1 &&
                              std::abs(chargerPoint->getX() - 431100.0) < 1e-6 &&
                              std::abs(chargerPoint->getY() - 5301150.0) < 1e-6;
    OGRFeature::DestroyFeature(charger);
    GDALClose(package);
    QVERIFY(atTheCharger);
    int chargerFeatures = 0;
    for (const QJsonValue& feature : readJsonObject(out + "/plan.geojson").value("features").toArray())
        if (feature.toObject().value("properties").toObject().value("kind").toString() == "charger")
            ++chargerFeatures;
    QCOMPARE(chargerFeatures, 1);

    // The same mission given by flags, the charger by --charger: the same sorties and times.
    const QString byFlags = scratch_.filePath("charger-flags");
    const QStringList flags{"--batch", "--raster", samplePath("synthetic/synthetic.asc"), "--classes",
                            samplePath("synthetic/classes.csv")};
    // The charger belongs to the --start before it.
    const QStringList robotFlags{"--start", "431040,5301040", "--charger", "431100,5301150",
                                 "--start", "431230,5301280", "--start",   "431420,5301060"};
    run = runMcpp(flags + robotFlags +
                  QStringList{"--planner", "wavefront-battery", "--param", "battery_s=600", "--max-waypoints",
                              "0", "--out", byFlags});
    checkOutputs(byFlags, 3, run, QStringLiteral("wavefront-battery"));
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(std::make_pair(partEnds(byFlags, 1).first, partEnds(byFlags, sorties).second), whole);
    const auto robotsOf = [](const QString& folder) {
        return readJsonObject(folder + "/report.json").value("robots").toArray();
    };
    for (int robot = 0; robot < 3; ++robot)
        for (const char* field : {"sorties", "time_s", "cells"})
            QCOMPARE(robotsOf(byFlags)[robot].toObject().value(field),
                     robotsOf(out)[robot].toObject().value(field));
    // A planner without batteries plans as without the charger, and says it left it out.
    const QString withoutBatteries = scratch_.filePath("charger-mlct");
    run = runMcpp(flags + robotFlags + QStringList{"--out", withoutBatteries});
    checkOutputs(withoutBatteries, 3, run);
    QVERIFY2(run.standardError.contains(QStringLiteral("chargers are left out")),
             qPrintable(run.standardError));
}

// CPPIED: detection.tif lies on the plan's lattice in the raster's CRS; every cell a robot covers is seen
// at least as likely as band 2 asks, and report.json's figures are those of the file. A rerun with another
// planner leaves no detection.tif behind.
// A drone standing where a rover cannot start (here on the lake's shore pixel) takes off there: the plan is
// made, the summary says where its path begins, and its waypoint files' home is that point, not the path's
// first. The same start for a rover is refused, naming the robot's start.
void TestBatchEndToEnd::anAircraftOnTheLakeTakesOffThere() {
    auto mission = sampleMissionAnywhere("synthetic", "synthetic.asc");
    auto robots = mission.value("robots").toArray();
    auto second = robots.at(1).toObject();
    second.insert("start", QJsonArray{431288.75, 5301138.75}); // the lake's first pixel
    robots.replace(1, second);
    mission.insert("robots", robots);
    const QString path = scratch_.filePath("lake-shore.json");
    QVERIFY(writeText(path, QJsonDocument(mission).toJson()));
    const auto refused = runMcpp({"--batch", path, "--out", scratch_.filePath("lake-rover")});
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.standardError.contains(QStringLiteral("robots[1].start (shrubland): ")) &&
                 refused.standardError.contains(QStringLiteral("is on an obstacle: class 4 (Lake)")) &&
                 refused.standardError.contains(QStringLiteral(
                     "an aircraft (vehicle \"multirotor\" or \"fixed-wing\") would take off there")),
             qPrintable(refused.standardError));

    const QString out = scratch_.filePath("lake-drone");
    const auto run =
        runMcpp({"--batch", path, "--vehicle", "multirotor", "--cruise-speed", "5", "--out", out});
    checkOutputs(out, 3, run, QStringLiteral("mcpp-mlct"));
    if (QTest::currentTestFailed())
        return;
    // The degrees are gdaltransform's (-s_srs EPSG:32633 -t_srs EPSG:4326) to seven decimals.
    QVERIFY2(run.standardOutput.contains(QStringLiteral(
                 "robot 2 takes off at its start (431288.75, 5301138.75; longitude 14.0813625, latitude "
                 "47.8599126), which is on an obstacle: class 4 "
                 "(Lake), which robots cannot cross; it flies ")) &&
                 run.standardOutput.contains(QStringLiteral("(robot 2 is shrubland)")),
             qPrintable(run.standardOutput));
    for (const int robot : {1, 2}) {
        const auto plan = readJsonObject(QStringLiteral("%1/robot_%2.plan").arg(out).arg(robot));
        const QJsonArray home = plan.value("mission").toObject().value("plannedHomePosition").toArray();
        const QPointF homePoint(home[0].toDouble(), home[1].toDouble());
        const QPointF pathStart = planEnds(plan).first;
        const double apart = std::hypot(homePoint.x() - pathStart.x(), homePoint.y() - pathStart.y());
        // A degree of latitude is 111 km: the shrubland drone's path begins metres from the shore.
        if (robot == 1)
            QVERIFY2(apart < 1e-9, qPrintable(QString::number(apart)));
        else
            QVERIFY2(apart > 1e-6 && apart < 1e-3, qPrintable(QString::number(apart)));
    }
}

namespace {

struct DatasetCloser {
    void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

Dataset openReadOnly(const QString& path, unsigned kind) {
    return Dataset(GDALDataset::FromHandle(
        GDALOpenEx(path.toStdString().c_str(), kind | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
}

double areaOf(const OGRGeometry& geometry) {
    if (const auto* many = dynamic_cast<const OGRMultiPolygon*>(&geometry))
        return many->get_Area();
    return geometry.toPolygon()->get_Area();
}

double perimeterOf(const OGRGeometry& geometry) {
    std::unique_ptr<OGRGeometry> boundary(geometry.Boundary());
    if (const auto* lines = dynamic_cast<const OGRMultiLineString*>(boundary.get()))
        return lines->get_Length();
    return boundary->toLineString()->get_Length();
}

} // namespace

// What the files hold of a real plan, read back with OGR and GDAL: each region's polygon has its robot's
// area (GeoPackage, in the raster's CRS, to 1e-6; GeoJSON, in degrees to 9 decimals, within what that
// rounding can move its edges), each path its robot's length (a polyline of turning points is as long as
// the path), and regions.tif names, pixel for pixel, the robot whose region polygon holds the pixel; the
// robots' covered areas add up to the plan's.
void TestBatchEndToEnd::exportsReadBackUnchangedInSubstance() {
    const QString out = scratch_.filePath("read-back");
    const auto run = runMcpp({"--batch", samplePath("zion-nlcd/mission.json"), "--out", out});
    checkOutputs(out, 5, run);
    if (QTest::currentTestFailed())
        return;
    const QJsonArray robots = readJsonObject(out + "/report.json").value("robots").toArray();
    const auto reported = [&](int robot, const char* key) {
        return robots.at(robot - 1).toObject().value(QLatin1String(key)).toDouble();
    };
    GDALAllRegister();
    const Dataset package = openReadOnly(out + "/plan.gpkg", GDAL_OF_VECTOR);
    QVERIFY(package != nullptr);
    int regions = 0;
    for (auto& feature : *package->GetLayerByName("regions")) {
        const int robot = feature->GetFieldAsInteger("robot");
        const double area = areaOf(*feature->GetGeometryRef());
        QVERIFY2(
            nearlyEqual(area, reported(robot, "area_m2")),
            qPrintable(
                QString("robot %1: %2 against %3 m2").arg(robot).arg(area).arg(reported(robot, "area_m2"))));
        ++regions;
    }
    QCOMPARE(regions, 5);
    // The robots' passable land adds up to the plan's covered area, each within its region's area, and
    // below it where the region's sub-cells hold water.
    double covered = 0.0;
    bool someWater = false;
    for (int robot = 1; robot <= 5; ++robot) {
        covered += reported(robot, "covered_area_m2");
        QVERIFY(reported(robot, "covered_area_m2") <= reported(robot, "area_m2") * (1.0 + 1e-12));
        someWater =
            someWater || reported(robot, "covered_area_m2") < reported(robot, "area_m2") * (1.0 - 1e-6);
    }
    const double coveredArea = readJsonObject(out + "/report.json").value("covered_area_m2").toDouble();
    QVERIFY2(std::abs(covered - coveredArea) <= coveredArea * 1e-9,
             qPrintable(QString("%1 against %2 m2").arg(covered).arg(coveredArea)));
    QVERIFY(someWater);
    int paths = 0;
    for (auto& feature : *package->GetLayerByName("paths")) {
        const int robot = feature->GetFieldAsInteger("robot");
        const double length = feature->GetGeometryRef()->toLineString()->get_Length();
        QVERIFY2(nearlyEqual(length, reported(robot, "length_m")),
                 qPrintable(QString("robot %1: %2 against %3 m")
                                .arg(robot)
                                .arg(length)
                                .arg(reported(robot, "length_m"))));
        ++paths;
    }
    QCOMPARE(paths, 5);

    // GeoJSON, taken back to the raster's CRS. A coordinate rounded to 9 decimals of a degree moves less
    // than 0.1 mm: a path's length by at most 0.2 mm a segment, a polygon's area by its perimeter times that.
    const Dataset raster = openReadOnly(out + "/regions.tif", GDAL_OF_RASTER);
    QVERIFY(raster != nullptr);
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const std::unique_ptr<OGRCoordinateTransformation> toRasterCrs(
        OGRCreateCoordinateTransformation(&wgs84, raster->GetSpatialRef()));
    QVERIFY(toRasterCrs != nullptr);
    const Dataset geoJson = openReadOnly(out + "/plan.geojson", GDAL_OF_VECTOR);
    QVERIFY(geoJson != nullptr);
    int checked = 0;
    for (auto& feature : *geoJson->GetLayer(0)) {
        const std::string kind = feature->GetFieldAsString("kind");
        if (kind != "region" && kind != "path")
            continue;
        const int robot = feature->GetFieldAsInteger("robot");
        std::unique_ptr<OGRGeometry> geometry(feature->GetGeometryRef()->clone());
        QCOMPARE(geometry->transform(toRasterCrs.get()), OGRERR_NONE);
        if (kind == "region") {
            const double area = areaOf(*geometry);
            QVERIFY2(std::abs(area - reported(robot, "area_m2")) <= perimeterOf(*geometry) * 1e-4,
                     qPrintable(QString("robot %1: %2 against %3 m2")
                                    .arg(robot)
                                    .arg(area)
                                    .arg(reported(robot, "area_m2"))));
        } else {
            const OGRLineString& line = *geometry->toLineString();
            const double length = line.get_Length();
            QVERIFY2(std::abs(length - reported(robot, "length_m")) <= line.getNumPoints() * 2e-4,
                     qPrintable(QString("robot %1: %2 against %3 m")
                                    .arg(robot)
                                    .arg(length)
                                    .arg(reported(robot, "length_m"))));
        }
        ++checked;
    }
    QCOMPARE(checked, 10);

    // regions.tif against the region polygons burnt onto the same pixels (a pixel is burnt where its
    // centre lies in a polygon): every pixel of a robot in the one, of no robot in the other.
    const int columns = raster->GetRasterXSize();
    const int rows = raster->GetRasterYSize();
    const auto pixels = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
    std::vector<std::uint8_t> written(pixels);
    QCOMPARE(raster->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, columns, rows, written.data(), columns, rows,
                                                GDT_Byte, 0, 0, nullptr),
             CE_None);
    GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
    const Dataset burnt(memory->Create("", columns, rows, 1, GDT_Byte, nullptr));
    double placed[6] = {};
    QCOMPARE(raster->GetGeoTransform(placed), CE_None);
    burnt->SetGeoTransform(placed);
    burnt->SetSpatialRef(raster->GetSpatialRef());
    int bands[] = {1};
    OGRLayerH layers[] = {OGRLayer::ToHandle(package->GetLayerByName("regions"))};
    char attribute[] = "ATTRIBUTE=robot";
    char* options[] = {attribute, nullptr};
    QCOMPARE(GDALRasterizeLayers(GDALDataset::ToHandle(burnt.get()), 1, bands, 1, layers, nullptr, nullptr,
                                 nullptr, options, nullptr, nullptr),
             CE_None);
    std::vector<std::uint8_t> expected(pixels);
    QCOMPARE(burnt->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, columns, rows, expected.data(), columns, rows,
                                               GDT_Byte, 0, 0, nullptr),
             CE_None);
    std::size_t ofRobots = 0;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const bool ofARobot = written[i] >= 1 && written[i] <= 5;
        ofRobots += ofARobot ? 1 : 0;
        differing += (ofARobot ? written[i] : 0) != expected[i] ? 1 : 0;
    }
    QVERIFY(ofRobots > pixels / 4);
    QCOMPARE(differing, std::size_t{0});
}

void TestBatchEndToEnd::detectionPlansWriteTheDetectionRaster() {
    const QString out = scratch_.filePath("detection");
    auto run = runMcpp({"--batch", samplePath("zion-nlcd/mission.json"), "--planner", "cppied", "--param",
                        "required_probability=0.9", "--out", out});
    checkOutputs(out, 5, run, QStringLiteral("cppied"));
    if (QTest::currentTestFailed())
        return;
    const std::string path = (out + "/detection.tif").toStdString();
    GDALAllRegister();
    const std::unique_ptr<GDALDataset> dataset(GDALDataset::FromHandle(
        GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    QVERIFY2(dataset != nullptr, path.c_str());
    QCOMPARE(dataset->GetRasterCount(), 2);
    // On the plan's lattice: sub-cells of the grid, on the same lattice as regions.tif (the same sub-cells,
    // that file cropped to the plan's cells).
    const std::string regionsPath = (out + "/regions.tif").toStdString();
    const std::unique_ptr<GDALDataset> regions(GDALDataset::FromHandle(
        GDALOpenEx(regionsPath.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    QVERIFY(regions != nullptr);
    double placed[6] = {};
    double regionsPlaced[6] = {};
    QCOMPARE(dataset->GetGeoTransform(placed), CE_None);
    QCOMPARE(regions->GetGeoTransform(regionsPlaced), CE_None);
    for (const int term : {1, 5})
        QVERIFY2(std::abs(placed[term] - regionsPlaced[term]) < 1e-6,
                 qPrintable(QString("%1: %2 vs %3").arg(term).arg(placed[term]).arg(regionsPlaced[term])));
    for (const int term : {0, 3}) {
        const double pixels = (regionsPlaced[term] - placed[term]) / placed[term == 0 ? 1 : 5];
        QVERIFY2(std::abs(pixels - std::round(pixels)) < 1e-6 && pixels > -1e-6,
                 qPrintable(QString("%1: %2 vs %3").arg(term).arg(placed[term]).arg(regionsPlaced[term])));
    }
    QVERIFY(QString(dataset->GetProjectionRef()).contains("UTM zone 12N"));
    const int columns = dataset->GetRasterXSize();
    const int rows = dataset->GetRasterYSize();
    std::vector<float> seen(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    std::vector<float> required(seen.size());
    QCOMPARE(dataset->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, columns, rows, seen.data(), columns, rows,
                                                 GDT_Float32, 0, 0, nullptr),
             CE_None);
    QCOMPARE(dataset->GetRasterBand(2)->RasterIO(GF_Read, 0, 0, columns, rows, required.data(), columns, rows,
                                                 GDT_Float32, 0, 0, nullptr),
             CE_None);
    std::size_t targets = 0;
    double minimum = 1.0;
    for (std::size_t i = 0; i < seen.size(); ++i) {
        // Nodata (-1) in both bands where no robot goes, values in both elsewhere.
        QCOMPARE(seen[i] < 0.0F, required[i] < 0.0F);
        if (required[i] <= 0.0F)
            continue;
        ++targets;
        QCOMPARE(required[i], 0.9F);
        QVERIFY2(seen[i] >= 0.9F - 1e-6F, qPrintable(QString("cell %1: %2").arg(i).arg(seen[i])));
        minimum = std::min(minimum, double(seen[i]));
    }
    // The file holds the box around the cells robots go to: its first and last rows and columns hold some.
    const auto hasData = [&](int column, int row) {
        return seen[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                    static_cast<std::size_t>(column)] >= 0.0F;
    };
    bool firstRow = false, lastRow = false, firstColumn = false, lastColumn = false;
    for (int column = 0; column < columns; ++column) {
        firstRow = firstRow || hasData(column, 0);
        lastRow = lastRow || hasData(column, rows - 1);
    }
    for (int row = 0; row < rows; ++row) {
        firstColumn = firstColumn || hasData(0, row);
        lastColumn = lastColumn || hasData(columns - 1, row);
    }
    QVERIFY(firstRow && lastRow && firstColumn && lastColumn);
    const QJsonObject detection = readJsonObject(out + "/report.json").value("detection").toObject();
    QCOMPARE(detection.value("targets").toDouble(), double(targets));
    QVERIFY(targets > 10000);
    QVERIFY(std::abs(detection.value("minimum").toDouble() - minimum) < 1e-6);
    QCOMPARE(detection.value("share_met").toDouble(), 1.0);
    QCOMPARE(detection.value("required_probability").toDouble(), 0.9);
    run = runMcpp({"--batch", samplePath("zion-nlcd/mission.json"), "--out", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    QVERIFY(!QFileInfo::exists(out + "/detection.tif"));
}

// MDSTC on the Zion sample with robot 1 (index 0) at half speed from 30 000 s and robot 3 stopping at
// 60 000 s: report.json gives the events, each robot's completion, and the static plan's figures under the
// same events (never done: a robot stops with work left).
void TestBatchEndToEnd::eventsArePlayedAndComparedWithTheStaticPlan() {
    const QString out = scratch_.filePath("events");
    const auto run = runMcpp({"--batch", samplePath("zion-nlcd/mission.json"), "--planner", "mdstc",
                              "--event", "30000:0:0.5", "--event", "60000:2:0", "--out", out});
    checkOutputs(out, 5, run, QStringLiteral("mdstc"));
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(run.standardOutput.contains("under 2 events"), qPrintable(run.standardOutput));
    const QJsonObject report = readJsonObject(out + "/report.json");
    const QJsonArray events = report.value("events").toArray();
    QCOMPARE(events.size(), 2);
    QCOMPARE(events[0].toObject().value("time_s").toDouble(), 30000.0);
    QCOMPARE(events[1].toObject().value("robot").toInt(), 2);
    QCOMPARE(events[1].toObject().value("speed_factor").toDouble(), 0.0);
    double latest = 0.0;
    int takenOver = 0;
    const QJsonArray robots = report.value("robots").toArray();
    for (const QJsonValue& value : robots) {
        const QJsonObject robot = value.toObject();
        latest = std::max(latest, robot.value("completion_s").toDouble());
        takenOver += robot.value("cells_taken_over").toInt();
    }
    QCOMPARE(report.value("makespan_under_events_s").toDouble(), latest);
    QVERIFY(takenOver > 0);
    // What they took over is also a vector layer: its cells add up to the report's.
    int takenOverInGeoJson = 0;
    for (const QJsonValue& feature : readJsonObject(out + "/plan.geojson").value("features").toArray()) {
        const QJsonObject properties = feature.toObject().value("properties").toObject();
        if (properties.value("kind").toString() == QStringLiteral("taken_over"))
            takenOverInGeoJson += properties.value("cells").toInt();
    }
    QCOMPARE(takenOverInGeoJson, takenOver);
    // The stopped robot was done when it stopped; the static plan's never finishes.
    const QJsonObject stopped = robots[2].toObject();
    QVERIFY(stopped.value("stopped").toBool());
    QVERIFY(stopped.value("completion_s").toDouble() <= 60000.0);
    QVERIFY(stopped.value("static_completion_s").isNull());
    QVERIFY(report.value("static_makespan_s").isNull());
    QCOMPARE(report.value("static_planner").toString(), QString("mcpp-mlct"));
    QVERIFY(report.value("static_plan_makespan_s").toDouble() > 0.0);
    // The others covered all the stopped robot left.
    for (const QJsonValue& issue : report.value("issues").toArray())
        QVERIFY(issue.toObject().value("code").toString() != QString("left-uncovered"));
}

void TestBatchEndToEnd::everyPlannerRunsFromTheCommandLine_data() {
    QTest::addColumn<QString>("planner");
    for (const mcpp::PlannerDescription& planner : mcpp::plannerDescriptions())
        QTest::newRow(planner.name.c_str()) << QString::fromStdString(planner.name);
}

// Every registered planner by name, with one of its own parameters set by --param: the report names the
// planner and the parameter's value, and a one-robot planner gets one start.
void TestBatchEndToEnd::everyPlannerRunsFromTheCommandLine() {
    QFETCH(QString, planner);
    const auto description = mcpp::makePlanner(planner.toStdString())->description();
    const QString out = scratch_.filePath("planner-" + planner);
    QStringList arguments = description.singleRobot
                                ? syntheticFlags() + QStringList{"--start", "431040,5301040"}
                                : QStringList{"--batch", samplePath("synthetic/mission.json")};
    arguments << "--planner" << planner << "--param"
              << "snap_starts_to_free_cells=true"
              << "--out" << out;
    const auto run = runMcpp(arguments);
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    const auto report = readJsonObject(out + "/report.json");
    QCOMPARE(report.value("planner").toString(), planner);
    const auto parameters = report.value("parameters").toObject();
    QCOMPARE(parameters.value("snap_starts_to_free_cells"), QJsonValue(true));
    QCOMPARE(parameters.size(), static_cast<qsizetype>(description.parameters.size()));
    QVERIFY(report.value("issues").isArray());
    const QString said = run.standardOutput + run.standardError;
    QVERIFY2(said.contains("with " + planner + ":"), qPrintable(said));
    QVERIFY(QFileInfo::exists(out + "/plan.geojson"));
}

void TestBatchEndToEnd::badInputExitsTwoWithOneLine_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("mentions"); // every one must appear in the line
    const auto flags = syntheticFlags();
    const QString out = scratch_.filePath("never-written");
    const QString mission = samplePath("synthetic/mission.json");

    QTest::newRow("start in nodata") << (flags + QStringList{"--start", syntheticOnNodata, "--out", out})
                                     << QStringList{"--start 1", "nodata"};
    QTest::newRow("start on the lake")
        << (flags + QStringList{"--start", "431040,5301040", "--start", syntheticOnLake, "--out", out})
        << QStringList{"--start 2", "Lake"};
    QTest::newRow("start outside the raster") << (flags + QStringList{"--start", "0,0", "--out", out})
                                              << QStringList{"--start 1", "outside the raster"};
    QTest::newRow("missing raster") << QStringList{"--batch",  "--raster", scratch_.filePath("missing.tif"),
                                                   "--preset", "nlcd",     "--start",
                                                   "1,2",      "--out",    out}
                                    << QStringList{"missing.tif"};
    QTest::newRow("missing mission") << QStringList{"--batch", scratch_.filePath("absent.json"), "--out", out}
                                     << QStringList{"absent.json"};
    QTest::newRow("malformed mission")
        << QStringList{"--batch", scratch_.filePath("broken.json"), "--out", out}
        << QStringList{"broken.json", "invalid JSON"};
    QTest::newRow("mission robot in nodata")
        << QStringList{"--batch", scratch_.filePath("nodata-robot.json"), "--out", out}
        << QStringList{
               "nodata-robot.json", "robots[1].start", "nodata",
               "; move it into the task area, or let the planner start the robot from the nearest free cell "
               "(",
               "planner.parameters.snap_starts_to_free_cells=true (or --param "
               "snap_starts_to_free_cells=true))"};
    QTest::newRow("mission robots in one cell")
        << QStringList{"--batch", scratch_.filePath("shared-cell.json"), "--out", out}
        << QStringList{"shared-cell.json", "robots[2].start (forest)", "same cell as robot 1's start",
                       "(robot 1 is robots[0], grassland)"};
    QTest::newRow("mission start in the wrong CRS")
        << QStringList{"--batch", scratch_.filePath("wrong-crs.json"), "--out", out}
        << QStringList{
               "wrong-crs.json", "robots[0].start_crs",
               "in EPSG:26911 the start (306000, 4150000) lies off the map, but these numbers lie on it "
               "in the raster's own CRS, EPSG:26912 (NAD83 / UTM zone 12N): give start_crs EPSG:26912"};
    QTest::newRow("mission start in metres given as degrees")
        << QStringList{"--batch", scratch_.filePath("metres-as-degrees.json"), "--out", out}
        << QStringList{"metres-as-degrees.json", "robots[0].start_crs",
                       "; these numbers lie on the map in the raster's own CRS, EPSG:26912 (NAD83 / UTM zone "
                       "12N): give start_crs EPSG:26912, or leave it out"};
    QTest::newRow("mission robot without start")
        << QStringList{"--batch", scratch_.filePath("no-start.json"), "--out", out}
        << QStringList{"no-start.json", "robots[0].start", "missing"};
    QTest::newRow("class table lacks a class")
        << QStringList{"--batch",
                       "--raster",
                       samplePath("synthetic/synthetic.asc"),
                       "--classes",
                       scratch_.filePath("partial.csv"),
                       "--start",
                       "431040,5301040",
                       "--out",
                       out}
        << QStringList{"synthetic.asc", "class 2", "--missing-as-obstacle"};
    QTest::newRow("bad class table") << QStringList{"--batch",
                                                    "--raster",
                                                    samplePath("synthetic/synthetic.asc"),
                                                    "--classes",
                                                    scratch_.filePath("bad.csv"),
                                                    "--start",
                                                    "431040,5301040",
                                                    "--out",
                                                    out}
                                     << QStringList{"bad.csv"};
    QTest::newRow("unknown preset") << (QStringList{"--batch", "--raster",
                                                    samplePath("synthetic/synthetic.asc"), "--preset",
                                                    "no-such-preset", "--start", "431040,5301040", "--out",
                                                    out})
                                    << QStringList{"--preset", "no-such-preset"};
    QTest::newRow("unknown planner") << QStringList{"--batch",         mission, "--planner",
                                                    "no-such-planner", "--out", out}
                                     << QStringList{"--planner", "no-such-planner", "mcpp-mlct"};
    QTest::newRow("unknown parameter")
        << QStringList{"--batch", mission, "--planner", "darp", "--param", "no_such_key=1", "--out", out}
        << QStringList{"--param no_such_key", "no planner has a parameter"};
    QTest::newRow("parameter of another planner")
        << QStringList{"--batch", mission, "--planner", "mstc", "--param", "max_iterations=5", "--out", out}
        << QStringList{"max_iterations", "mstc has no parameter", "balanced"};
    QTest::newRow("parameter not a number")
        << QStringList{"--batch", mission, "--planner", "darp", "--param", "max_iterations=abc", "--out", out}
        << QStringList{"--param max_iterations", "whole number", "abc"};
    QTest::newRow("parameter out of range")
        << QStringList{"--batch", mission, "--planner", "darp", "--param", "convergence_tolerance=2",
                       "--out",   out}
        << QStringList{"convergence_tolerance", "0 to 0.5", "2"};
    QTest::newRow("one-robot planner, three starts")
        << QStringList{"--batch", mission, "--planner", "spiral-stc", "--out", out}
        << QStringList{"spiral-stc plans for one robot", "3 starts", "darp", "mstc"};
    QTest::newRow("unknown start CRS")
        << (flags + QStringList{"--start", "1,2", "--start-crs", "EPSG:999999", "--out", out})
        << QStringList{"--start-crs"};
    QTest::newRow("two robots in one cell")
        << (flags + QStringList{"--start", "431050,5301050", "--start", "431055,5301055", "--out", out})
        << QStringList{"--start 2", "(431055, 5301055; longitude 14.0782511, latitude 47.8591342)",
                       "same cell as robot 1's start (a cell", "snap_starts_to_free_cells=true"};
    QTest::newRow("--out is a file") << QStringList{"--batch", mission, "--out",
                                                    samplePath("synthetic/classes.csv")}
                                     << QStringList{"--out", "classes.csv", "not a folder"};
    QTest::newRow("bad flag") << QStringList{"--batch", mission, "--out", out, "--start", "12,abc"}
                              << QStringList{"--start"};
}

void TestBatchEndToEnd::badInputExitsTwoWithOneLine() {
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, mentions);

    QVERIFY(writeText(scratch_.filePath("broken.json"), "{ \"format\": \"mcpp-mission\", \"version\": "));
    QVERIFY(writeText(scratch_.filePath("partial.csv"),
                      "value,name,speed_mps,fov_m,passable\n1,Forest,1,5,true\n"
                      "3,Grass,3,20,true\n4,Lake,0,10,false\n"));
    QVERIFY(writeText(scratch_.filePath("bad.csv"), "value,name,speed,fov_m,passable\n1,Forest,1,5,true\n"));
    // Copies of the synthetic mission with one robot broken; the raster path made absolute.
    auto mission = sampleMissionAnywhere("synthetic", "synthetic.asc");
    QVERIFY(!mission.value("robots").toArray().isEmpty());
    auto robots = mission.value("robots").toArray();
    auto second = robots.at(1).toObject();
    second.insert("start", QJsonArray{431470, 5301310});
    robots.replace(1, second);
    auto nodataMission = mission;
    nodataMission.insert("robots", robots);
    QVERIFY(writeText(scratch_.filePath("nodata-robot.json"), QJsonDocument(nodataMission).toJson()));
    auto first = robots.at(0).toObject();
    first.remove("start");
    robots.replace(0, first);
    auto noStartMission = mission;
    noStartMission.insert("robots", robots);
    QVERIFY(writeText(scratch_.filePath("no-start.json"), QJsonDocument(noStartMission).toJson()));
    auto sharing = mission.value("robots").toArray();
    auto third = sharing.at(2).toObject();
    third.insert("start", QJsonArray{431040, 5301040}); // grassland's start
    sharing.replace(2, third);
    auto sharedCellMission = mission;
    sharedCellMission.insert("robots", sharing);
    QVERIFY(writeText(scratch_.filePath("shared-cell.json"), QJsonDocument(sharedCellMission).toJson()));
    // The Zion sample with its first start said to be in UTM zone 11, its numbers being zone 12's.
    auto zion = sampleMissionAnywhere("zion-nlcd", "nlcd.tif");
    auto zionRobots = zion.value("robots").toArray();
    auto northWest = zionRobots.at(0).toObject();
    northWest.insert("start_crs", QStringLiteral("EPSG:26911"));
    zionRobots.replace(0, northWest);
    zion.insert("robots", zionRobots);
    QVERIFY(writeText(scratch_.filePath("wrong-crs.json"), QJsonDocument(zion).toJson()));
    northWest.insert("start_crs", QStringLiteral("EPSG:4326")); // metres that no longitude reaches
    zionRobots.replace(0, northWest);
    zion.insert("robots", zionRobots);
    QVERIFY(writeText(scratch_.filePath("metres-as-degrees.json"), QJsonDocument(zion).toJson()));

    const auto run = runMcpp(arguments);
    QVERIFY2(run.exitCode == 2,
             qPrintable(QStringLiteral("exit %1: %2").arg(run.exitCode).arg(run.standardError)));
    QVERIFY2(run.standardError.endsWith('\n') && run.standardError.count('\n') == 1,
             qPrintable(run.standardError));
    QVERIFY(run.standardError.startsWith(QStringLiteral("mcpp: ")));
    for (const auto& mention : mentions) {
        QVERIFY2(run.standardError.contains(mention), qPrintable(mention + " not in: " + run.standardError));
    }
    QVERIFY(run.standardOutput.isEmpty());
    QVERIFY2(!QFileInfo::exists(scratch_.filePath("never-written")),
             "bad input must not create the output folder");
}

// The planner numbers robots from 1; a mission file's robots are known by name: a warning about one says
// which it is, without the mission's array index an error gives to find the field.
void TestBatchEndToEnd::warningsNameTheRobotsTheyNumber() {
    auto mission = sampleMissionAnywhere("synthetic", "synthetic.asc");
    auto robots = mission.value("robots").toArray();
    QVERIFY(robots.size() >= 3);
    auto third = robots.at(2).toObject();
    QCOMPARE(third.value("name").toString(), QStringLiteral("forest"));
    third.insert("start", robots.at(0).toObject().value("start")); // in the first robot's cell
    robots.replace(2, third);
    mission.insert("robots", robots);
    auto planner = mission.value("planner").toObject();
    auto parameters = planner.value("parameters").toObject();
    parameters.insert("snap_starts_to_free_cells", true);
    planner.insert("parameters", parameters);
    mission.insert("planner", planner);
    const QString path = scratch_.filePath("moved-start.json");
    QVERIFY(writeText(path, QJsonDocument(mission).toJson()));
    const auto run = runMcpp({"--batch", path, "--out", scratch_.filePath("moved-start")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.standardError));
    const QString moved = run.standardError.split('\n').filter(QStringLiteral("moved")).join('\n');
    QVERIFY2(moved.startsWith(QStringLiteral("mcpp: warning: robot 3 start ")),
             qPrintable(run.standardError));
    QVERIFY2(moved.endsWith(QStringLiteral(" (robot 1 is grassland; robot 3 is forest)")), qPrintable(moved));
}

QTEST_GUILESS_MAIN(TestBatchEndToEnd)
#include "test_batch_end_to_end.moc"
