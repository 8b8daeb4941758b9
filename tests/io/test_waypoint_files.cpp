// Per-robot waypoint files compared with real files from QGroundControl, MAVSDK and ArduPilot.

#include "PlanFixture.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/TextFiles.hpp"
#include "tests/support/SyntheticMaps.hpp"
#include "tests/support/TestData.hpp"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

using namespace mcpp;
using namespace mcpp::io;
using mcpp::test::testDataPath;

namespace {

QJsonObject readJson(const std::string& path) {
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

std::set<QString> keysOf(const QJsonObject& object) {
    const QStringList keys = object.keys();
    return {keys.begin(), keys.end()};
}

// The JsonValue (insertion-ordered) of a parsed document: QJsonObject keeps keys sorted, as the plans
// write them.
internal::JsonValue jsonValueOf(const QJsonValue& value) {
    if (value.isObject()) {
        internal::JsonValue object = internal::JsonValue::object();
        const QJsonObject members = value.toObject();
        for (auto member = members.begin(); member != members.end(); ++member)
            object.add(member.key().toStdString(), jsonValueOf(member.value()));
        return object;
    }
    if (value.isArray()) {
        internal::JsonValue array = internal::JsonValue::array();
        for (const QJsonValue& item : value.toArray())
            array.push(jsonValueOf(item));
        return array;
    }
    if (value.isBool())
        return {value.toBool()};
    if (value.isDouble())
        return {value.toDouble()};
    if (value.isString())
        return {value.toString().toStdString()};
    return {};
}

std::vector<std::vector<std::string>> tabRows(const std::string& path, std::string& header) {
    std::ifstream file(path);
    std::getline(file, header);
    if (!header.empty() && header.back() == '\r')
        header.pop_back();
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(file, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.empty())
            continue;
        std::vector<std::string> fields;
        std::stringstream stream(line);
        std::string field;
        while (std::getline(stream, field, '\t'))
            fields.push_back(field);
        rows.push_back(fields);
    }
    return rows;
}

} // namespace

class WaypointFilesTest : public QObject {
    Q_OBJECT

  private:
    Plan plan_ = test::makeFixturePlan();
    GeoReference reference_ = GeoReference::fromDefinition("EPSG:26912").value();
    ClassTable classes_;
    QTemporaryDir folder_;

    ExportContext context(ExportSettings settings = {}) const {
        return ExportContext{plan_, reference_, classes_, settings};
    }
    std::string file(const char* name) const { return folder_.filePath(name).toStdString(); }

  private slots:
    void mergingCollinearPoints() {
        const std::vector<Waypoint> all = exportedWaypoints(plan_.paths[0], plan_.cells, false);
        QCOMPARE(all.size(), plan_.paths[0].waypoints.size());
        const std::vector<Waypoint> merged = exportedWaypoints(plan_.paths[0], plan_.cells, true);
        QCOMPARE(merged.size(), std::size_t{5}); // the two inner points of the straight top run go
        QCOMPARE(merged[1].x, plan_.paths[0].waypoints[3].x);
        QCOMPARE(exportedWaypointIndices(plan_.paths[0], plan_.cells, true)[1], std::size_t{3});
        // A speed change keeps its point even on a straight line.
        const std::vector<Waypoint> second = exportedWaypoints(plan_.paths[1], plan_.cells, true);
        QCOMPARE(second.size(), plan_.paths[1].waypoints.size());
    }

    // Asked to keep collinear points, the files of a path whose straight runs were merged (large plans)
    // hold every waypoint it walked, as those of the whole path do.
    void collinearPointsOfMergedRunsOnRequest() {
        ExportSettings settings;
        settings.mergeCollinear = false;
        const Plan whole = plan_;
        std::string header;
        QVERIFY(writeWaypointList(context(settings), 0, file("whole.waypoints")).ok());
        QVERIFY(writeWaypointCsv(context(settings), 0, file("whole.csv")).ok());
        for (CoveragePath& path : plan_.paths)
            mergeStraightRuns(path, plan_.cells);
        const bool merged = plan_.paths[0].runsMerged();
        const bool listWritten = writeWaypointList(context(settings), 0, file("merged.waypoints")).ok();
        const bool csvWritten = writeWaypointCsv(context(settings), 0, file("merged.csv")).ok();
        plan_ = whole;
        QVERIFY(merged && listWritten && csvWritten);
        const auto wholeRows = tabRows(file("whole.waypoints"), header);
        const auto mergedRows = tabRows(file("merged.waypoints"), header);
        QCOMPARE(mergedRows.size(), wholeRows.size());
        for (std::size_t row = 0; row < wholeRows.size(); ++row)
            for (std::size_t field : {8U, 9U}) // latitude, longitude
                QVERIFY(std::abs(std::stod(mergedRows[row][field]) - std::stod(wholeRows[row][field])) <
                        1e-9);
        const auto lines = [](const std::string& path) {
            std::ifstream csv(path);
            std::size_t count = 0;
            for (std::string line; std::getline(csv, line);)
                ++count;
            return count;
        };
        QCOMPARE(lines(file("merged.csv")), lines(file("whole.csv")));
        QCOMPARE(lines(file("whole.csv")), plan_.paths[0].waypoints.size() + 1);
    }

    // What the files keep by default (turning points, speed and land-cover changes) is the same whether
    // the path's straight runs were merged or not: on a planned map of three land covers, two of them
    // alike but for their names.
    void mergedRunsExportTheSamePoints() {
        test::RandomMapSpec spec;
        spec.columns = 40;
        spec.rows = 30;
        spec.landCovers = 3;
        spec.obstacleFraction = 0.05;
        spec.robots = 3;
        spec.seed = 5;
        PlanningProblem problem = test::randomProblem(spec);
        // Wood as fast as grass and seen as far: a change of land cover with no change of speed or size.
        problem.classes.set({2, "wood", 0x705030U, 2.0, 10.0, true});
        problem.classes.set({1, "grass", 0x404040U, 2.0, 10.0, true});
        const Plan planned = MlctPlanner{}.plan(problem, {});
        for (const CoveragePath& path : planned.paths) {
            CoveragePath merged = path;
            mergeStraightRuns(merged, planned.cells);
            QVERIFY(merged.waypoints.size() < path.waypoints.size());
            const std::vector<Waypoint> expected = exportedWaypoints(path, planned.cells, true);
            const std::vector<Waypoint> actual = exportedWaypoints(merged, planned.cells, true);
            QCOMPARE(actual.size(), expected.size());
            for (std::size_t i = 0; i < expected.size(); ++i)
                QVERIFY(actual[i].x == expected[i].x && actual[i].y == expected[i].y &&
                        actual[i].cell == expected[i].cell &&
                        actual[i].speedMetresPerSecond == expected[i].speedMetresPerSecond);
            QCOMPARE(turningPoints(merged).size(), turningPoints(path).size());
        }
    }

    void qgroundControlPlanMatchesTheSampleStructure() {
        const QJsonObject sample =
            readJson(testDataPath("waypoint-formats/mavsdk_qgroundcontrol_sample.plan"));
        QVERIFY(!sample.isEmpty());
        const std::string path = file("robot0.plan");
        ExportSettings settings;
        settings.vehicle.altitudeMetres = 25.0;
        settings.mergeCollinear = false;
        Status written = writeQGroundControlPlan(context(settings), 0, path);
        QVERIFY2(written.ok(), written.error().c_str());
        const QJsonObject plan = readJson(path);
        QVERIFY(keysOf(plan) == keysOf(sample));
        // Degrees to eight decimals at most (an autopilot holds seven), never in exponent form.
        QFile text(QString::fromStdString(path));
        QVERIFY(text.open(QIODevice::ReadOnly));
        const QString planText = QString::fromUtf8(text.readAll());
        QVERIFY(!planText.contains(QRegularExpression(QStringLiteral("[0-9]\\.[0-9]{9}"))));
        QVERIFY(!planText.contains(QRegularExpression(QStringLiteral("[0-9]e[-+]?[0-9]"))));
        QCOMPARE(plan["fileType"].toString(), QString("Plan"));
        QCOMPARE(plan["version"].toInt(), sample["version"].toInt());
        QCOMPARE(plan["groundStation"].toString(), QString("QGroundControl"));
        QVERIFY(keysOf(plan["geoFence"].toObject()) == keysOf(sample["geoFence"].toObject()));
        QVERIFY(keysOf(plan["rallyPoints"].toObject()) == keysOf(sample["rallyPoints"].toObject()));
        const QJsonObject mission = plan["mission"].toObject();
        const QJsonObject sampleMission = sample["mission"].toObject();
        QVERIFY(keysOf(mission) == keysOf(sampleMission));
        QCOMPARE(mission["version"].toInt(), 2);
        QCOMPARE(mission["cruiseSpeed"].toDouble(), 0.5);

        // Every waypoint item has the keys of the sample's NAV_WAYPOINT items.
        QJsonObject sampleWaypoint;
        for (const QJsonValue& item : sampleMission["items"].toArray()) {
            if (item.toObject()["command"].toInt() == 16)
                sampleWaypoint = item.toObject();
        }
        const QJsonArray allItems = mission["items"].toArray();
        // The vehicle is told its speed first (cruiseSpeed is only the ground station's default).
        const QJsonObject speed = allItems[0].toObject();
        QCOMPARE(speed["command"].toInt(), 178);
        QCOMPARE(speed["doJumpId"].toInt(), 1);
        QCOMPARE(speed["params"].toArray()[1].toDouble(), 0.5);
        QJsonArray items;
        for (qsizetype i = 1; i < allItems.size(); ++i)
            items.append(allItems[i]);
        QCOMPARE(items.size(), static_cast<qsizetype>(plan_.paths[0].waypoints.size()));
        int jump = 2;
        for (qsizetype i = 0; i < items.size(); ++i) {
            const QJsonObject item = items[i].toObject();
            QVERIFY(keysOf(item) == keysOf(sampleWaypoint));
            QCOMPARE(item["command"].toInt(), 16);
            QCOMPARE(item["frame"].toInt(), 3);
            QCOMPARE(item["type"].toString(), QString("SimpleItem"));
            QCOMPARE(item["doJumpId"].toInt(), jump++);
            QVERIFY(item["autoContinue"].toBool());
            const QJsonArray params = item["params"].toArray();
            QCOMPARE(params.size(), 7);
            QVERIFY(params[3].isNull());
            const Waypoint& waypoint = plan_.paths[0].waypoints[static_cast<std::size_t>(i)];
            const LonLat expected = reference_.toWgs84({waypoint.x, waypoint.y}).value();
            QVERIFY(std::abs(params[4].toDouble() - expected.latitude) <= 6e-9); // eight decimals
            QVERIFY(std::abs(params[5].toDouble() - expected.longitude) <= 6e-9);
            QCOMPARE(params[6].toDouble(),
                     0.0); // a rover drives on the ground, whatever altitude it is given
            QCOMPARE(item["Altitude"].toDouble(), 0.0);
        }
        const QJsonArray home = mission["plannedHomePosition"].toArray();
        QCOMPARE(home.size(), 3);
        QCOMPARE(home[0].toDouble(), items[0].toObject()["params"].toArray()[4].toDouble()); // first waypoint
        QCOMPARE(home[1].toDouble(), items[0].toObject()["params"].toArray()[5].toDouble());
    }

    // The plans are written as text directly: laid out byte for byte as JsonValue writes the same
    // document (two-space indents, arrays of numbers and flat objects such as the items on one line), with
    // and without speed changes, for a rover and for an aircraft (its takeoff and return to launch).
    void qgroundControlPlanIsLaidOutAsJsonValueWritesIt() {
        for (const VehicleType type : {VehicleType::Rover, VehicleType::Multirotor})
            for (const int robot : {0, 1}) {
                ExportSettings settings;
                settings.vehicle.type = type;
                settings.vehicle.cameraTriggerMetres = robot == 1 ? 12.5 : 0.0; // with camera commands
                const std::string path = file("layout.plan");
                QVERIFY(writeQGroundControlPlan(context(settings), robot, path).ok());
                QFile written(QString::fromStdString(path));
                QVERIFY(written.open(QIODevice::ReadOnly));
                const QByteArray text = written.readAll();
                const QJsonDocument parsed = QJsonDocument::fromJson(text);
                QVERIFY(parsed.isObject());
                const std::string expected =
                    jsonValueOf(parsed.object()).toText(internal::JsonValue::Layout::FlatObjectsOnOneLine);
                QCOMPARE(text.toStdString(), expected);
            }
    }

    void speedChangesBecomeChangeSpeedItems() {
        const std::string path = file("robot1.plan");
        QVERIFY(writeQGroundControlPlan(context(), 1, path).ok());
        const QJsonArray items = readJson(path)["mission"].toObject()["items"].toArray();
        std::vector<double> speeds;
        for (const QJsonValue& value : items) {
            const QJsonObject item = value.toObject();
            if (item["command"].toInt() == 178)
                speeds.push_back(item["params"].toArray()[1].toDouble());
        }
        // The speed it starts at (the 20 m cell's 1.5 m/s), then the one change, to 1 m/s.
        QCOMPARE(speeds, (std::vector<double>{1.5, 1.0}));
        // A fixed cruise speed: one speed item at the start, cruiseSpeed set.
        ExportSettings cruise;
        cruise.vehicle.cruiseSpeedMetresPerSecond = 2.0;
        QVERIFY(writeQGroundControlPlan(context(cruise), 1, path).ok());
        const QJsonObject mission = readJson(path)["mission"].toObject();
        QCOMPARE(mission["cruiseSpeed"].toDouble(), 2.0);
        const QJsonArray cruiseItems = mission["items"].toArray();
        QCOMPARE(cruiseItems[0].toObject()["params"].toArray()[1].toDouble(), 2.0);
        for (qsizetype i = 0; i < cruiseItems.size(); ++i)
            QCOMPARE(cruiseItems[i].toObject()["command"].toInt(), i == 0 ? 178 : 16);
    }

    // An aeroplane's autopilot is told an airspeed (type 0): a ground speed would set ArduPlane's least
    // speed over the ground, not its cruise. Other vehicles are told their ground speed (type 1).
    void speedChangesTellAnAeroplaneItsAirspeed() {
        for (const auto& [type, speedType] :
             {std::pair{VehicleType::Rover, 1}, {VehicleType::Multirotor, 1}, {VehicleType::FixedWing, 0}}) {
            ExportSettings settings;
            settings.vehicle.type = type;
            const std::string planPath = file("typed.plan");
            const std::string listPath = file("typed.waypoints");
            QVERIFY(writeQGroundControlPlan(context(settings), 0, planPath).ok());
            QVERIFY(writeWaypointList(context(settings), 0, listPath).ok());
            int planTypes = 0;
            for (const QJsonValue& item : readJson(planPath)["mission"].toObject()["items"].toArray())
                if (item.toObject()["command"].toInt() == 178) {
                    QCOMPARE(item.toObject()["params"].toArray()[0].toInt(), speedType);
                    ++planTypes;
                }
            std::string header;
            int listTypes = 0;
            for (const std::vector<std::string>& row : tabRows(listPath, header))
                if (row[3] == "178") {
                    QCOMPARE(std::stod(row[4]), double(speedType));
                    ++listTypes;
                }
            QVERIFY(planTypes > 0);
            QCOMPARE(listTypes, planTypes);
        }
    }

    void waypointListMatchesQgcWpl110() {
        std::string sampleHeader;
        const auto sample =
            tabRows(testDataPath("waypoint-formats/qgc_unittest_MissionPlanner.waypoints"), sampleHeader);
        const std::string path = file("robot0.waypoints");
        ExportSettings settings;
        settings.mergeCollinear = false;
        QVERIFY(writeWaypointList(context(settings), 0, path).ok());
        std::string header;
        const auto rows = tabRows(path, header);
        QCOMPARE(header, sampleHeader);
        // Home, the speed the vehicle starts at, then one row per waypoint.
        QCOMPARE(rows.size(), plan_.paths[0].waypoints.size() + 2);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            QCOMPARE(rows[i].size(), sample[0].size());
            QCOMPARE(rows[i][0], std::to_string(i));
            QCOMPARE(rows[i][3], std::string(i == 1 ? "178" : "16"));
            QCOMPARE(rows[i][11], std::string("1"));
        }
        QCOMPARE(std::stod(rows[1][5]), 0.5);   // DO_CHANGE_SPEED's second parameter: the land-cover speed
        QCOMPARE(rows[0][1], std::string("1")); // home row is current, as QGroundControl writes it
        QCOMPARE(rows[0][2], std::string("0"));
        QCOMPARE(rows[2][2], std::string("3"));
        const Waypoint& first = plan_.paths[0].waypoints[0];
        const LonLat expected = reference_.toWgs84({first.x, first.y}).value();
        QVERIFY(std::abs(std::stod(rows[2][8]) - expected.latitude) < 1e-7);
        QVERIFY(std::abs(std::stod(rows[2][9]) - expected.longitude) < 1e-7);
        QCOMPARE(std::stod(rows[2][10]), 0.0); // a rover's, whatever the settings' altitude
        QCOMPARE(rows[0][8], rows[2][8]);
    }

    // A photo survey: each part starts the camera after its first waypoint, a photo every so many metres
    // and one at once, and stops it after its last, so that no photos are taken on the way out or back;
    // the two items count against the autopilot's limit.
    void aCameraTakesPhotosAlongEachPartsWaypointsOnly() {
        ExportSettings settings;
        settings.mergeCollinear = false;
        settings.vehicle.type = VehicleType::Multirotor;
        settings.vehicle.cameraTriggerMetres = 25.0;
        settings.vehicle.maxWaypoints = 10;
        // The camera items of QGroundControl's own survey, in the MAVSDK sample.
        QJsonObject sampleCameraItem;
        const QJsonArray survey =
            readJson(testDataPath("waypoint-formats/"
                                  "mavsdk_qgroundcontrol_sample_with_survey.plan"))["mission"]
                .toObject()["items"]
                .toArray();
        for (const QJsonValue& item : survey)
            for (const QJsonValue& inner :
                 item.toObject()["TransectStyleComplexItem"].toObject()["Items"].toArray())
                if (inner.toObject()["command"].toInt() == 206)
                    sampleCameraItem = inner.toObject();
        QVERIFY(!sampleCameraItem.isEmpty());
        QCOMPARE(sampleCameraItem["frame"].toInt(), 2);
        const std::string path = file("camera.plan");
        QVERIFY(writeQGroundControlPlan(context(settings), 0, path).ok());
        QVERIFY(!QFile::exists(QString::fromStdString(path)));
        qsizetype waypoints = 0;
        for (const char* part : {"camera_part_1.plan", "camera_part_2.plan"}) {
            const QJsonArray items = readJson(file(part))["mission"].toObject()["items"].toArray();
            QVERIFY2(items.size() + 1 <= settings.vehicle.maxWaypoints, part); // home is an item too
            std::vector<int> commands;
            for (const QJsonValue& item : items)
                commands.push_back(item.toObject()["command"].toInt());
            // Takeoff, speed, first waypoint, camera on, ..., last waypoint, camera off, return to launch.
            QCOMPARE(commands.front(), 22);
            QCOMPARE(commands[1], 178);
            QCOMPARE(commands[2], 16);
            QCOMPARE(commands[3], 206);
            QCOMPARE(commands[commands.size() - 3], 16);
            QCOMPARE(commands[commands.size() - 2], 206);
            QCOMPARE(commands.back(), 20);
            QCOMPARE(std::count(commands.begin(), commands.end(), 206), 2);
            const QJsonArray start = items[3].toObject()["params"].toArray();
            QCOMPARE(start[0].toDouble(), 25.0);
            QCOMPARE(start[2].toDouble(), 1.0); // a first photo at once
            QCOMPARE(items[3].toObject()["frame"].toInt(), 2);
            const QJsonArray stop = items[items.size() - 2].toObject()["params"].toArray();
            QCOMPARE(stop[0].toDouble(), 0.0);
            QCOMPARE(stop[2].toDouble(), 1.0); // and a last photo there, as QGroundControl stops it
            QVERIFY(keysOf(items[3].toObject()) == keysOf(sampleCameraItem));
            // Exactly the items the limit counted: home, takeoff, speed, the camera's two and the return,
            // beside the waypoints (one speed along the whole path).
            const auto partWaypoints = std::count(commands.begin(), commands.end(), 16);
            QCOMPARE(items.size() + 1, 6 + partWaypoints);
            waypoints += partWaypoints;
        }
        // The second part begins where the first ended: one waypoint in both.
        QCOMPARE(waypoints, static_cast<qsizetype>(plan_.paths[0].waypoints.size()) + 1);

        // The same in a QGC WPL 110 file, for a rover in one file.
        settings.vehicle.type = VehicleType::Rover;
        settings.vehicle.maxWaypoints = 0;
        const std::string list = file("camera.waypoints");
        QVERIFY(writeWaypointList(context(settings), 0, list).ok());
        std::string header;
        const auto rows = tabRows(list, header);
        QCOMPARE(rows.size(), plan_.paths[0].waypoints.size() + 4);
        QCOMPARE(rows[2][3], std::string("16"));
        QCOMPARE(rows[3][3], std::string("206"));
        QCOMPARE(std::stod(rows[3][4]), 25.0);
        QCOMPARE(std::stod(rows[3][6]), 1.0);
        QCOMPARE(rows[rows.size() - 2][3], std::string("16"));
        QCOMPARE(rows.back()[3], std::string("206"));
        QCOMPARE(std::stod(rows.back()[4]), 0.0);
        QCOMPARE(std::stod(rows.back()[6]), 1.0);
        for (std::size_t i = 0; i < rows.size(); ++i)
            QCOMPARE(rows[i][0], std::to_string(i));
    }

    void waypointCsv() {
        const std::string path = file("robot1.csv");
        QVERIFY(writeWaypointCsv(context(), 1, path).ok());
        std::ifstream input(path);
        std::string line;
        std::getline(input, line);
        QCOMPARE(line, std::string("index,x,y,lon,lat,class,speed_mps,fov_m,cumulative_s"));
        std::vector<std::string> lines;
        while (std::getline(input, line))
            lines.push_back(line);
        QCOMPARE(lines.size(), plan_.paths[1].waypoints.size());
        std::vector<std::string> fields;
        std::stringstream stream(lines[2]);
        while (std::getline(stream, line, ','))
            fields.push_back(line);
        QCOMPARE(fields.size(), std::size_t{9});
        const Waypoint& waypoint = plan_.paths[1].waypoints[2];
        // Metres to three decimals, degrees to eight.
        QVERIFY(std::abs(std::stod(fields[1]) - waypoint.x) <= 6e-4);
        QVERIFY(std::abs(std::stod(fields[2]) - waypoint.y) <= 6e-4);
        QVERIFY2(fields[1].find('.') == std::string::npos || fields[1].size() - fields[1].find('.') <= 4,
                 fields[1].c_str());
        const LonLat expected = reference_.toWgs84({waypoint.x, waypoint.y}).value();
        QVERIFY(std::abs(std::stod(fields[3]) - expected.longitude) <= 6e-9);
        QVERIFY2(fields[3].size() - fields[3].find('.') <= 9, fields[3].c_str());
        QCOMPARE(std::stod(fields[5]), 6.0);
        // Two 10 m legs at 1.5 m/s, no turn price; seconds to three decimals.
        QVERIFY(std::abs(std::stod(fields[8]) - 20.0 / 1.5) <= 6e-4);
        QCOMPARE(fields[8], std::string("13.333"));
        // Every row where its x and y lie, whether the robot's mission placed the point (its turns) or the
        // CSV did (the points between them).
        for (const std::string& row : lines) {
            std::vector<double> values;
            std::stringstream columns(row);
            for (std::string field; std::getline(columns, field, ',');)
                values.push_back(field.empty() ? 0.0 : std::stod(field));
            // The millimetre the metres were rounded to moves the degrees by at most about 1e-8.
            const LonLat place = reference_.toWgs84({values[1], values[2]}).value();
            QVERIFY(std::abs(values[3] - place.longitude) <= 2e-8);
            QVERIFY(std::abs(values[4] - place.latitude) <= 2e-8);
        }
    }

    void waypointCsvWritesFloatSpeedsAsTheirDecimals() {
        // Speeds are floats; 0.3F is 0.30000001192092896 as a double, and the file must say 0.3.
        Waypoint& waypoint = plan_.paths[1].waypoints[2];
        const float kept = waypoint.speedMetresPerSecond;
        waypoint.speedMetresPerSecond = 0.3F;
        const std::string path = file("robot1-speeds.csv");
        const bool written = writeWaypointCsv(context(), 1, path).ok();
        waypoint.speedMetresPerSecond = kept;
        QVERIFY(written);
        std::ifstream input(path);
        std::string line;
        for (int skipped = 0; skipped < 3; ++skipped)
            std::getline(input, line);
        std::getline(input, line);
        std::vector<std::string> fields;
        std::stringstream stream(line);
        while (std::getline(stream, line, ','))
            fields.push_back(line);
        QCOMPARE(fields.size(), std::size_t{9});
        QCOMPARE(fields[6], std::string("0.3"));
    }

    // Mission files' numbers: rounded, fixed notation, no trailing zeros, never "-0".
    void roundedNumbers_data() {
        QTest::addColumn<double>("value");
        QTest::addColumn<int>("decimals");
        QTest::addColumn<QString>("expected");
        QTest::newRow("metres") << 322009.0365214371 << 3 << "322009.037";
        QTest::newRow("round, not 3e+05") << 300000.0 << 3 << "300000";
        QTest::newRow("degrees") << 7.400000000000001 << 8 << "7.4";
        QTest::newRow("west") << -113.193948618702 << 8 << "-113.19394862";
        QTest::newRow("a hair below zero") << -0.000000001 << 8 << "0";
        QTest::newRow("no decimals") << 1234.5 << 0 << "1235";
    }
    void roundedNumbers() {
        QFETCH(double, value);
        QFETCH(int, decimals);
        QFETCH(QString, expected);
        std::string text;
        internal::appendRounded(text, value, decimals);
        QCOMPARE(QString::fromStdString(text), expected);
    }

    void unknownRobotIsAnError() {
        Status status = writeQGroundControlPlan(context(), 5, file("robot5.plan"));
        QVERIFY(!status.ok());
        // Robot index 5 is the sixth robot: messages number robots from 1, as the files do.
        QVERIFY(status.error().find("robot 6") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(WaypointFilesTest)
#include "test_waypoint_files.moc"
