// A plan saved beside its mission comes back whole, only for the inputs it was planned from; a damaged
// file is refused with its name and never crashes the reader.
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/Mission.hpp"
#include "io/PlanFile.hpp"
#include "tests/support/SyntheticMaps.hpp"
#include "tests/support/TestData.hpp"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <fstream>
#include <random>

using namespace mcpp;

namespace {

Plan plannedMap() {
    test::RandomMapSpec spec;
    spec.columns = 24;
    spec.rows = 18;
    spec.landCovers = 3;
    spec.obstacleFraction = 0.08;
    spec.fovPixels = 1.0;
    spec.robots = 3;
    spec.seed = 7;
    return MlctPlanner{}.plan(test::randomProblem(spec), {});
}

bool sameWaypoints(const std::vector<Waypoint>& a, const std::vector<Waypoint>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Waypoint& x, const Waypoint& y) {
        return x.x == y.x && x.y == y.y && x.cell == y.cell &&
               x.speedMetresPerSecond == y.speedMetresPerSecond;
    });
}

void compareCells(const CellGraph& a, const CellGraph& b) {
    QCOMPARE(a.size(), b.size());
    QCOMPARE(a.frame().columns, b.frame().columns);
    QCOMPARE(a.frame().bottomCellSize, b.frame().bottomCellSize);
    QCOMPARE(a.frame().originX, b.frame().originX);
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Cell& x = a.cells()[i];
        const Cell& y = b.cells()[i];
        QVERIFY(x.column == y.column && x.row == y.row && x.span == y.span && x.level == y.level);
        QVERIFY(x.minX == y.minX && x.minY == y.minY && x.size == y.size && x.classValue == y.classValue);
        QVERIFY(x.speedMetresPerSecond == y.speedMetresPerSecond &&
                x.passableAreaSquareMetres == y.passableAreaSquareMetres && x.freeSubCells == y.freeSubCells);
    }
    QCOMPARE(a.neighbourLists().offsets(), b.neighbourLists().offsets());
    QCOMPARE(a.neighbourLists().neighbours(), b.neighbourLists().neighbours());
    QCOMPARE(a.fieldsOfView.size(), b.fieldsOfView.size());
    QCOMPARE(a.passableAreaSquareMetres, b.passableAreaSquareMetres);
    // The locator is rebuilt: every cell is found at its centre.
    for (std::size_t i = 0; i < b.size(); ++i)
        QCOMPARE(b.cellAt({b.cells()[i].centreX(), b.cells()[i].centreY()}), static_cast<int>(i));
}

std::string bytesOf(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

} // namespace

class TestPlanFile : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir folder_;
    std::string file(const char* name) const { return folder_.filePath(name).toStdString(); }

  private slots:
    void planComesBackWhole() {
        Plan plan = plannedMap();
        // Times in the field, as a plan of drones holds them.
        plan.metrics.fieldMakespanSeconds = 9000.5;
        plan.metrics.fieldLowerBoundSeconds = 7000.25;
        for (RobotMetrics& robot : plan.metrics.robots)
            robot.fieldSeconds = 8000.0 + robot.robot;
        // What the ratio is measured against: a reopened plan reads its ratio as it was planned.
        plan.metrics.sharedPartsRatio = 1.25;
        plan.metrics.boundOfDetectionPasses = true;
        QCOMPARE(plan.paths.size(), std::size_t{3});
        plan.paths[1].takeOff = MapPoint{-120.5, 33.25}; // an aircraft taking off outside the area
        // Land left out beyond every flight's reach, drawn with the land no robot covers.
        plan.landBeyondReach = PixelRuns{-50.0, 120.0, 10.0, 12.5, {{0, 2, 5}, {0, 7, 9}, {3, 0, 4}}};
        const std::string path = file("whole.mcpp-plan");
        const io::Status saved = io::savePlanFile(plan, "inputs-a", path);
        QVERIFY2(saved.ok(), saved.error().c_str());
        auto loaded = io::loadPlanFile(path, "inputs-a");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        QVERIFY(loaded.value().has_value());
        const Plan& back = *loaded.value();
        QCOMPARE(back.planner, plan.planner);
        QVERIFY(back.parameters == plan.parameters);
        compareCells(plan.cells, back.cells);
        QCOMPARE(back.regions.robotOfCell, plan.regions.robotOfCell);
        QCOMPARE(back.regions.startCell, plan.regions.startCell);
        QCOMPARE(back.regions.costSeconds, plan.regions.costSeconds);
        QCOMPARE(back.paths.size(), plan.paths.size());
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot) {
            const CoveragePath& a = plan.paths[robot];
            const CoveragePath& b = back.paths[robot];
            QVERIFY(a.robot == b.robot && a.lengthMetres == b.lengthMetres && a.timeSeconds == b.timeSeconds);
            QVERIFY(a.turns == b.turns && a.repeatedSubCellVisits == b.repeatedSubCellVisits &&
                    a.closed == b.closed);
            QVERIFY(sameWaypoints(a.waypoints, b.waypoints));
            QVERIFY(a.takeOff == b.takeOff);
        }
        QVERIFY(back.paths[1].takeOff.has_value());
        QCOMPARE(back.landBeyondReach.originX, -50.0);
        QCOMPARE(back.landBeyondReach.pixelHeight, 12.5);
        QCOMPARE(back.landBeyondReach.runs.size(), std::size_t{3});
        QCOMPARE(back.landBeyondReach.runs[1].firstColumn, 7);
        QCOMPARE(back.landBeyondReach.runs[2].row, 3);
        QCOMPARE(back.landBeyondReach.runs[2].endColumn, 4);
        QCOMPARE(back.metrics.makespanSeconds, plan.metrics.makespanSeconds);
        QCOMPARE(back.metrics.ratio, plan.metrics.ratio);
        QCOMPARE(back.metrics.coveredFraction, plan.metrics.coveredFraction);
        QCOMPARE(back.metrics.robots.size(), plan.metrics.robots.size());
        QCOMPARE(back.metrics.robots[2].turns, plan.metrics.robots[2].turns);
        QCOMPARE(back.metrics.robots[2].fieldSeconds, 8002.0);
        QCOMPARE(back.metrics.fieldMakespanSeconds, 9000.5);
        QCOMPARE(back.metrics.fieldLowerBoundSeconds, 7000.25);
        QCOMPARE(back.metrics.sharedPartsRatio, 1.25);
        QVERIFY(back.metrics.boundOfDetectionPasses);
        QCOMPARE(back.metrics.stageMilliseconds, plan.metrics.stageMilliseconds);
        QVERIFY(back.issues == plan.issues);
        QVERIFY(!back.metrics.ownSpeedsIgnored);
        // Saving what was read gives the same bytes: nothing is lost or reordered.
        QVERIFY(io::savePlanFile(back, "inputs-a", file("again.mcpp-plan")).ok());
        QCOMPARE(bytesOf(file("again.mcpp-plan")), bytesOf(path));
    }

    // A plan that timed robots of their own speeds at the class table's is read back so, from its warning:
    // compared again, it is not set beside plans keeping their speeds.
    void ownSpeedsIgnoredComesBackFromTheWarning() {
        Plan plan = plannedMap();
        plan.metrics.ownSpeedsIgnored = true;
        plan.issues.push_back({IssueSeverity::Warning, "own-speeds-ignored", "timed at the class speeds"});
        const std::string path = file("class-speeds.mcpp-plan");
        QVERIFY(io::savePlanFile(plan, "inputs-a", path).ok());
        auto loaded = io::loadPlanFile(path, "inputs-a");
        QVERIFY(loaded.ok() && loaded.value().has_value());
        QVERIFY(loaded.value()->metrics.ownSpeedsIgnored);
    }

    // A robot of its own speed turns at its price in a plan read back, as when it was planned: the turn
    // times the plan's model gives come back as that model, not cell by cell at the class speeds.
    void aRobotOfItsOwnSpeedTurnsAtItsPriceReadBack() {
        test::RandomMapSpec spec;
        spec.columns = 24;
        spec.rows = 18;
        spec.landCovers = 3;
        spec.fovPixels = 1.0;
        spec.robots = 2;
        spec.seed = 7;
        PlanningProblem problem = test::randomProblem(spec);
        problem.robotSpeeds = {0.0, 6.0};
        const Plan plan = MlctPlanner{}.plan(problem, {}); // turns priced from the speed, the default
        const std::string path = file("own-speed.mcpp-plan");
        QVERIFY(io::savePlanFile(plan, "inputs-a", path).ok());
        auto loaded = io::loadPlanFile(path, "inputs-a");
        QVERIFY2(loaded.ok() && loaded.value().has_value(), loaded.ok() ? "" : loaded.error().c_str());
        const Plan& back = *loaded.value();
        const int cell = plan.paths[1].waypoints.front().cell;
        QCOMPARE(back.cells.turnSeconds(cell, 6.0F), plan.cells.turnSeconds(cell, 6.0F));
        QVERIFY(back.cells.turnSeconds(cell, 6.0F) > back.cells.turnSeconds(cell)); // 6 m/s beats the class's
        QCOMPARE(cumulativeSeconds(back.paths[1], back.cells).back(),
                 cumulativeSeconds(plan.paths[1], plan.cells).back());
    }

    // A large plan's paths with their straight runs merged come back merged, with the count of waypoints
    // they walked, so that they are neither measured again (their repeated visits counted from what is
    // left) nor drawn as if each step were a run.
    void mergedPathsComeBackMerged() {
        Plan plan = plannedMap();
        mergeStraightRuns(plan.paths[1], plan.cells);
        QVERIFY(plan.paths[1].runsMerged());
        const std::string path = file("merged.mcpp-plan");
        QVERIFY(io::savePlanFile(plan, "inputs-m", path).ok());
        auto loaded = io::loadPlanFile(path, "inputs-m");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        const Plan& back = *loaded.value();
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot) {
            QCOMPARE(back.paths[robot].walkedWaypoints, plan.paths[robot].walkedWaypoints);
            QVERIFY(back.paths[robot].runFollows == plan.paths[robot].runFollows);
            QVERIFY(sameWaypoints(back.paths[robot].waypoints, plan.paths[robot].waypoints));
        }
        QVERIFY(!back.paths[0].runsMerged());
    }

    // Merged runs that cannot be this map's walk are refused as damage, before anything expands them.
    void mergedRunsThatDoNotAddUpAreRefused() {
        Plan plan = plannedMap();
        mergeStraightRuns(plan.paths[0], plan.cells);
        QVERIFY(plan.paths[0].runsMerged());
        for (const std::size_t walked :
             {plan.paths[0].waypoints.size() - 1, plan.paths[0].waypoints.size() + 9 * plan.cells.size()}) {
            Plan damaged = plan;
            damaged.paths[0].walkedWaypoints = walked;
            QVERIFY(io::savePlanFile(damaged, "inputs-d", file("damaged.mcpp-plan")).ok());
            const auto loaded = io::loadPlanFile(file("damaged.mcpp-plan"), "inputs-d");
            QVERIFY(!loaded.ok());
            QVERIFY2(loaded.error().find("merged runs do not add up") != std::string::npos,
                     loaded.error().c_str());
        }
        Plan shortFlags = plan;
        shortFlags.paths[0].runFollows.pop_back();
        QVERIFY(io::savePlanFile(shortFlags, "inputs-d", file("damaged.mcpp-plan")).ok());
        QVERIFY(!io::loadPlanFile(file("damaged.mcpp-plan"), "inputs-d").ok());
    }

    // Files of the formats before (MCPP-PLAN 3: no counts of walked waypoints; 4: no times in the field; 5:
    // no take-off points; 6: no kind of bound) are still read.
    void filesOfTheFormatBeforeAreRead() {
        const std::string seed =
            bytesOf(test::sourcePath("tests/fuzz/corpus/fuzz_plan_file/compressed-body"));
        QVERIFY(seed.size() > 1);
        const auto before = io::parsePlanBody(std::string_view(seed).substr(1), "seed", 3);
        QVERIFY2(before.ok(), before.ok() ? "" : before.error().c_str());
        QVERIFY(!before.value().paths.empty());
        writeBytes(file("format3.mcpp-plan"), "MCPP-PLAN 3\ninputs-3\n" + seed.substr(1));
        auto loaded = io::loadPlanFile(file("format3.mcpp-plan"), "inputs-3");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        QVERIFY(loaded.value().has_value());
        QCOMPARE(loaded.value()->paths.size(), before.value().paths.size());

        // MCPP-PLAN 4 (no times in the field), as mcpp saved it for the synthetic sample, is read with none;
        // the sample flown by drones, saved by this version, reads back with them.
        const std::string fourth =
            bytesOf(test::sourcePath("tests/fuzz/corpus/fuzz_plan_file/compressed-body-v4"));
        writeBytes(file("format4.mcpp-plan"), "MCPP-PLAN 4\ninputs-4\n" + fourth.substr(1));
        auto fromFourth = io::loadPlanFile(file("format4.mcpp-plan"), "inputs-4");
        QVERIFY2(fromFourth.ok(), fromFourth.ok() ? "" : fromFourth.error().c_str());
        QVERIFY(fromFourth.value().has_value());
        const Plan& plan = *fromFourth.value();
        QCOMPARE(plan.paths.size(), std::size_t{3});
        QCOMPARE(plan.metrics.robots.size(), std::size_t{3});
        QVERIFY(plan.metrics.makespanSeconds > 0.0);
        QCOMPARE(plan.metrics.fieldMakespanSeconds, 0.0);
        QCOMPARE(plan.metrics.robots[2].fieldSeconds, 0.0);
        const std::string fifth =
            bytesOf(test::sourcePath("tests/fuzz/corpus/fuzz_plan_file/compressed-body-v5"));
        const auto fromFifth = io::parsePlanBody(std::string_view(fifth).substr(1), "seed", 5);
        QVERIFY2(fromFifth.ok(), fromFifth.ok() ? "" : fromFifth.error().c_str());
        QCOMPARE(fromFifth.value().paths.size(), std::size_t{3});
        // That plan's drones (3 min flights, 2 min turnarounds) come home later than their paths end.
        const PlanMetrics& flown = fromFifth.value().metrics;
        QVERIFY(flown.fieldLowerBoundSeconds > flown.lowerBoundSeconds);
        QVERIFY(flown.fieldMakespanSeconds > flown.makespanSeconds);
        QVERIFY(flown.robots[1].fieldSeconds > flown.robots[1].timeSeconds);
        QVERIFY(std::none_of(fromFifth.value().paths.begin(), fromFifth.value().paths.end(),
                             [](const CoveragePath& path) { return path.takeOff.has_value(); }));
        // Read as the format before or after, the same bytes are damaged: the versions are told apart.
        QVERIFY(!io::parsePlanBody(std::string_view(fifth).substr(1), "seed", 4).ok());
        QVERIFY(!io::parsePlanBody(std::string_view(fifth).substr(1), "seed", 6).ok());
        QVERIFY(!io::parsePlanBody(std::string_view(fifth).substr(1), "seed", 7).ok());
        QCOMPARE(flown.sharedPartsRatio, 0.0); // no kind of bound before MCPP-PLAN 7: the plain one
        QVERIFY(!flown.boundOfDetectionPasses);
        // The synthetic sample's plan as this version saves it (the fuzzer's seed of it) is read whole, and
        // not as the version before.
        const std::string seventh =
            bytesOf(test::sourcePath("tests/fuzz/corpus/fuzz_plan_file/compressed-body-v7"));
        const auto fromSeventh = io::parsePlanBody(std::string_view(seventh).substr(1), "seed", 7);
        QVERIFY2(fromSeventh.ok(), fromSeventh.ok() ? "" : fromSeventh.error().c_str());
        QCOMPARE(fromSeventh.value().paths.size(), std::size_t{3});
        QVERIFY(fromSeventh.value().metrics.ratio >= 1.0);
        QVERIFY(!io::parsePlanBody(std::string_view(seventh).substr(1), "seed", 6).ok());
        QVERIFY(!io::parsePlanBody(std::string_view(seventh).substr(1), "seed", 8).ok());
        QVERIFY(fromSeventh.value().landBeyondReach.empty()); // none before MCPP-PLAN 8
        // The same plan with land beyond reach, as this version saves it (the fuzzer's seed of it).
        const std::string eighth =
            bytesOf(test::sourcePath("tests/fuzz/corpus/fuzz_plan_file/compressed-body-v8"));
        const auto fromEighth = io::parsePlanBody(std::string_view(eighth).substr(1), "seed", 8);
        QVERIFY2(fromEighth.ok(), fromEighth.ok() ? "" : fromEighth.error().c_str());
        QCOMPARE(fromEighth.value().landBeyondReach.runs.size(), std::size_t{4});
        QCOMPARE(fromEighth.value().landBeyondReach.runs.back().endColumn, 30);
        QVERIFY(!io::parsePlanBody(std::string_view(eighth).substr(1), "seed", 7).ok());
        // Drawn: its labels mark that land where no cell lies.
        const LabelGrid labels = regionLabels(fromEighth.value());
        QVERIFY(std::count(labels.labels.begin(), labels.labels.end(), unreachableLabel) > 0);
    }

    void waypointsOffTheGridComeBackAsTheyWere() {
        // Most waypoints are saved as a cell and a sub-cell; these are not and must come back exactly.
        Plan plan = plannedMap();
        std::vector<Waypoint>& first = plan.paths[0].waypoints;
        QVERIFY(first.size() > 10);
        first[3].x += 0.123;                  // not a sub-cell centre
        first[6].speedMetresPerSecond *= 0.5; // another speed
        first[7].cell = -1;                   // in no cell
        const std::string path = file("unusual.mcpp-plan");
        QVERIFY(io::savePlanFile(plan, "inputs-a", path).ok());
        auto loaded = io::loadPlanFile(path, "inputs-a");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        for (std::size_t robot = 0; robot < plan.paths.size(); ++robot)
            QVERIFY(sameWaypoints(loaded.value()->paths[robot].waypoints, plan.paths[robot].waypoints));
    }

    void otherInputsAreNotRestored() {
        const std::string path = file("other.mcpp-plan");
        QVERIFY(io::savePlanFile(plannedMap(), "inputs-a", path).ok());
        auto loaded = io::loadPlanFile(path, "inputs-b");
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        QVERIFY(!loaded.value().has_value());
    }

    void damagedFilesAreRefusedByName() {
        const std::string path = file("good.mcpp-plan");
        QVERIFY(io::savePlanFile(plannedMap(), "inputs-a", path).ok());
        const std::string good = bytesOf(path);
        const std::string damaged = file("damaged.mcpp-plan");
        // Cut anywhere after the header, or with bytes changed: an error naming the file, never a crash.
        std::mt19937 random(11);
        const std::size_t header = good.find('\n', good.find('\n') + 1) + 1;
        for (int trial = 0; trial < 60; ++trial) {
            std::string bytes = good;
            if (trial % 2 == 0) {
                bytes.resize(header + random() % (good.size() - header));
            } else {
                for (int flip = 0; flip < 4; ++flip)
                    bytes[header + random() % (good.size() - header)] ^=
                        static_cast<char>(1 + random() % 255);
            }
            writeBytes(damaged, bytes);
            auto loaded = io::loadPlanFile(damaged, "inputs-a");
            QVERIFY2(!loaded.ok(), qPrintable(QStringLiteral("trial %1 read a damaged file").arg(trial)));
            QVERIFY(loaded.error().find(damaged) == 0);
        }
        // Land beyond reach in runs out of order (a damaged file's would be drawn over and over).
        Plan disordered = plannedMap();
        disordered.landBeyondReach = PixelRuns{0.0, 0.0, 10.0, 10.0, {{3, 0, 4}, {0, 2, 5}}};
        QVERIFY(io::savePlanFile(disordered, "inputs-a", damaged).ok());
        const auto outOfOrder = io::loadPlanFile(damaged, "inputs-a");
        QVERIFY(!outOfOrder.ok() && outOfOrder.error().find("runs out of order") != std::string::npos);
        writeBytes(damaged, "{\"fileType\": \"Plan\"}\n");
        auto other = io::loadPlanFile(damaged, "inputs-a");
        QVERIFY(!other.ok() && other.error().find("not a plan file") != std::string::npos);
        auto missing = io::loadPlanFile(file("missing.mcpp-plan"), "inputs-a");
        QVERIFY(!missing.ok() && missing.error().find("missing.mcpp-plan") != std::string::npos);
    }

    void planFileSitsBesideTheMission() {
        QCOMPARE(io::planFilePath("/data/survey/mission.json"),
                 std::string("/data/survey/mission.mcpp-plan"));
        QCOMPARE(io::planFilePath("field.v2.json"), std::string("field.v2.mcpp-plan"));
    }

    void fingerprintFollowsWhatThePlanDependsOn() {
        // A mission beside its own copy of the sample raster, so the test may touch the raster.
        const std::string raster = file("land.tif");
        std::filesystem::copy_file(test::sourcePath("samples/zion-nlcd/nlcd.tif"), raster,
                                   std::filesystem::copy_options::overwrite_existing);
        const std::string missionPath = file("mission.json");
        auto loaded = io::loadMission(test::sourcePath("samples/zion-nlcd/mission.json"));
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        io::Mission mission = loaded.value();
        mission.rasterPath = "land.tif"; // relative to the mission, as saved
        const std::string base = io::planInputsFingerprint(mission, missionPath);
        QCOMPARE(base.size(), std::size_t{64});
        QCOMPARE(io::planInputsFingerprint(mission, missionPath), base);

        io::Mission renamed = mission;
        renamed.robots[0].name = "Another name";
        renamed.exports.vehicle.altitudeMetres = 55.0;
        QCOMPARE(io::planInputsFingerprint(renamed, missionPath), base);

        io::Mission moved = mission;
        moved.robots[1].start.x += 30.0;
        QVERIFY(io::planInputsFingerprint(moved, missionPath) != base);
        io::Mission slower = mission;
        auto landCover =
            *std::find_if(slower.classes.classes().begin(), slower.classes.classes().end(),
                          [](const LandCoverClass& candidate) { return candidate.isTraversable(); });
        landCover.speedMetresPerSecond *= 0.5;
        slower.classes.set(landCover);
        QVERIFY(io::planInputsFingerprint(slower, missionPath) != base);
        // Each robot's cruise speed drives it in the plan; the fleet's altitude does not.
        io::Mission drone = mission;
        drone.robots[0].vehicle.cruiseSpeedMetresPerSecond = 12.0;
        const std::string withDrone = io::planInputsFingerprint(drone, missionPath);
        QVERIFY(withDrone != base);
        drone.robots[0].vehicle.cruiseSpeedMetresPerSecond = 10.0;
        QVERIFY(io::planInputsFingerprint(drone, missionPath) != withDrone);
        io::Mission otherPlanner = mission;
        otherPlanner.planner.planner = "darp";
        QVERIFY(io::planInputsFingerprint(otherPlanner, missionPath) != base);
        // A flight time shapes only the waypoint files, except for a planner on batteries: there it is
        // the battery of robots without their own.
        io::Mission longerFlights = mission;
        longerFlights.exports.vehicle.flightTimeSeconds = 1800.0;
        QCOMPARE(io::planInputsFingerprint(longerFlights, missionPath), base);
        io::Mission onBatteries = mission;
        onBatteries.planner = defaultPlannerChoice("wavefront-battery");
        const std::string batteryBase = io::planInputsFingerprint(onBatteries, missionPath);
        onBatteries.exports.vehicle.flightTimeSeconds = 1800.0;
        QVERIFY(io::planInputsFingerprint(onBatteries, missionPath) != batteryBase);
        // Where time in the field is measured (aircraft), the vehicles shape the plan's figures there and
        // MCPP-MLCT's division: a turnaround or a flight time makes the plan out of date; names still do not.
        io::Mission flying = mission;
        flying.exports.vehicle.type = io::VehicleType::Multirotor;
        const std::string flyingBase = io::planInputsFingerprint(flying, missionPath);
        QVERIFY(flyingBase != base);
        flying.robots[0].name = "Another name";
        QCOMPARE(io::planInputsFingerprint(flying, missionPath), flyingBase);
        flying.exports.vehicle.turnaroundSeconds = 300.0;
        const std::string withTurnarounds = io::planInputsFingerprint(flying, missionPath);
        QVERIFY(withTurnarounds != flyingBase);
        flying.robots[1].vehicle.flightTimeSeconds = 1200.0;
        QVERIFY(io::planInputsFingerprint(flying, missionPath) != withTurnarounds);

        // What the window keeps when it reads the files: empty (unknown) for a file that is not there.
        const std::string identity = io::inputFilesIdentity({raster, std::string(), std::string()});
        QVERIFY(!identity.empty());
        QVERIFY(io::inputFilesIdentity({raster, file("no-such-area.geojson"), std::string()}).empty());
        // A path with ".." names the same file: the same fingerprint.
        io::Mission roundabout = mission;
        roundabout.rasterPath = "../" + QFileInfo(folder_.path()).fileName().toStdString() + "/land.tif";
        QCOMPARE(io::planInputsFingerprint(roundabout, missionPath), base);

        // The raster changed on disk (same path): the fingerprint changes.
        std::filesystem::last_write_time(raster,
                                         std::filesystem::last_write_time(raster) + std::chrono::seconds(5));
        QVERIFY(io::planInputsFingerprint(mission, missionPath) != base);
        QVERIFY(io::inputFilesIdentity({raster, std::string(), std::string()}) != identity);
    }
};

QTEST_APPLESS_MAIN(TestPlanFile)
#include "test_plan_file.moc"
