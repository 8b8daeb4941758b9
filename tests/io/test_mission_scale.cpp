// How large a mission is, said before planning from the land cover alone: the places its paths pass (each
// class's FOV squared over its land, or the smallest FOV's on a uniform grid), the least time any plan
// takes at the table's speeds, and the FOV factor that brings it down.
#include "io/MissionScale.hpp"

#include <QtTest>

using namespace mcpp;

namespace {

// 1 km2 of grass (10 m FOV, 2 m/s), 1 km2 of forest (5 m, 1 m/s) and water, on 10 m pixels.
io::LoadedRaster twoSquareKilometres() {
    io::LoadedRaster raster;
    raster.grid.pixelWidth = 10.0;
    raster.grid.pixelHeight = 10.0;
    raster.classPixelCounts = {{1, 10000}, {2, 10000}, {3, 5000}};
    return raster;
}

ClassTable grassForestWater() {
    return ClassTable({{1, "Grass", 0x00ff00, 2.0, 10.0, true},
                       {2, "Forest", 0x006600, 1.0, 5.0, true},
                       {3, "Water", 0x0000ff, 0.0, 10.0, false}});
}

std::string factorFlag(double factor) {
    return "--fov-scale " + std::to_string(static_cast<int>(std::lround(factor * 10.0))) + "/10";
}

} // namespace

class TestMissionScale : public QObject {
    Q_OBJECT

  private slots:
    void placesFollowEachClassFieldOfView();
    void theFactorBringsThePlacesDown();
    void onlyLargeMissionsAreWarned();
    void robotsAtACruiseSpeedAreNotTimedAtTheTable();
    void memoryIsCountedOverTheTaskArea();
};

void TestMissionScale::placesFollowEachClassFieldOfView() {
    const io::MissionScale quadTree =
        io::missionScale(twoSquareKilometres(), grassForestWater(), 2, {PlannerChoice{"mcpp-mlct", {}}});
    QCOMPARE(quadTree.passableSquareMetres, 2e6);
    QCOMPARE(quadTree.coveragePoints, 1e6 / 100.0 + 1e6 / 25.0);
    QCOMPARE(quadTree.smallestFieldOfViewMetres, 5.0);
    QCOMPARE(quadTree.smallestFieldOfViewClass, std::string("Forest"));
    // Grass in 10 m strips at 2 m/s, forest in 5 m strips at 1 m/s, shared by two robots.
    QCOMPARE(quadTree.sweepSeconds, (1e6 / 20.0 + 1e6 / 5.0) / 2.0);
    QCOMPARE(quadTree.planners, 1);
    // DARP plans every cell at the smallest FOV; with it in a comparison, so is the count.
    const io::MissionScale uniform =
        io::missionScale(twoSquareKilometres(), grassForestWater(), 2,
                         {PlannerChoice{"mcpp-mlct", {}}, PlannerChoice{"darp", {}}});
    QCOMPARE(uniform.coveragePoints, 2e6 / 25.0);
    QCOMPARE(uniform.planners, 2);
}

void TestMissionScale::theFactorBringsThePlacesDown() {
    io::MissionScale scale;
    scale.coveragePoints = 57e6;
    QCOMPARE(scale.fieldOfViewFactorFor(5e6), 3.4); // sqrt(11.4) = 3.38, rounded up to two digits
    QVERIFY(scale.coveragePoints / (3.4 * 3.4) <= 5e6);
    QCOMPARE(scale.fieldOfViewFactorFor(60e6), 1.0);
    scale.coveragePoints = 1e9;
    QCOMPARE(scale.fieldOfViewFactorFor(5e6), 15.0); // sqrt(200) = 14.14
}

void TestMissionScale::onlyLargeMissionsAreWarned() {
    const auto remedy = [](double factor) { return factorFlag(factor); };
    io::MissionScale scale;
    scale.passableSquareMetres = 1.43e9;
    scale.smallestFieldOfViewMetres = 5.0;
    scale.smallestFieldOfViewClass = "Forest";
    scale.sweepSeconds = 95.4e6;
    scale.coveragePoints = io::largeMissionPoints;
    QVERIFY(!io::largeMissionWarning(scale, true, remedy));
    scale.coveragePoints = 37e6;
    const auto one = io::largeMissionWarning(scale, true, remedy);
    QVERIFY(one);
    for (const char* part : {"1430 km2", "5 m (Forest)", "about 37 million places", "1104 d 4 h",
                             "--fov-scale 14/10 brings it to about 19 million places"})
        QVERIFY2(one->find(part) != std::string::npos, qPrintable(QString::fromStdString(*one)));
    QVERIFY(one->find("planners") == std::string::npos);
    // A comparison runs every planner in turn: said at a quarter of the count, the planners named.
    scale.coveragePoints = 6e6;
    QVERIFY(!io::largeMissionWarning(scale, true, remedy));
    scale.planners = 7;
    const auto several = io::largeMissionWarning(scale, true, remedy);
    QVERIFY(several);
    QVERIFY2(several->find("for each of the 7 planners") != std::string::npos &&
                 several->find("--fov-scale 11/10") != std::string::npos,
             qPrintable(QString::fromStdString(*several)));
}

void TestMissionScale::robotsAtACruiseSpeedAreNotTimedAtTheTable() {
    io::LoadedRaster raster = twoSquareKilometres();
    raster.classPixelCounts = {{2, 2'000'000}}; // 200 km2 of forest at 5 m: 8 million places
    io::Mission mission;
    io::RobotSpec robot;
    robot.name = "north";
    mission.robots.push_back(robot);
    const std::vector<PlannerChoice> darp{PlannerChoice{"darp", {}}, PlannerChoice{"mstc", {}}};
    const auto remedy = [](double factor) { return factorFlag(factor); };
    const auto atTable = io::largeMissionWarning(mission, raster, grassForestWater(), darp, remedy);
    QVERIFY(atTable);
    QVERIFY2(atTable->find("class table's speeds") != std::string::npos,
             qPrintable(QString::fromStdString(*atTable)));
    mission.robots.front().vehicle.cruiseSpeedMetresPerSecond = 8.0;
    const auto cruising = io::largeMissionWarning(mission, raster, grassForestWater(), darp, remedy);
    QVERIFY(cruising);
    QVERIFY(cruising->find("class table's speeds") == std::string::npos);
}

// A quadtree, and a uniform grid as one of one level, spans the top cells holding the task area's pixels:
// the window's banner and the large-mission check count as the planners' guards do.
void TestMissionScale::memoryIsCountedOverTheTaskArea() {
    io::LoadedRaster raster;
    raster.grid.columns = 100;
    raster.grid.rows = 100;
    raster.grid.pixelWidth = 100.0;
    raster.grid.pixelHeight = 100.0;
    raster.grid.values.assign(10000, 1);
    raster.grid.outside.assign(10000, ClassGrid::outsideArea);
    for (int row = 40; row < 45; ++row)
        for (int column = 30; column < 35; ++column)
            raster.grid.outside[raster.grid.index(column, row)] = 0;
    raster.classPixelCounts = {{1, 25}};
    const ClassTable grass({{1, "Grass", 0x00ff00, 1.0, 1.0, true}});
    const auto quadTree = io::planningMemory(raster, grass, PlannerChoice{"mcpp-mlct", {}});
    QVERIFY(quadTree);
    QCOMPARE(quadTree->estimate.bottomCells, std::int64_t{250 * 250}); // 500 m at 2 m cells
    const auto uniform = io::planningMemory(raster, grass, PlannerChoice{"darp", {}});
    QVERIFY(uniform);
    QCOMPARE(uniform->estimate.bottomCells, std::int64_t{250 * 250}); // the same window, one level
    QVERIFY(!io::planningMemory(raster, ClassTable({{1, "Water", 0x0000ff, 0.0, 1.0, false}}),
                                PlannerChoice{"mcpp-mlct", {}}));
}

QTEST_APPLESS_MAIN(TestMissionScale)
#include "test_mission_scale.moc"
