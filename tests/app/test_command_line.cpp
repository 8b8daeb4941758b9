#include "app/CommandLine.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"

#include <QProcess>
#include <QtTest>
#include <string>
#include <vector>

using mcpp::app::CommandLine;
using mcpp::app::RunMode;

Q_DECLARE_METATYPE(std::vector<std::string>)

namespace {

std::vector<std::string> split(const QString& arguments) {
    std::vector<std::string> result;
    for (const auto& argument : arguments.split(QLatin1Char(' '), Qt::SkipEmptyParts))
        result.push_back(argument.toStdString());
    return result;
}

// "a, b, c": the planners this build offers, as messages list them.
std::string availableList() {
    std::string list;
    for (const auto& name : mcpp::availablePlanners())
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

// The smallest valid flag mission, to which each error case adds or removes one thing.
const QString flagMission =
    QStringLiteral("--batch --raster map.tif --classes classes.csv --start 10,20 --out out");

} // namespace

class TestCommandLine : public QObject {
    Q_OBJECT

  private slots:
    void helpAndVersionWinOverEverythingElse_data();
    void helpAndVersionWinOverEverythingElse();
    void guiModeTakesOneOptionalFile();
    void batchWithMissionFile();
    void missionFileTakesOverrideFlags();
    void batchWithEveryFlag();
    void batchWithPresetAndShortForms();
    void startCrsTakesAnyDefinition();
    void negativeAndSpacedCoordinates();
    void errors_data();
    void errors();
    void usageDocumentsEveryFlag();
    void plannerHelpListsEveryDeclaredParameter();
    void versionNamesTheProjectVersion();
    void executablePrintsTheParserErrorOnOneLine();
};

void TestCommandLine::helpAndVersionWinOverEverythingElse_data() {
    QTest::addColumn<QString>("arguments");
    QTest::addColumn<int>("mode");
    QTest::newRow("--help") << "--help" << static_cast<int>(RunMode::Help);
    QTest::newRow("-h") << "-h" << static_cast<int>(RunMode::Help);
    QTest::newRow("--help after a bad flag")
        << "--batch --frobnicate --help" << static_cast<int>(RunMode::Help);
    QTest::newRow("--version") << "--version" << static_cast<int>(RunMode::Version);
    QTest::newRow("-v with batch") << "--batch m.json -v" << static_cast<int>(RunMode::Version);
}

void TestCommandLine::helpAndVersionWinOverEverythingElse() {
    QFETCH(QString, arguments);
    QFETCH(int, mode);
    const auto result = CommandLine::parse(split(arguments));
    QVERIFY2(result.ok(), result.error.c_str());
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(static_cast<int>(result.options.mode), mode);
}

void TestCommandLine::guiModeTakesOneOptionalFile() {
    auto result = CommandLine::parse({});
    QVERIFY(result.ok());
    QCOMPARE(static_cast<int>(result.options.mode), static_cast<int>(RunMode::Gui));
    QVERIFY(result.options.guiFile.empty());

    result = CommandLine::parse({"samples/zion-nlcd/mission.json"});
    QVERIFY(result.ok());
    QCOMPARE(static_cast<int>(result.options.mode), static_cast<int>(RunMode::Gui));
    QCOMPARE(result.options.guiFile, std::string("samples/zion-nlcd/mission.json"));
    QVERIFY(result.options.missionPath.empty());

    result = CommandLine::parse({"map.tif"});
    QVERIFY(result.ok());
    QCOMPARE(result.options.guiFile, std::string("map.tif"));
}

void TestCommandLine::batchWithMissionFile() {
    const auto result = CommandLine::parse(split("--batch samples/zion-nlcd/mission.json --out /tmp/plan"));
    QVERIFY2(result.ok(), result.error.c_str());
    const auto& options = result.options;
    QCOMPARE(static_cast<int>(options.mode), static_cast<int>(RunMode::Batch));
    QCOMPARE(options.missionPath, std::string("samples/zion-nlcd/mission.json"));
    QCOMPARE(options.outputDirectory, std::string("/tmp/plan"));
    QVERIFY(!options.missionFromFlags());
    QVERIFY(options.rasterPath.empty());
    QVERIFY(options.starts.empty());
    QVERIFY(!options.planner.has_value());
    QVERIFY(!options.band.has_value());
    QVERIFY(options.parameters.empty());
    QVERIFY(!options.quiet);
    QVERIFY(!options.missingAsObstacle);

    // The mission may come after the flags as well.
    const auto reordered = CommandLine::parse(split("--out /tmp/plan --batch m.json"));
    QVERIFY2(reordered.ok(), reordered.error.c_str());
    QCOMPARE(reordered.options.missionPath, std::string("m.json"));
}

void TestCommandLine::missionFileTakesOverrideFlags() {
    const auto result = CommandLine::parse(split("--batch m.json --out o --planner mcpp-mlct --band 3 "
                                                 "--purity 0.1 --open-paths --missing-as-obstacle -q"));
    QVERIFY2(result.ok(), result.error.c_str());
    const auto& options = result.options;
    QCOMPARE(options.planner.value_or(""), std::string("mcpp-mlct"));
    QCOMPARE(options.band.value_or(0), 3);
    QCOMPARE(options.parameters.size(), std::size_t{2});
    QCOMPARE(options.parameters[0].key, std::string("purity_tolerance"));
    QCOMPARE(options.parameters[0].value, std::string("0.1"));
    QCOMPARE(options.parameters[0].flag, std::string("--purity"));
    QCOMPARE(options.parameters[1].key, std::string("closed_tour"));
    QCOMPARE(options.parameters[1].value, std::string("false"));
    QVERIFY(options.missingAsObstacle);
    QVERIFY(options.quiet);
}

void TestCommandLine::batchWithEveryFlag() {
    const auto result = CommandLine::parse(split(
        "--batch --raster map.tif --classes table.csv --start 318000.5,4130000 --start 319000,4131000.25 "
        "--start -113.1,37.2 --start-crs EPSG:4326 --charger 318100,4130200.5 --planner mcpp-mlct --band 2 "
        "--purity 0.25 --missing-as-obstacle --open-paths --quiet --out results --vehicle multirotor "
        "--altitude 60 --cruise-speed 8.5 --fov-scale 4 --flight-time 25min --turnaround 4.5min "
        "--camera-trigger 37.5"));
    QVERIFY2(result.ok(), result.error.c_str());
    const auto& options = result.options;
    QCOMPARE(static_cast<int>(options.mode), static_cast<int>(RunMode::Batch));
    QVERIFY(options.missionFromFlags());
    QCOMPARE(options.rasterPath, std::string("map.tif"));
    QCOMPARE(options.classesPath, std::string("table.csv"));
    QVERIFY(options.preset.empty());
    QCOMPARE(options.starts.size(), std::size_t{3});
    QCOMPARE(options.starts[0].x, 318000.5);
    QCOMPARE(options.starts[0].y, 4130000.0);
    QCOMPARE(options.starts[1].x, 319000.0);
    QCOMPARE(options.starts[1].y, 4131000.25);
    QCOMPARE(options.starts[2].x, -113.1);
    QCOMPARE(options.starts[2].y, 37.2);
    QCOMPARE(options.startCrs, std::string("EPSG:4326"));
    // The robot of the --start before it, the third; the others charge at their starts.
    QCOMPARE(options.chargers.size(), std::size_t{3});
    QVERIFY(!options.chargers[0] && !options.chargers[1]);
    QVERIFY(options.chargers[2].has_value());
    QCOMPARE(options.chargers[2]->x, 318100.0);
    QCOMPARE(options.chargers[2]->y, 4130200.5);
    QCOMPARE(options.planner.value_or(""), std::string("mcpp-mlct"));
    QCOMPARE(options.band.value_or(0), 2);
    QCOMPARE(options.parameters.size(), std::size_t{2});
    QCOMPARE(options.parameters[0].value, std::string("0.25"));
    QVERIFY(options.missingAsObstacle);
    QCOMPARE(options.parameters[1].flag, std::string("--open-paths"));
    QVERIFY(options.quiet);
    QCOMPARE(options.outputDirectory, std::string("results"));
    QVERIFY(options.vehicleType == mcpp::io::VehicleType::Multirotor);
    QCOMPARE(options.altitudeMetres.value_or(-1.0), 60.0);
    QCOMPARE(options.cruiseSpeedMetresPerSecond.value_or(-1.0), 8.5);
    QCOMPARE(options.fieldOfViewScale.value_or(-1.0), 4.0);
    QCOMPARE(options.flightTimeSeconds.value_or(-1.0), 1500.0);
    QCOMPARE(options.turnaroundSeconds.value_or(-1.0), 270.0);
    QCOMPARE(options.cameraTriggerMetres.value_or(-1.0), 37.5);
    QVERIFY(!options.fieldOfViewMetres);
    // One footprint for every class, in place of the scale.
    const auto footprint = CommandLine::parse(split("--batch m.json --out o --fov 42.5"));
    QVERIFY2(footprint.ok(), footprint.error.c_str());
    QCOMPARE(footprint.options.fieldOfViewMetres.value_or(-1.0), 42.5);
    QVERIFY(!footprint.options.fieldOfViewScale);
    // The outputs asked for, each once, report.json (which the summary reads) always among them.
    QVERIFY(options.outputKeys.empty());
    const auto some = CommandLine::parse(split("--batch m.json --out o --outputs png,kml,png"));
    QVERIFY2(some.ok(), some.error.c_str());
    QCOMPARE(some.options.outputKeys, (std::vector<std::string>{"png", "kml", "report-json"}));
}

void TestCommandLine::batchWithPresetAndShortForms() {
    const auto result = CommandLine::parse(
        split("--batch --raster=map.tif --preset=nlcd --start=1,2 --start-crs=epsg:32612 -o out"));
    QVERIFY2(result.ok(), result.error.c_str());
    const auto& options = result.options;
    QCOMPARE(options.rasterPath, std::string("map.tif"));
    QCOMPARE(options.preset, std::string("nlcd"));
    QVERIFY(options.classesPath.empty());
    QCOMPARE(options.starts.size(), std::size_t{1});
    QCOMPARE(options.startCrs, std::string("epsg:32612"));
    QCOMPARE(options.outputDirectory, std::string("out"));
}

// --start-crs takes what a mission file's start_crs takes: any definition, checked when the map is read.
void TestCommandLine::startCrsTakesAnyDefinition() {
    for (const std::string crs : {"ESRI:102008", "+proj=utm +zone=32 +datum=WGS84", "WGS84"}) {
        const auto result = CommandLine::parse({"--batch", "--raster", "m.tif", "--preset", "p", "--start",
                                                "1,2", "--start-crs", crs, "--out", "o"});
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(result.options.startCrs, crs);
    }
}

void TestCommandLine::negativeAndSpacedCoordinates() {
    // A value starting with a single dash is a coordinate, not a flag; spaces around the numbers are fine.
    const auto result = CommandLine::parse({"--batch", "--raster", "m.tif", "--preset", "p", "--start",
                                            "-5.5, -7", "--start", " 1e3 ,+2 ", "--out", "o"});
    QVERIFY2(result.ok(), result.error.c_str());
    QCOMPARE(result.options.starts.size(), std::size_t{2});
    QCOMPARE(result.options.starts[0].x, -5.5);
    QCOMPARE(result.options.starts[0].y, -7.0);
    QCOMPARE(result.options.starts[1].x, 1000.0);
    QCOMPARE(result.options.starts[1].y, 2.0);
}

void TestCommandLine::errors_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const auto words = [](const QString& text) { return text.split(QLatin1Char(' '), Qt::SkipEmptyParts); };
    const QString raster = QStringLiteral("--batch --raster map.tif --start 10,20 --out out ");

    QTest::newRow("missing --out") << words("--batch m.json") << "--batch needs --out DIR";
    QTest::newRow("missing --out with flags")
        << words("--batch --raster map.tif --classes c.csv --start 1,2") << "--batch needs --out DIR";
    QTest::newRow("--out without value") << words("--batch m.json --out") << "--out needs a value: DIR";
    QTest::newRow("--out followed by a flag")
        << words("--batch m.json --out --quiet") << "--out needs a value: DIR";
    QTest::newRow("--out given twice")
        << words("--batch m.json --out a --out b") << "--out is given more than once";
    QTest::newRow("--classes and --preset") << words(raster + "--classes c.csv --preset nlcd")
                                            << "--classes and --preset cannot be used together";
    QTest::newRow("--raster without --start")
        << words("--batch --raster map.tif --out out") << "--raster needs at least one --start X,Y";
    QTest::newRow("third --start not a number")
        << words("--batch --raster map.tif --preset p --start 1,2 --start 3,4 --start 12,abc --out o")
        << "--start 3: \"12,abc\" is not X,Y";
    QTest::newRow("--start without comma")
        << words(flagMission + " --start 12") << "--start 2: \"12\" is not X,Y";
    QTest::newRow("--start with a space after the comma")
        << words("--batch --raster m.tif --preset p --start 7.40, 1.67 --out o")
        << "--start 1: \"7.40,\" is not X,Y: write it without a space after the comma, or in quotes";
    QTest::newRow("--start with three numbers")
        << words("--batch --raster m.tif --preset p --start 1,2,3 --out o")
        << "--start 1: \"1,2,3\" is not X,Y";
    QTest::newRow("--start not finite") << words("--batch --raster m.tif --preset p --start nan,2 --out o")
                                        << "--start 1: \"nan,2\" is not X,Y";
    QTest::newRow("--start without value")
        << words("--batch --raster m.tif --preset p --start") << "--start needs a value: X,Y";
    QTest::newRow("no --start") << words("--batch --raster m.tif --preset p --out o")
                                << "--raster needs at least one --start X,Y";
    QTest::newRow("unknown flag") << words("--batch m.json --out o --frobnicate")
                                  << "unknown flag --frobnicate (see mcpp --help)";
    QTest::newRow("flag cut short") << words("--batch m.json --out o --cruise 3")
                                    << "unknown flag --cruise (did you mean --cruise-speed? see mcpp --help)";
    QTest::newRow("flag misspelt") << words("--batch m.json --out o --altitud 3")
                                   << "unknown flag --altitud (did you mean --altitude? see mcpp --help)";
    QTest::newRow("unknown short flag") << words("-x") << "unknown flag -x (see mcpp --help)";
    QTest::newRow("unknown flag with value")
        << words("--colour=red") << "unknown flag --colour (see mcpp --help)";
    QTest::newRow("--altitude with a unit")
        << words(flagMission + " --altitude 100m")
        << "--altitude: \"100m\" is not an altitude above home (a number of metres without a unit, 0 to "
           "10000): write 100";
    // Another unit, or a number the flag refuses, gets no number to write.
    QTest::newRow("--altitude in kilometres") << words(flagMission + " --altitude 1.5km")
                                              << "--altitude: \"1.5km\" is not an altitude above home (a "
                                                 "number of metres without a unit, 0 to 10000)";
    QTest::newRow("--altitude too high with a unit")
        << words(flagMission + " --altitude 20000m")
        << "--altitude: \"20000m\" is not an altitude above home (a number of metres without a unit, 0 to "
           "10000)";
    QTest::newRow("--cruise-speed with a unit") << words(flagMission + " --cruise-speed 10m/s")
                                                << "--cruise-speed: \"10m/s\" is not a speed (a number of "
                                                   "metres per second without a unit: 0 for the "
                                                   "land-cover speeds, up to 1000): write 10";
    QTest::newRow("--flight-time in minutes without a unit")
        << words(flagMission + " --flight-time 25")
        << "--flight-time \"25\": must be 0 (no limit) or a flight of 1 min to 1000 h (60 to 3600000 s), not "
           "25 s (for 25 minutes, write 25min)";
    QTest::newRow("--start-crs empty")
        << words(flagMission + " --start-crs=") << "--start-crs needs a value: CRS";
    QTest::newRow("--charger not a point")
        << words(raster + "--preset p --charger 1,2 --start 30,40 --charger 3")
        << "--charger after --start 2: \"3\" is not X,Y";
    QTest::newRow("two chargers for one start")
        << words(raster + "--preset p --charger 1,2 --charger 3,4")
        << "--start 1 has a --charger already: give one --charger after each --start";
    QTest::newRow("--charger before any --start")
        << words("--batch --raster map.tif --charger 1,2 --start 10,20 --out out")
        << "--charger \"1,2\" comes before any --start: give it after the --start of its robot";
    QTest::newRow("mission and --charger")
        << words("--batch m.json --charger 1,2 --out o")
        << "--charger cannot be combined with a mission file; the mission gives it";
    QTest::newRow("--band zero") << words("--batch m.json --out o --band 0")
                                 << "--band: \"0\" is not a band number (1, 2, ...)";
    QTest::newRow("--band text") << words("--batch m.json --out o --band two")
                                 << "--band: \"two\" is not a band number (1, 2, ...)";
    QTest::newRow("--purity too large")
        << words("--batch m.json --out o --purity 1.5")
        << "--purity: expected a number from 0 up to (not including) 1, got 1.5";
    QTest::newRow("--purity negative")
        << words("--batch m.json --out o --purity -0.1")
        << "--purity: expected a number from 0 up to (not including) 1, got -0.1";
    QTest::newRow("--max-waypoints too small")
        << words("--batch m.json --out o --max-waypoints 3")
        << "--max-waypoints: \"3\" is not an item limit (0 for none, or 10 or more mission items)";
    QTest::newRow("--vehicle unknown")
        << words("--batch m.json --out o --vehicle quadcopter")
        << "--vehicle: \"quadcopter\" is not a vehicle (rover, multirotor or fixed-wing)";
    QTest::newRow("--altitude negative")
        << words("--batch m.json --out o --altitude -5")
        << "--altitude: \"-5\" is not an altitude above home (a number of metres without a unit, 0 to 10000)";
    QTest::newRow("--cruise-speed in km/h")
        << words("--batch m.json --out o --cruise-speed 1200")
        << "--cruise-speed: \"1200\" is not a speed (a number of metres per second without a unit: 0 for the "
           "land-cover speeds, up to 1000)";
    QTest::newRow("--flight-time in parsecs")
        << words("--batch m.json --out o --flight-time 12parsecs")
        << "--flight-time: \"12parsecs\" is not a duration (seconds, or a number with s, min or h: 25min)";
    QTest::newRow("--flight-time of half a minute")
        << words("--batch m.json --out o --flight-time 30")
        << "--flight-time \"30\": must be 0 (no limit) or a flight of 1 min to 1000 h (60 to 3600000 s), "
           "not 30 s (for 30 minutes, write 30min)";
    QTest::newRow("--flight-time a second above 1000 h")
        << words("--batch m.json --out o --flight-time 3600001")
        << "--flight-time \"3600001\": must be 0 (no limit) or a flight of 1 min to 1000 h (60 to 3600000 "
           "s), "
           "not 3600001 s";
    QTest::newRow("--turnaround of two days")
        << words("--batch m.json --out o --turnaround 48h")
        << "--turnaround \"48h\": must be a time on the ground of 0 to 24 h (0 to 86400 s), not 172800 s";
    QTest::newRow("--camera-trigger negative") << words("--batch m.json --out o --camera-trigger -5")
                                               << "--camera-trigger: \"-5\" is not a distance between photos "
                                                  "(a number of metres without a unit: 0 for none, or 0.1 "
                                                  "to 10000)";
    QTest::newRow("--turnaround without a number")
        << words("--batch m.json --out o --turnaround soon")
        << "--turnaround: \"soon\" is not a duration (seconds, or a "
           "number with s, min or h: 5min)";
    QTest::newRow("--fov-scale zero")
        << words("--batch m.json --out o --fov-scale 0")
        << "--fov-scale: \"0\" is not a factor for the fields of view (more than 0, up to 1000)";
    QTest::newRow("--fov zero") << words("--batch m.json --out o --fov 0")
                                << "--fov: \"0\" is not a field of view (more than 0, up to 100000 m)";
    QTest::newRow("--fov beyond any sensor")
        << words("--batch m.json --out o --fov 2e5")
        << "--fov: \"2e5\" is not a field of view (more than 0, up to 100000 m)";
    QTest::newRow("--outputs unknown")
        << words("--batch m.json --out o --outputs geojson,shapefile")
        << "--outputs: \"shapefile\" is not an output; the outputs are geojson, gpkg, regions-tif, "
           "detection-tif, kml, gpx, qgc-plan, qgc-wpl, waypoint-csv, report-json, report-csv, png, svg";
    QTest::newRow("--outputs empty")
        << words("--batch m.json --out o --outputs ,")
        << "--outputs needs output names separated by commas: geojson, gpkg, "
           "regions-tif, detection-tif, kml, gpx, qgc-plan, qgc-wpl, waypoint-csv, "
           "report-json, report-csv, png, svg";
    QTest::newRow("--fov beside --fov-scale")
        << words("--batch m.json --out o --fov 40 --fov-scale 2")
        << "--fov and --fov-scale cannot be used together: --fov sets every class's field of view, "
           "--fov-scale multiplies the table's";
    QTest::newRow("--max-waypoints negative")
        << words("--batch m.json --out o --max-waypoints -700")
        << "--max-waypoints: \"-700\" is not an item limit (0 for none, or 10 or more mission items)";
    QTest::newRow("--param without value")
        << words("--batch m.json --out o --param closed_tour") << "--param: \"closed_tour\" is not KEY=VALUE";
    QTest::newRow("--param without key")
        << words("--batch m.json --out o --param =3") << "--param: \"=3\" is not KEY=VALUE";
    QTest::newRow("--param unknown key") << words("--batch m.json --out o --param closed_tours=true")
                                         << "--param closed_tours: no planner has a parameter of that name "
                                            "(did you mean closed_tour? see mcpp "
                                            "--help-planner NAME)";
    QTest::newRow("--param key far from any")
        << words("--batch m.json --out o --param frobnicate=1")
        << "--param frobnicate: no planner has a parameter of that name (see mcpp --help-planner NAME)";
    QTest::newRow("--planner misspelt")
        << words("--batch m.json --out o --planner darpp")
        << "--planner: unknown planner \"darpp\": did you mean \"darp\"? (available: " +
               QString::fromStdString(availableList()) + ")";
    QTest::newRow("--planner unknown")
        << words("--batch m.json --out o --planner dijkstra")
        << "--planner: unknown planner \"dijkstra\" (available: " + QString::fromStdString(availableList()) +
               ")";
    QTest::newRow("switch with value")
        << words("--batch m.json --out o --quiet=yes") << "--quiet takes no value";
    QTest::newRow("batch flag without --batch") << words("--out o") << "--out only applies with --batch";
    QTest::newRow("--start without --batch")
        << words("m.json --start 1,2") << "--start only applies with --batch";
    QTest::newRow("two files") << words("a.json b.json")
                               << "unexpected argument \"b.json\" (see mcpp --help)";
    QTest::newRow("two missions") << words("--batch a.json b.json --out o")
                                  << "unexpected argument \"b.json\" (see mcpp --help)";
    QTest::newRow("mission and --raster")
        << words("--batch m.json --raster map.tif --out o")
        << "--raster cannot be combined with a mission file; the mission gives it";
    QTest::newRow("mission and --start")
        << words("--batch m.json --start 1,2 --out o")
        << "--start cannot be combined with a mission file; the mission gives it";
    QTest::newRow("--batch alone") << words("--batch") << "--batch needs MISSION.json or --raster FILE";
    QTest::newRow("--batch with flags but no raster")
        << words("--batch --preset p --start 1,2 --out o") << "--batch needs MISSION.json or --raster FILE";
}

void TestCommandLine::errors() {
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    std::vector<std::string> list;
    for (const auto& argument : arguments)
        list.push_back(argument.toStdString());
    const auto result = CommandLine::parse(list);
    QVERIFY(!result.ok());
    QCOMPARE(QString::fromStdString(result.error), message);
    QCOMPARE(result.exitCode, 2);
    QVERIFY(!result.error.empty() && result.error.find('\n') == std::string::npos);
}

void TestCommandLine::usageDocumentsEveryFlag() {
    const auto usage = QString::fromStdString(CommandLine::usage());
    for (const char* flag : {"--batch",
                             "--out",
                             "--raster",
                             "--classes",
                             "--preset",
                             "--start X,Y",
                             "--start-crs",
                             "--charger X,Y",
                             "--planner",
                             "--band",
                             "--purity",
                             "--param KEY=VALUE",
                             "--help-planner NAME",
                             "--missing-as-obstacle",
                             "--open-paths",
                             "--quiet",
                             "--help",
                             "--version",
                             "plan.geojson",
                             "report.json",
                             "robot_<n>.plan",
                             "robot_<n>.waypoints",
                             "robot_<n>.csv",
                             "plan.png",
                             "mcpp-mlct"}) {
        QVERIFY2(usage.contains(QLatin1String(flag)), flag);
    }
}

void TestCommandLine::plannerHelpListsEveryDeclaredParameter() {
    for (const auto& planner : mcpp::plannerDescriptions()) {
        const auto result = CommandLine::parse({"--help-planner", planner.name});
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(static_cast<int>(result.options.mode), static_cast<int>(RunMode::PlannerHelp));
        const auto help = QString::fromStdString(CommandLine::plannerHelp(planner.name));
        QVERIFY(help.contains(QString::fromStdString(planner.summary)));
        for (const auto& parameter : planner.parameters) {
            const auto setting = parameter.key + "=" + parameter.format(parameter.defaultValue);
            QVERIFY2(help.contains(QString::fromStdString(setting)), setting.c_str());
            // The unit is said once, with the range ("from 0 to 600 s.", not "600 s (s).").
            if (!parameter.unit.empty())
                QVERIFY2(!help.contains(QString::fromStdString(" (" + parameter.unit + ").")),
                         setting.c_str());
            // A parameter that needs switches names them all ("Only with balanced=true and ...").
            if (!parameter.onlyWith.empty())
                QVERIFY2(
                    help.simplified().contains(QString::fromStdString(
                        "Only with " + switchesText(switchesNeeded(planner.parameters, parameter)) + ".")),
                    setting.c_str());
        }
        // The usage lists the planner on one line.
        QVERIFY(QString::fromStdString(CommandLine::usage())
                    .contains(QString::fromStdString("  " + planner.name)));
    }
    const auto unknown = CommandLine::parse({"--help-planner", "dijkstra"});
    QVERIFY(!unknown.ok());
    QVERIFY(unknown.error.find("unknown planner \"dijkstra\"") != std::string::npos);
}

void TestCommandLine::versionNamesTheProjectVersion() {
    QCOMPARE(QString::fromStdString(CommandLine::versionText()), QStringLiteral("mcpp " MCPP_VERSION "\n"));
}

void TestCommandLine::executablePrintsTheParserErrorOnOneLine() {
    const QString executable = qEnvironmentVariable("MCPP_EXECUTABLE");
    if (executable.isEmpty())
        QSKIP("MCPP_EXECUTABLE is not set; run through ctest");
    QProcess process;
    process.start(executable, {"--batch", "--raster", "map.tif", "--preset", "p", "--start", "1,2", "--start",
                               "3,4", "--start", "12,abc", "--out", "o"});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 2);
    QCOMPARE(QString::fromUtf8(process.readAllStandardError()),
             QStringLiteral("mcpp: --start 3: \"12,abc\" is not X,Y\n"));
    QVERIFY(process.readAllStandardOutput().isEmpty());

    process.start(executable, {"--version"});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitCode(), 0);
    QCOMPARE(QString::fromUtf8(process.readAllStandardOutput()), QStringLiteral("mcpp " MCPP_VERSION "\n"));

    process.start(executable, {"--help"});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitCode(), 0);
    QVERIFY(QString::fromUtf8(process.readAllStandardOutput()).contains(QStringLiteral("--start-crs CRS")));
}

QTEST_GUILESS_MAIN(TestCommandLine)
#include "test_command_line.moc"
