// Mission files: save -> load gives the same mission, save -> load -> save the same bytes; defaults; paths.

#include "core/model/HumanUnits.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"
#include "io/MissionInputs.hpp"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace mcpp;
using namespace mcpp::io;

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
}

Mission sampleMission() {
    Mission mission;
    mission.rasterPath = "../landcover/nlcd.tif";
    mission.band = 1;
    mission.preset = "nlcd-simplified";
    mission.classes = presetClassTable("nlcd-simplified").value();
    mission.classes.set(
        LandCoverClass{9, "Ünïcode \"quoted\", with comma", 0x0a0b0c, 0.1 + 0.2, 1.0 / 3.0, true});
    LandCoverClass forest{10, "Under trees", 0x225522, 0.5, 5.0, true};
    forest.detectionProbability = 0.35; // what a sensor sees through the canopy, for detection planners
    mission.classes.set(forest);
    mission.missingClassesAsObstacles = true;
    mission.robots = {RobotSpec{"alpha", {318819.349, 4132665.467}, ""},
                      RobotSpec{"beta", {-113.05, 37.3}, "EPSG:4326"},
                      RobotSpec{"", {1e-7, 123456789.123456789}, ""}};
    // The second robot flies its own drone; the others take the mission's vehicle.
    mission.robots[1].vehicle.type = VehicleType::Multirotor;
    mission.robots[1].vehicle.altitudeMetres = 45.5;
    mission.robots[1].vehicle.maxWaypoints = 0;
    mission.robots[1].vehicle.flightTimeSeconds = 1320.0;       // its own battery: 22 min
    mission.robots[1].vehicle.turnaroundSeconds = 90.0;         // and a quicker swap
    mission.robots[1].vehicle.cameraTriggerMetres = 40.0;       // and a camera taking photos
    mission.robots[2].batterySeconds = 1500.0;                  // its own battery, for battery planners
    mission.robots[2].charger = MapPoint{302000.5, 4154000.25}; // and its charger away from its start
    mission.events = {{120.5, 1, 0.5}, {600.0, 0, 0.0}};        // robot 1 at half speed, then robot 0 stops
    mission.planner.parameters.set("purity_tolerance", 0.05);
    mission.planner.parameters.set("blocked_threshold", 0.6);
    mission.planner.parameters.set("closed_tour", false);
    mission.planner.parameters.set("rebalance_iterations", 250);
    mission.planner.parameters.set("snap_starts_to_free_cells", true);
    mission.planner.parameters.set("turn_s", 2.5);
    mission.exports.vehicle.altitudeMetres = 12.5;
    mission.exports.vehicle.cruiseSpeedMetresPerSecond = 1.2;
    mission.exports.mergeCollinear = false;
    mission.exports.vehicle.maxWaypoints = 350;
    mission.exports.vehicle.flightTimeSeconds = 1500.0;
    mission.exports.vehicle.turnaroundSeconds = 300.0;
    mission.exports.speedTolerance = 0.25;
    mission.exports.speedChangesAtTurnsOnly = true;
    return mission;
}

// A map on which every class of the table has pixels.
LoadedRaster rasterWithEvery(const ClassTable& classes) {
    LoadedRaster raster;
    for (const LandCoverClass& landCover : classes.classes())
        raster.classPixelCounts[landCover.value] = 100;
    return raster;
}

void compareMissions(const Mission& a, const Mission& b) {
    QCOMPARE(a.version, b.version);
    QCOMPARE(a.rasterPath, b.rasterPath);
    QCOMPARE(a.band, b.band);
    QCOMPARE(a.preset, b.preset);
    QVERIFY(a.classes == b.classes);
    QCOMPARE(a.missingClassesAsObstacles, b.missingClassesAsObstacles);
    QVERIFY(a.robots == b.robots);
    QCOMPARE(a.planner.planner, b.planner.planner);
    QVERIFY(a.planner.parameters == b.planner.parameters);
    QVERIFY(a.exports == b.exports);
}

} // namespace

class MissionFilesTest : public QObject {
    Q_OBJECT

  private slots:
    void saveLoadSaveIsByteIdentical() {
        QTemporaryDir folder;
        const std::string first = folder.filePath("mission.json").toStdString();
        const std::string second = folder.filePath("again.json").toStdString();
        const Mission mission = sampleMission();
        QVERIFY(saveMission(mission, first).ok());
        auto loaded = loadMission(first);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        compareMissions(loaded.value(), mission);
        QVERIFY(saveMission(loaded.value(), second).ok());
        QCOMPARE(readBytes(second), readBytes(first));
        QCOMPARE(missionToJson(loaded.value()), readBytes(first));
    }

    // A class row without a colour is marked so the preset's or the raster's colour can take its place,
    // and is written back without one.
    void classRowsWithoutColourAreMarked() {
        const auto loaded = parseMission(
            R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                "classes": {"table": [{"value": 1, "name": "Grass", "speed_mps": 1, "fov_m": 10},
                                      {"value": 2, "name": "Wood", "color": "#336633", "speed_mps": 1,
                                       "fov_m": 10}]},
                "robots": [{"name": "one", "start": [1, 1]}]})",
            "mission.json");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        QCOMPARE(loaded.value().classesWithoutColour, (std::set<std::int32_t>{1}));
        QCOMPARE(loaded.value().classes.find(2)->colorRgb, 0x336633U);
        // Written back as it was read: the row still gives no colour.
        const auto again = parseMission(missionToJson(loaded.value()), "again.json");
        QVERIFY2(again.ok(), again.ok() ? "" : again.error().c_str());
        QVERIFY(again.value() == loaded.value());
        // A table whose colours were filled in (the window's) gives every row one.
        Mission coloured = loaded.value();
        coloured.classesWithoutColour.clear();
        const auto filled = parseMission(missionToJson(coloured), "filled.json");
        QVERIFY(filled.ok() && filled.value().classesWithoutColour.empty());
    }

    // Beside a preset, a class row may give only what it changes: the rest is the preset's row for its
    // value. A value the preset lacks, or a row without a preset, must give its speed and field of view,
    // and the message says where they could come from.
    void aClassRowBesideAPresetTakesWhatItLeavesOut() {
        const ClassTable preset = presetClassTable("esa-worldcover").value();
        const LandCoverClass* grass = preset.find(30);
        QVERIFY(grass != nullptr && grass->speedMetresPerSecond != 0.5);
        const auto missionWith = [](const std::string& classes) {
            return parseMission(R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                "classes": )" + classes +
                                    R"(, "robots": [{"name": "one", "start": [1, 1]}]})",
                                "mission.json");
        };
        const auto loaded =
            missionWith(R"({"preset": "esa-worldcover", "table": [{"value": 30, "speed_mps": 0.5}]})");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        const LandCoverClass* row = loaded.value().classes.find(30);
        QVERIFY(row != nullptr);
        QCOMPARE(row->speedMetresPerSecond, 0.5);
        QCOMPARE(row->name, grass->name);
        QCOMPARE(row->fieldOfViewMetres, grass->fieldOfViewMetres);
        QCOMPARE(row->passable, grass->passable);

        // A speed given to a class the preset makes an obstacle makes it passable.
        const LandCoverClass* water = preset.find(80);
        QVERIFY(water != nullptr && !water->passable);
        const auto crossed =
            missionWith(R"({"preset": "esa-worldcover", "table": [{"value": 80, "speed_mps": 1}]})");
        QVERIFY2(crossed.ok(), crossed.ok() ? "" : crossed.error().c_str());
        QVERIFY(crossed.value().classes.find(80)->passable);
        QCOMPARE(crossed.value().classes.find(80)->fieldOfViewMetres, water->fieldOfViewMetres);
        // Ticking passable alone leaves the preset's speed of 0: refused, naming the speed to give.
        const auto stillAWall =
            missionWith(R"({"preset": "esa-worldcover", "table": [{"value": 80, "passable": true}]})");
        QVERIFY(!stillAWall.ok());
        QCOMPARE(
            stillAWall.error(),
            std::string("mission.json: classes.table[0].passable: true, but the preset esa-worldcover gives "
                        "class 80 (Permanent water bodies) a speed of 0 m/s, which keeps it an obstacle: "
                        "give speed_mps too"));

        const auto unknown =
            missionWith(R"({"preset": "esa-worldcover", "table": [{"value": 31, "speed_mps": 0.5}]})");
        QVERIFY(!unknown.ok());
        QCOMPARE(unknown.error(), std::string("mission.json: classes.table[0].fov_m: missing, and the preset "
                                              "esa-worldcover has no class 31 to take it from"));
        const auto noPreset = missionWith(R"({"table": [{"value": 30, "fov_m": 10}]})");
        QVERIFY(!noPreset.ok());
        QVERIFY2(noPreset.error().find("classes.table[0].speed_mps: missing: a class row gives it unless "
                                       "classes.preset names a preset") != std::string::npos,
                 noPreset.error().c_str());
    }

    void fileIsVersionedJsonInAFixedOrder() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("mission.json").toStdString();
        QVERIFY(saveMission(sampleMission(), path).ok());
        const std::string text = readBytes(path);
        QVERIFY(text.rfind("{\n  \"format\": \"mcpp-mission\",\n  \"version\": 2,\n", 0) == 0);
        QVERIFY(text.find("\"raster\"") < text.find("\"classes\""));
        QVERIFY(text.find("\"robots\"") < text.find("\"planner\""));
        const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(text));
        QVERIFY(document.isObject());
        const QJsonObject root = document.object();
        QCOMPARE(root["format"].toString(), QString("mcpp-mission"));
        QCOMPARE(root["robots"].toArray().size(), 3);
        QCOMPARE(root["robots"].toArray()[1].toObject()["start_crs"].toString(), QString("EPSG:4326"));
        const QJsonArray table = root["classes"].toObject()["table"].toArray();
        QCOMPARE(table.size(), 10);
        QCOMPARE(table[9].toObject()["detection_probability"].toDouble(), 0.35);
        QVERIFY(!table[8].toObject().contains("detection_probability"));
        QCOMPARE(root["planner"].toObject()["name"].toString(), QString("mcpp-mlct"));
        const QJsonObject parameters = root["planner"].toObject()["parameters"].toObject();
        QCOMPARE(parameters["purity_tolerance"].toDouble(), 0.05);
        QCOMPARE(parameters["rebalance_iterations"].toInt(), 250);
        QCOMPARE(parameters["closed_tour"].toBool(), false);
        QCOMPARE(parameters["turn_s"].toDouble(), 2.5);
        // Shortest round-trip numbers, not fixed decimals.
        QVERIFY(text.find("0.30000000000000004") != std::string::npos);
        QVERIFY(text.find("\"altitude_m\": 12.5") != std::string::npos);
        // A robot's own vehicle values only; the others take the mission's.
        const QJsonObject beta = root["robots"].toArray()[1].toObject();
        QCOMPARE(beta["vehicle"].toString(), QString("multirotor"));
        QCOMPARE(beta["altitude_m"].toDouble(), 45.5);
        QCOMPARE(beta["max_waypoints"].toInt(), 0);
        QVERIFY(!beta.contains("cruise_speed_mps"));
        QVERIFY(!root["robots"].toArray()[0].toObject().contains("vehicle"));
        const QJsonObject exports = root["exports"].toObject();
        QCOMPARE(exports["vehicle"].toString(), QString("rover"));
        QCOMPARE(exports["max_waypoints"].toInt(), 350);
        QCOMPARE(exports["flight_time_s"].toDouble(), 1500.0);
        QCOMPARE(beta["flight_time_s"].toDouble(), 1320.0);
        QCOMPARE(exports["turnaround_s"].toDouble(), 300.0);
        QCOMPARE(beta["turnaround_s"].toDouble(), 90.0);
        QCOMPARE(beta["camera_trigger_m"].toDouble(), 40.0);
        QCOMPARE(exports["camera_trigger_m"].toDouble(), 0.0);
        QVERIFY(!root["robots"].toArray()[0].toObject().contains("camera_trigger_m"));
        QCOMPARE(exports["speed_tolerance"].toDouble(), 0.25);
        QCOMPARE(exports["speed_changes_at_turns_only"].toBool(), true);
        const std::vector<VehicleSettings> vehicles = robotVehicles(sampleMission());
        QCOMPARE(vehicles[0].maxWaypoints, 350);
        QCOMPARE(vehicles[0].altitudeMetres, 12.5);
        QCOMPARE(vehicles[1].maxWaypoints, 0);
        QCOMPARE(vehicles[0].flightTimeSeconds, 1500.0);
        QCOMPARE(vehicles[1].flightTimeSeconds, 1320.0);
        QCOMPARE(vehicles[0].turnaroundSeconds, 300.0);
        QCOMPARE(vehicles[1].turnaroundSeconds, 90.0);
        QCOMPARE(vehicles[0].cameraTriggerMetres, 0.0);
        QCOMPARE(vehicles[1].cameraTriggerMetres, 40.0);
        QCOMPARE(vehicles[1].altitudeMetres, 45.5);
        QCOMPARE(vehicles[1].cruiseSpeedMetresPerSecond, 1.2);
        QVERIFY(vehicles[1].type == VehicleType::Multirotor);
        QCOMPARE(root["robots"].toArray()[2].toObject()["battery_s"].toDouble(), 1500.0);
        QVERIFY(!beta.contains("battery_s"));
        const QJsonArray charger = root["robots"].toArray()[2].toObject()["charger"].toArray();
        QCOMPARE(charger.size(), 2);
        QCOMPARE(charger[0].toDouble(), 302000.5);
        QCOMPARE(charger[1].toDouble(), 4154000.25);
        QVERIFY(!beta.contains("charger"));
        // Battery planners fly each robot on its own battery_s, else on what its vehicle's flight time
        // leaves after the climb to its altitude and the descent (the mission's rover: all 1500 s of it).
        const std::vector<double> batteries = robotBatteries(sampleMission());
        QCOMPARE(batteries.size(), std::size_t{3});
        QCOMPARE(batteries[0], 1500.0);
        QVERIFY(std::abs(batteries[1] - (1320.0 - 45.5 / 2.5 - 45.5 / 1.5)) < 1e-9);
        QCOMPARE(batteries[2], 1500.0);
        Mission withoutFlightTimes = sampleMission();
        withoutFlightTimes.exports.vehicle.flightTimeSeconds = 0.0;
        withoutFlightTimes.robots[1].vehicle.flightTimeSeconds.reset();
        QCOMPARE(robotBatteries(withoutFlightTimes), (std::vector<double>{0.0, 0.0, 1500.0}));
        const QJsonArray events = root["events"].toArray();
        QCOMPARE(events.size(), 2);
        QCOMPARE(events[0].toObject()["time_s"].toDouble(), 120.5);
        QCOMPARE(events[0].toObject()["robot"].toInt(), 1);
        QCOMPARE(events[1].toObject()["speed_factor"].toDouble(), 0.0);
    }

    // Drones at a preset's fields of view (a ground robot's) are told to scale them; scaled, or beside a
    // rover, nothing is said.
    void aircraftAtAPresetsFieldsOfViewAreWarned() {
        Mission mission = sampleMission();
        mission.exports.vehicle.type = VehicleType::Rover;
        for (RobotSpec& robot : mission.robots)
            robot.vehicle.type.reset();
        PlanningProblem problem;
        problem.classes = presetClassTable("esa-worldcover").value();
        const auto warned = [&](const PlanningProblem& given) {
            PlanningProblem planned = given;
            applyRobotSettings(mission, rasterWithEvery(planned.classes), planned);
            const auto note =
                std::find_if(planned.notes.begin(), planned.notes.end(),
                             [](const PlanIssue& issue) { return issue.code == "aircraft-at-ground-fov"; });
            return note == planned.notes.end() ? std::string() : note->message;
        };
        QVERIFY(warned(problem).empty()); // rovers: the preset's fields of view are theirs
        mission.robots[1].vehicle.type = VehicleType::Multirotor;
        QVERIFY(warned(problem).empty()); // a drone beside rovers: the table is the rovers' too
        mission.exports.vehicle.type = VehicleType::Multirotor;
        const std::string message = warned(problem);
        QVERIFY2(message.find("which are preset esa-worldcover's, a ground robot's (the smallest 5 m") !=
                     std::string::npos,
                 message.c_str());
        QVERIFY2(message.find("--fov-scale") != std::string::npos, message.c_str());
        std::vector<LandCoverClass> scaled = problem.classes.classes();
        for (LandCoverClass& landCover : scaled)
            landCover.fieldOfViewMetres *= 4.0;
        PlanningProblem camera = problem;
        camera.classes = ClassTable(std::move(scaled));
        QVERIFY(warned(camera).empty());
    }

    // A preset of another product than the one the raster names is warned of; the raster's own preset, or
    // none, is not.
    void aPresetOfAnotherProductIsWarnedOf() {
        Mission mission = sampleMission();
        LoadedRaster raster = rasterWithEvery(presetClassTable("canada-landcover").value());
        raster.path = "/data/nrcan_landcover_2015.tif"; // its file name names the product
        const auto warning = [&](const std::string& preset) {
            mission.preset = preset;
            PlanningProblem problem;
            problem.classes = presetClassTable("canada-landcover").value();
            applyRobotSettings(mission, raster, problem);
            const auto note =
                std::find_if(problem.notes.begin(), problem.notes.end(), [](const PlanIssue& issue) {
                    return issue.code == "preset-of-another-product";
                });
            return note == problem.notes.end() ? std::string() : note->message;
        };
        const std::string message = warning("corine-grid");
        QVERIFY2(message.find("by its file name, yet the classes are preset corine-grid's") !=
                         std::string::npos &&
                     message.find("Choose the preset canada-landcover") != std::string::npos,
                 message.c_str());
        QVERIFY(warning("canada-landcover").empty());
        QVERIFY(warning("").empty());
        const ClassTable ownRows = mission.classes;
        mission.classes = presetClassTable("canada-landcover").value(); // rows of its own for every class
        QVERIFY(warning("corine-grid").empty());
        mission.classes =
            presetClassTable("corine-grid").value(); // the preset's rows, as the window holds them
        QVERIFY(!warning("corine-grid").empty());
        mission.classes = ownRows;
        raster.path = "/data/map.tif"; // nothing names it: its codes alone do not make it Canada's
        QVERIFY(warning("corine-grid").empty());
    }

    // classes.fov_m is written only when set, read back as written, and a footprint of no size is refused
    // by its key.
    void aFootprintOverEveryClassIsKeptInTheFile() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("drones.json").toStdString();
        Mission mission = sampleMission();
        // The classes object's own key, not the table rows' fov_m: written only when set.
        const auto classesObject = [&path] {
            return QJsonDocument::fromJson(QByteArray::fromStdString(readBytes(path)))
                .object()["classes"]
                .toObject();
        };
        QVERIFY(saveMission(mission, path).ok());
        QVERIFY(!classesObject().contains("fov_m"));
        mission.fieldOfViewMetres = 60.0;
        QVERIFY(saveMission(mission, path).ok());
        QCOMPARE(classesObject()["fov_m"].toDouble(), 60.0);
        auto loaded = loadMission(path);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        QCOMPARE(loaded.value().fieldOfViewMetres, std::optional<double>(60.0));
        QVERIFY(loaded.value() == mission);
        const std::string bad = folder.filePath("bad.json").toStdString();
        std::string text = readBytes(path);
        const std::size_t at = text.find("\"fov_m\": 60");
        QVERIFY(at != std::string::npos);
        text.replace(at, 11, "\"fov_m\": 0");
        writeText(bad, text);
        const auto refused = loadMission(bad);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().find("classes.fov_m: must be a field of view of more than 0 m") !=
                     std::string::npos,
                 refused.error().c_str());
    }

    // Photos farther apart than the footprint the passes are spaced by leave ground unphotographed along the
    // path: a warning names the distance and what gives 20 % overlap; within it, none.
    void photosFartherThanTheFootprintAreWarnedOf() {
        Mission mission = sampleMission();
        PlanningProblem problem;
        problem.classes = ClassTable({{1, "grass", 0x00ff00, 1.5, 60.0, true},
                                      {2, "forest", 0x008000, 0.5, 80.0, true},
                                      {3, "water", 0x0000ff, 0.0, 10.0, false}});
        const auto photoNotes = [&] {
            PlanningProblem planned = problem;
            applyRobotSettings(mission, rasterWithEvery(planned.classes), planned);
            std::vector<std::string> found;
            for (const PlanIssue& note : planned.notes)
                if (note.code == "photos-farther-than-footprint")
                    found.push_back(note.message);
            return found;
        };
        mission.exports.vehicle.cameraTriggerMetres = 48.0;
        for (RobotSpec& robot : mission.robots)
            robot.vehicle.cameraTriggerMetres.reset();
        QVERIFY(photoNotes().empty());
        mission.robots[1].vehicle.cameraTriggerMetres = 75.0; // beyond the grass's 60 m, within the forest's
        const std::vector<std::string> notes = photoNotes();
        QCOMPARE(notes.size(), std::size_t{1});
        QVERIFY2(notes[0].find("photos farther apart than the 60 m field of view") != std::string::npos &&
                     notes[0].find("up to every 75 m") != std::string::npos &&
                     notes[0].find("a photo every 48 m") != std::string::npos,
                 notes[0].c_str());
    }

    // A start read in its start_crs and written back reads as given, save after save, though the way into
    // the planning frame and back is a millimetre off (WGS84 to Swiss LV95 shifts the datum); without a
    // start_crs, or with one the points cannot go into, it is written in the planning CRS's units.
    void startsAreWrittenBackAsGiven() {
        const auto swiss = GeoReference::fromDefinition("EPSG:2056");
        QVERIFY2(swiss.ok(), swiss.ok() ? "" : swiss.error().c_str());
        const GeoReference& georeference = swiss.value();
        RobotSpec robot{"drone", {6.6183, 46.5708}, "EPSG:4326"};
        robot.charger = MapPoint{6.61, 46.57};
        for (int save = 0; save < 5; ++save) {
            RobotSpec held = robot; // as the window holds it: in the planning frame
            held.start = georeference.fromCrs(robot.startCrs, robot.start).value();
            held.charger = georeference.fromCrs(robot.startCrs, *robot.charger).value();
            robot = robotAsWritten(held, georeference);
            QCOMPARE(robot.startCrs, std::string("EPSG:4326"));
            QCOMPARE(robot.start.x, 6.6183);
            QCOMPARE(robot.start.y, 46.5708);
            QCOMPARE(robot.charger->x, 6.61);
            QCOMPARE(robot.charger->y, 46.57);
        }
        // Moved a metre east in the planning frame: written with the decimals that hold it to 5 mm.
        RobotSpec moved = robot;
        moved.start = georeference.fromCrs("EPSG:4326", robot.start).value();
        moved.start.x += 1.0;
        moved.charger.reset();
        const RobotSpec written = robotAsWritten(moved, georeference);
        const MapPoint back = georeference.fromCrs("EPSG:4326", written.start).value();
        QVERIFY(std::hypot(back.x - moved.start.x, back.y - moved.start.y) <= 0.005);
        QVERIFY(written.start.x != 6.6183);
        // In the planning CRS's units: the fewest decimals within 5 mm (3.5 mm off here), not the float's
        // tail.
        RobotSpec own{"rover", {2533000.123456789, 1152000.5}, ""};
        const RobotSpec ownWritten = robotAsWritten(own, georeference);
        QVERIFY(ownWritten.startCrs.empty());
        QCOMPARE(ownWritten.start.x, 2533000.12);
        QCOMPARE(ownWritten.start.y, 1152000.5);
        // A CRS the points cannot go into: written in the planning CRS's units, without it.
        RobotSpec unknown{"lost", {2533000.0, 1152000.0}, "EPSG:999999"};
        const RobotSpec unknownWritten = robotAsWritten(unknown, georeference);
        QVERIFY(unknownWritten.startCrs.empty());
        QCOMPARE(unknownWritten.start.x, 2533000.0);
    }

    // The passes are spaced by the smallest field of view of the classes on the map: a class of the table
    // that the map lacks sets off neither the photo warning nor the preset's, and its FOV is not named.
    void onlyClassesOnTheMapSpaceThePasses() {
        Mission mission = sampleMission();
        mission.exports.vehicle.type = VehicleType::Multirotor;
        mission.exports.vehicle.cameraTriggerMetres = 75.0;
        for (RobotSpec& robot : mission.robots) {
            robot.vehicle.type.reset();
            robot.vehicle.cameraTriggerMetres.reset();
        }
        PlanningProblem problem;
        problem.classes = ClassTable({{1, "grass", 0x00ff00, 1.5, 60.0, true},
                                      {2, "forest", 0x008000, 0.5, 80.0, true},
                                      {3, "water", 0x0000ff, 0.0, 10.0, false}});
        const auto codesOn = [&](const LoadedRaster& raster) {
            PlanningProblem planned = problem;
            applyRobotSettings(mission, raster, planned);
            std::vector<std::string> codes;
            for (const PlanIssue& note : planned.notes)
                codes.push_back(note.code);
            return codes;
        };
        const auto has = [](const std::vector<std::string>& codes, const std::string& code) {
            return std::find(codes.begin(), codes.end(), code) != codes.end();
        };
        LoadedRaster forestAndWater;
        forestAndWater.classPixelCounts = {{1, 0}, {2, 500}, {3, 40}}; // grass counted but with no pixel
        QVERIFY(has(codesOn(rasterWithEvery(problem.classes)), "photos-farther-than-footprint"));
        QVERIFY(!has(codesOn(forestAndWater), "photos-farther-than-footprint"));

        // At the preset's fields of view, the smallest named is the smallest on the map.
        problem.classes = presetClassTable("esa-worldcover").value();
        mission.exports.vehicle.cameraTriggerMetres = 0.0;
        LoadedRaster grassland;
        grassland.classPixelCounts = {{30, 1000}, {80, 200}}; // grassland and water
        PlanningProblem planned = problem;
        applyRobotSettings(mission, grassland, planned);
        const auto note =
            std::find_if(planned.notes.begin(), planned.notes.end(),
                         [](const PlanIssue& issue) { return issue.code == "aircraft-at-ground-fov"; });
        QVERIFY(note != planned.notes.end());
        const double grassFieldOfView = problem.classes.find(30)->fieldOfViewMetres;
        QVERIFY2(note->message.find("(the smallest " + formatQuantity(grassFieldOfView, 4) + " m") !=
                     std::string::npos,
                 note->message.c_str());
        LoadedRaster waterOnly;
        waterOnly.classPixelCounts = {{80, 1000}}; // nothing to cover: no footprint to scale
        PlanningProblem nothing = problem;
        applyRobotSettings(mission, waterOnly, nothing);
        QVERIFY(std::none_of(nothing.notes.begin(), nothing.notes.end(),
                             [](const PlanIssue& issue) { return issue.code == "aircraft-at-ground-fov"; }));
    }

    // A cruise speed the whole fleet shares is what the plan uses over every passable class; speeds that
    // differ leave the class table's and say why.
    void fleetCruiseSpeedIsPlannedWith() {
        Mission mission = sampleMission();
        for (RobotSpec& robot : mission.robots)
            robot.vehicle.cruiseSpeedMetresPerSecond.reset();
        mission.exports.vehicle.cruiseSpeedMetresPerSecond = 0.0;
        mission.robots[1].vehicle.type.reset();                // rovers all, until the end
        mission.robots[1].vehicle.cameraTriggerMetres.reset(); // no photos to space
        PlanningProblem problem;
        problem.classes = ClassTable({{1, "grass", 0x00ff00, 1.5, 10.0, true},
                                      {2, "forest", 0x008000, 0.5, 5.0, true},
                                      {3, "water", 0x0000ff, 0.0, 10.0, false}});
        const ClassTable landCover = problem.classes;
        PlanningProblem unchanged = problem;
        applyRobotSettings(mission, rasterWithEvery(unchanged.classes), unchanged);
        QVERIFY(unchanged.classes == landCover);
        QVERIFY(unchanged.notes.empty());
        QCOMPARE(fleetCruiseSpeed(mission), 0.0);

        mission.exports.vehicle.cruiseSpeedMetresPerSecond = 8.5;
        QCOMPARE(fleetCruiseSpeed(mission), 8.5);
        PlanningProblem flown = problem;
        applyRobotSettings(mission, rasterWithEvery(flown.classes), flown);
        QCOMPARE(flown.classes.find(1)->speedMetresPerSecond, 8.5);
        QCOMPARE(flown.classes.find(2)->speedMetresPerSecond, 8.5);
        QCOMPARE(flown.classes.find(2)->fieldOfViewMetres, 5.0); // what it sees still follows the land cover
        QVERIFY(!flown.classes.find(3)->isTraversable());
        QCOMPARE(flown.notes.size(), std::size_t{1});
        QCOMPARE(flown.notes[0].code, std::string("cruise-speed"));
        QVERIFY(flown.notes[0].message.find("8.5 m/s") != std::string::npos);

        mission.robots[1].vehicle.cruiseSpeedMetresPerSecond = 6.0;
        QCOMPARE(fleetCruiseSpeed(mission), 0.0);
        PlanningProblem mixed = problem;
        applyRobotSettings(mission, rasterWithEvery(mixed.classes), mixed);
        QVERIFY(mixed.classes == landCover);
        QCOMPARE(mixed.robotSpeeds, (std::vector<double>{8.5, 6.0, 8.5})); // each robot drives at its own
        QCOMPARE(mixed.notes.size(), std::size_t{1});
        QCOMPARE(mixed.notes[0].code, std::string("cruise-speeds-differ"));
        QVERIFY(mixed.notes[0].severity == IssueSeverity::Information);
        QVERIFY2(mixed.notes[0].message.find("beta 6 m/s") != std::string::npos,
                 mixed.notes[0].message.c_str());

        // Beside robots of speeds of their own, an aircraft left without one is named.
        Mission crawling = mission;
        crawling.exports.vehicle.type = VehicleType::Rover;
        crawling.exports.vehicle.cruiseSpeedMetresPerSecond = 0.0;
        crawling.robots[0].vehicle.cruiseSpeedMetresPerSecond = 3.0;
        crawling.robots[1].vehicle.type = VehicleType::Multirotor;
        crawling.robots[1].vehicle.cruiseSpeedMetresPerSecond.reset();
        crawling.robots[2].vehicle.type = VehicleType::Rover;
        crawling.robots[2].vehicle.cruiseSpeedMetresPerSecond.reset();
        PlanningProblem slow = problem;
        applyRobotSettings(crawling, rasterWithEvery(slow.classes), slow);
        QCOMPARE(slow.notes.size(), std::size_t{3});
        QCOMPARE(slow.notes[2].code, std::string("altitude-above-home")); // an aircraft among them
        QCOMPARE(slow.notes[1].code, std::string("aircraft-at-ground-speeds"));
        QVERIFY(slow.notes[1].severity == IssueSeverity::Warning);
        QVERIFY2(slow.notes[1].message.rfind("beta is an aircraft without a cruise speed", 0) == 0,
                 slow.notes[1].message.c_str());
        crawling.robots[1].vehicle.type = VehicleType::Rover; // rovers at the land cover's speeds are meant
        PlanningProblem rovers = problem;
        applyRobotSettings(crawling, rasterWithEvery(rovers.classes), rovers);
        QCOMPARE(rovers.notes.size(), std::size_t{1}); // rovers: no word of altitudes

        // A drone without a cruise speed flies at the table's speeds: said, since presets give a ground
        // robot's.
        for (RobotSpec& robot : mission.robots)
            robot.vehicle.cruiseSpeedMetresPerSecond.reset();
        mission.exports.vehicle.cruiseSpeedMetresPerSecond = 0.0;
        mission.robots[1].vehicle.type = VehicleType::Multirotor;
        PlanningProblem aircraft = problem;
        applyRobotSettings(mission, rasterWithEvery(aircraft.classes), aircraft);
        QVERIFY(aircraft.classes == landCover);
        QCOMPARE(aircraft.notes.size(), std::size_t{2});
        QCOMPARE(aircraft.notes[0].code, std::string("aircraft-at-ground-speeds"));
        // The map holds no heights: said once, as a note, that altitudes are above home.
        QCOMPARE(aircraft.notes[1].code, std::string("altitude-above-home"));
        QVERIFY(aircraft.notes[1].severity == IssueSeverity::Information);
        QVERIFY2(aircraft.notes[1].message.find("where the land rises above home they fly that much lower") !=
                     std::string::npos,
                 aircraft.notes[1].message.c_str());

        // Aircraft at the height of home, or above what drones may fly without a permit, are named; a rover's
        // altitude means nothing.
        mission.exports.vehicle.cruiseSpeedMetresPerSecond = 8.0;
        mission.robots[0].vehicle.altitudeMetres = 0.0;   // a rover
        mission.robots[1].vehicle.altitudeMetres = 150.0; // a multirotor
        mission.robots[1].name = "beta";
        PlanningProblem altitudes = problem;
        applyRobotSettings(mission, rasterWithEvery(altitudes.classes), altitudes);
        QCOMPARE(altitudes.notes.size(), std::size_t{3});
        QCOMPARE(altitudes.notes[1].code, std::string("altitude-above-120m"));
        QVERIFY2(altitudes.notes[1].message.find("(beta 150 m)") != std::string::npos,
                 altitudes.notes[1].message.c_str());
        QVERIFY2(altitudes.notes[1].message.find("higher than 120 m (400 ft) above home") !=
                     std::string::npos,
                 altitudes.notes[1].message.c_str());
        mission.robots[1].vehicle.altitudeMetres = 2.0;
        PlanningProblem low = problem;
        applyRobotSettings(mission, rasterWithEvery(low.classes), low);
        const PlanIssue& tooLow = low.notes[low.notes.size() - 2];
        QCOMPARE(tooLow.code, std::string("altitude-too-low"));
        QVERIFY2(tooLow.message.find("(beta 2 m)") != std::string::npos, tooLow.message.c_str());
        QVERIFY2(tooLow.message.find("lower than 5 m above home") != std::string::npos,
                 tooLow.message.c_str());

        // A cruise speed beyond what such a vehicle works at, likely km/h given as m/s, is warned of with
        // the metres per second it would be; up to that speed, nothing is said.
        mission.robots[1].vehicle.altitudeMetres = 60.0;
        mission.robots[1].vehicle.type = VehicleType::FixedWing;
        mission.robots[1].vehicle.cruiseSpeedMetresPerSecond = 60.0;
        const auto cruiseWarning = [&] {
            PlanningProblem fast = problem;
            applyRobotSettings(mission, rasterWithEvery(fast.classes), fast);
            for (const PlanIssue& note : fast.notes)
                if (note.code == "implausible-cruise-speed")
                    return note.message;
            return std::string();
        };
        QCOMPARE(cruiseWarning(), std::string());
        mission.robots[1].vehicle.cruiseSpeedMetresPerSecond = 200.0;
        QCOMPARE(
            cruiseWarning(),
            std::string("beta cruises at 200 m/s (720 km/h), faster than a fixed-wing works at (up to about "
                        "60 m/s): cruise speeds are in metres per second (55.56 m/s is 200 km/h); the "
                        "turns of a fast vehicle take long, and its times mean little"));
    }

    // A planner that flies on batteries is told each robot's battery: from its vehicle's flight time less
    // the climb and descent, its own battery_s, or the planner's; a note says which, so that the vehicle's
    // flight time and the planner's battery_s do not part unseen. Other planners get no note.
    void batteryPlannersFlyOnFlightTimes() {
        Mission mission = sampleMission();
        mission.robots[0].vehicle.flightTimeSeconds = 0.0; // a rover without a limit
        mission.exports.vehicle.flightTimeSeconds = 0.0;
        mission.planner = defaultPlannerChoice("wavefront-battery");
        mission.planner.parameters.set("battery_s", 900.0);
        PlanningProblem problem;
        applyRobotSettings(mission, rasterWithEvery(problem.classes), problem);
        const double beta = 1320.0 - 45.5 / 2.5 - 45.5 / 1.5;
        QCOMPARE(problem.batterySeconds, (std::vector<double>{0.0, beta, 1500.0}));
        const auto note =
            std::find_if(problem.notes.begin(), problem.notes.end(),
                         [](const PlanIssue& issue) { return issue.code == "batteries-from-flight-times"; });
        QVERIFY(note != problem.notes.end());
        QVERIFY(note->severity == IssueSeverity::Information);
        QCOMPARE(
            note->message,
            "sorties are planned on each vehicle's flight time, an aircraft's less its climb and descent: " +
                formatDuration(beta) +
                " for beta; Robot 3 on its own battery_s; alpha, without a flight time, on "
                "the planner's battery_s (15 min)");

        // Beta, an aircraft, spends longer in the field than on its path: the planner is given its measure.
        QVERIFY(static_cast<bool>(problem.fieldSeconds));
        // And what each robot's flights allow, for the bound in the field: beta's 22 min flights, each
        // with its climb to 45.5 m and its descent.
        QCOMPARE(problem.robotFlights.size(), mission.robots.size());
        QCOMPARE(problem.robotFlights[1].flightSeconds, 1320.0);
        QCOMPARE(problem.robotFlights[1].climbAndDescentSeconds, 45.5 / 2.5 + 45.5 / 1.5);
        QVERIFY(problem.robotFlights[1].splitsPaths());
        QCOMPARE(problem.robotFlights[1].turnaroundSeconds, 90.0);
        QVERIFY(!problem.robotFlights[0].splitsPaths());    // alpha flies no limit
        QCOMPARE(problem.robotFlights[1].fastestPace, 1.0); // at the fleet's cruise speed, as planned
        // Beta flies out to its work and back at its cruise speed; alpha's trips are not counted.
        QCOMPARE(problem.robotFlights[1].tripMetresPerSecond, 1.2);
        QVERIFY(problem.robotFlights[1].makesTrips());
        QVERIFY(!problem.robotFlights[0].makesTrips());
        // At the land cover's speeds, commanded rounded and held within the 25 % tolerance, a cell may be
        // flown faster than planned: the bound counts its flights at the fastest pace they can take.
        Mission landSpeeds = mission;
        landSpeeds.exports.vehicle.cruiseSpeedMetresPerSecond = 0.0;
        landSpeeds.exports.speedChangesAtTurnsOnly = false;
        PlanningProblem atLandSpeeds;
        applyRobotSettings(landSpeeds, rasterWithEvery(atLandSpeeds.classes), atLandSpeeds);
        QCOMPARE(atLandSpeeds.robotFlights[1].fastestPace, 0.75 / 1.05);
        QVERIFY(!atLandSpeeds.robotFlights[1].makesTrips()); // how fast it flies out is not known
        // Speeds changed only at turns are each leg's slowest, rounded down: never faster than planned.
        landSpeeds.exports.speedChangesAtTurnsOnly = true;
        PlanningProblem atTurns;
        applyRobotSettings(landSpeeds, rasterWithEvery(atTurns.classes), atTurns);
        QCOMPARE(atTurns.robotFlights[1].fastestPace, 1.0);
        Mission rovers = mission;
        for (RobotSpec& robot : rovers.robots)
            robot.vehicle.type = VehicleType::Rover;
        rovers.exports.vehicle.type = VehicleType::Rover;
        rovers.exports.vehicle.turnaroundSeconds = 0.0;
        for (RobotSpec& robot : rovers.robots)
            robot.vehicle.turnaroundSeconds = 0.0;
        PlanningProblem onTheGround;
        applyRobotSettings(rovers, rasterWithEvery(onTheGround.classes), onTheGround);
        QVERIFY(!onTheGround.fieldSeconds); // their split missions end with their paths
        QVERIFY(onTheGround.robotFlights.empty());

        mission.planner = defaultPlannerChoice("mcpp-mlct");
        PlanningProblem other;
        applyRobotSettings(mission, rasterWithEvery(other.classes), other);
        QVERIFY(std::none_of(other.notes.begin(), other.notes.end(), [](const PlanIssue& issue) {
            return issue.code == "batteries-from-flight-times";
        }));
    }

    void minimalMissionGetsDefaults() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("minimal.json").toStdString();
        writeText(path, R"({"format": "mcpp-mission", "version": 1, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}]})");
        auto loaded = loadMission(path);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        const Mission& mission = loaded.value();
        QCOMPARE(mission.band, 1);
        QVERIFY(mission.classes.empty());
        QVERIFY(mission.preset.empty());
        QCOMPARE(mission.robots.size(), std::size_t{1});
        QCOMPARE(mission.robots[0].start, (MapPoint{10, 20}));
        const PlannerChoice defaults = defaultPlannerChoice();
        QCOMPARE(mission.planner.planner, defaults.planner);
        QCOMPARE(mission.planner.parameters.real("blocked_threshold"), 0.5);
        QVERIFY(mission.planner.parameters == defaults.parameters);
        QCOMPARE(mission.exports.vehicle.altitudeMetres, ExportSettings{}.vehicle.altitudeMetres);
        // Saving fills in every key; that file reads back to the same mission and writes the same bytes.
        const std::string full = folder.filePath("full.json").toStdString();
        QVERIFY(saveMission(mission, full).ok());
        auto reloaded = loadMission(full);
        QVERIFY(reloaded.ok());
        compareMissions(reloaded.value(), mission);
        QCOMPARE(missionToJson(reloaded.value()), readBytes(full));
        // The automatic turn time is saved as its word and read back as automatic, in any case.
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}],
                            "planner": {"name": "mcpp-mlct", "parameters": {"turn_s": "Auto"}}})");
        auto capitalised = loadMission(path);
        QVERIFY2(capitalised.ok(), capitalised.ok() ? "" : capitalised.error().c_str());
        QVERIFY(TurnTimeModel::from(capitalised.value().planner.parameters).fixedSecondsPer90Degrees < 0.0);
        QVERIFY(readBytes(full).find("\"turn_s\": \"auto\"") != std::string::npos);
        QVERIFY(TurnTimeModel::from(reloaded.value().planner.parameters).fixedSecondsPer90Degrees < 0.0);
    }

    // A flight too short for the climb names the robots that have it, the whole fleet as one when all share
    // it, and robots whose own settings fail otherwise.
    void flightsTooShortAreNamedByRobot() {
        Mission mission = sampleMission();
        for (RobotSpec& robot : mission.robots)
            robot.vehicle = VehicleOverrides{};
        mission.robots[0].name = "north";
        mission.robots[1].name = "south";
        mission.robots[2].name = "east";
        mission.exports.vehicle.type = VehicleType::Multirotor;
        mission.exports.vehicle.altitudeMetres = 120.0;
        mission.exports.vehicle.flightTimeSeconds = 600.0;
        QVERIFY(!fleetFlightProblem(mission));
        mission.exports.vehicle.flightTimeSeconds = 60.0;
        const auto everyRobot = fleetFlightProblem(mission);
        QVERIFY(everyRobot);
        QVERIFY2(everyRobot->rfind("every robot: a flight of 1 min leaves no time to survey", 0) == 0,
                 everyRobot->c_str());
        mission.exports.vehicle.flightTimeSeconds = 600.0;
        mission.robots[0].vehicle.flightTimeSeconds = 60.0;
        mission.robots[2].vehicle.flightTimeSeconds = 60.0;
        const auto two = fleetFlightProblem(mission);
        QVERIFY(two);
        QVERIFY2(two->rfind("north and east: a flight of 1 min", 0) == 0, two->c_str());
        mission.robots[2].vehicle.flightTimeSeconds = 90.0; // too short too, at 120 m, but another figure
        const auto others = fleetFlightProblem(mission);
        QVERIFY(others);
        QVERIFY2(others->rfind("north: a flight of 1 min", 0) == 0, others->c_str());
        QVERIFY2(others->ends_with("; east cannot fly its own settings either"), others->c_str());
    }

    // An item limit below the smallest that works is refused with the value given.
    void tooSmallAnItemLimitIsQuoted() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("limit.json").toStdString();
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}, {"start": [30, 20], "max_waypoints": 5}]})");
        const auto loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(), path +
                                     ": robots[1].max_waypoints: must be 0 (no limit) or at least 10 mission "
                                     "items, not 5");
    }

    // Times are seconds: a time written with its unit is refused, with the number to write instead. A bare
    // number too few seconds for a flight is likely minutes: the hint gives their seconds, and the number
    // written as such is refused with them too; a turnaround of "25" is 25 s. Text that is no time keeps the
    // plain message.
    void timeWithAUnitNamesTheSecondsToWrite() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("units.json").toStdString();
        const auto refusal = [&path](const std::string& robot, const std::string& exports) {
            writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                                "robots": [)" +
                                robot + R"(], "exports": {)" + exports + "}}");
            const auto loaded = loadMission(path);
            return loaded.ok() ? std::string("loaded") : loaded.error();
        };
        const std::string robot = R"({"start": [10, 20]})";
        QCOMPARE(refusal(R"({"start": [10, 20], "flight_time_s": "0.5 h"})", R"("turnaround_s": "5min")"),
                 path + ": robots[0].flight_time_s: expected a number of seconds, found the text \"0.5 h\": "
                        "write 1800 for 30 min");
        QCOMPARE(refusal(robot, R"("turnaround_s": "5min")"),
                 path +
                     ": exports.turnaround_s: expected a number of seconds, found the text \"5min\": write "
                     "300 for 5 min");
        QCOMPARE(refusal(R"({"start": [10, 20], "flight_time_s": "25"})", ""),
                 path +
                     ": robots[0].flight_time_s: expected a number of seconds, found the text \"25\": write "
                     "1500 for 25 min");
        QCOMPARE(refusal(R"({"start": [10, 20], "flight_time_s": 25})", ""),
                 path +
                     ": robots[0].flight_time_s: must be 0 (no limit) or a flight of 1 min to 1000 h (60 to "
                     "3600000 s), not 25 s: write 1500 for 25 min");
        QCOMPARE(refusal(robot, R"("turnaround_s": "25")"),
                 path +
                     ": exports.turnaround_s: expected a number of seconds, found the text \"25\": write 25 "
                     "for 25 s");
        QCOMPARE(refusal(robot, R"("turnaround_s": "soon")"),
                 path + ": exports.turnaround_s: expected a number, found a string");
    }

    // Distances and speeds written as text are refused with the number to write, in the key's unit; text in
    // another unit is not given a number that would be read in the wrong one.
    void distanceWithAUnitNamesTheNumberToWrite() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("units.json").toStdString();
        const auto errorWith = [&](const std::string& exports) {
            writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                                "robots": [{"start": [10, 20]}], "exports": {)" +
                                exports + "}}");
            const auto loaded = loadMission(path);
            return loaded.ok() ? std::string() : loaded.error();
        };
        QCOMPARE(
            errorWith(R"("camera_trigger_m": "48 m")"),
            path + ": exports.camera_trigger_m: expected a number of metres, found the text \"48 m\": write "
                   "48, without quotes or a unit (the key's name gives it)");
        QCOMPARE(errorWith(R"("cruise_speed_mps": "12.5")"),
                 path + ": exports.cruise_speed_mps: expected a number of metres per second, found the text "
                        "\"12.5\": write 12.5, without quotes or a unit (the key's name gives it)");
        QCOMPARE(errorWith(R"("altitude_m": "400 ft")"),
                 path +
                     ": exports.altitude_m: expected a number of metres, found the text \"400 ft\": give it "
                     "in metres, without quotes or a unit");
        QCOMPARE(
            errorWith(R"("camera_trigger_m": " +48 Metres ")"),
            path +
                ": exports.camera_trigger_m: expected a number of metres, found the text \" +48 Metres \": "
                "write 48, without quotes or a unit (the key's name gives it)");
        QCOMPARE(errorWith(R"("speed_tolerance": "10%")"),
                 path + ": exports.speed_tolerance: expected a number, found the text \"10%\": give it as a "
                        "number, without quotes");
        QCOMPARE(errorWith(R"("altitude_m": "high")"),
                 path + ": exports.altitude_m: expected a number, found a string");
    }

    // A mistyped key or planner parameter names the one most likely meant; one far from any, none.
    void mistypedKeysNameTheKeyMeant() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("typo.json").toStdString();
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}], "exports": {"altitud_m": 30}})");
        auto loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(), path + ": exports.altitud_m: unknown key: did you mean \"altitude_m\"?");
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}], "exports": {"colour": 30}})");
        loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(), path + ": exports.colour: unknown key");
        // A known key with more round it, and what other tools call a robot's start, name ours.
        const std::vector<std::pair<std::string, std::string>> otherNames{
            {R"("robots_list": [{"start": [10, 20]}])", "robots_list: unknown key: did you mean \"robots\"?"},
            {R"("robots": [{"position": [10, 20]}])",
             "robots[0].position: unknown key: did you mean \"start\"?"},
            {R"("robots": [{"home": [10, 20]}])", "robots[0].home: unknown key: did you mean \"start\"?"}};
        for (const auto& [robots, error] : otherNames) {
            writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"}, )" +
                                robots + "}");
            loaded = loadMission(path);
            QVERIFY(!loaded.ok());
            QCOMPARE(loaded.error(), path + ": " + error); // "home" is not "name", two letters off
        }
        // A key of an inner object given at the top level names the object it belongs in.
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}], "preset": "nlcd"})");
        loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(), path +
                                     ": preset: unknown key at the top level: it belongs in \"classes\", as "
                                     "\"classes\": {\"preset\": ...}");
        // A drone's keys too, and a robot's, whose home is an array of objects.
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}], "fov_m": 40})");
        loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(), path +
                                     ": fov_m: unknown key at the top level: it belongs in \"classes\", as "
                                     "\"classes\": {\"fov_m\": ...}");
        // A vehicle's key is every robot's in exports, or one robot's own in its entry of robots.
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}], "flight_time_s": 1200})");
        loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(),
                 path +
                     ": flight_time_s: unknown key at the top level: it belongs in \"exports\", as "
                     "\"exports\": {\"flight_time_s\": ...} for every robot, or in an entry of \"robots\", "
                     "as \"robots\": [{\"flight_time_s\": ...}], for that robot alone");
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}], "start_crs": "EPSG:4326"})");
        loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error(), path + ": start_crs: unknown key at the top level: it belongs in each of "
                                        "\"robots\", as \"robots\": [{\"start_crs\": ...}]");
        writeText(path, R"({"format": "mcpp-mission", "version": 2, "raster": {"path": "map.tif"},
                            "robots": [{"start": [10, 20]}],
                            "planner": {"name": "mcpp-mlct", "parameters": {"fewer_turn_slack": 2}}})");
        loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        QVERIFY2(
            loaded.error().find("planner.parameters.fewer_turn_slack: unknown parameter of planner mcpp-mlct "
                                "(did you mean \"fewer_turns_slack\"? parameters: ") != std::string::npos,
            loaded.error().c_str());
    }

    void rasterPathIsRelativeToTheMissionFile() {
        Mission mission;
        mission.rasterPath = "../data/map.tif";
        QCOMPARE(resolveRasterPath(mission, "/projects/site/missions/m.json"),
                 std::string("/projects/site/data/map.tif"));
        mission.rasterPath = "/abs/map.tif";
        QCOMPARE(resolveRasterPath(mission, "/projects/m.json"), std::string("/abs/map.tif"));
        mission.rasterPath = "map.tif";
        QCOMPARE(resolveRasterPath(mission, "m.json"), std::string("map.tif"));
    }

    void saveIsAtomic() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("mission.json").toStdString();
        QVERIFY(saveMission(sampleMission(), path).ok());
        const std::string before = readBytes(path);
        // A failing save (folder missing) reports the path and leaves no partial file.
        const std::string elsewhere = folder.filePath("missing/mission.json").toStdString();
        Status failed = saveMission(sampleMission(), elsewhere);
        QVERIFY(!failed.ok());
        QVERIFY(failed.error().find(elsewhere) != std::string::npos);
        QCOMPARE(readBytes(path), before);
        int files = 0;
        for ([[maybe_unused]] const auto& entry :
             std::filesystem::directory_iterator(folder.path().toStdString()))
            ++files;
        QCOMPARE(files, 1);
    }
};

QTEST_GUILESS_MAIN(MissionFilesTest)
#include "test_mission_files.moc"
