// Waypoints beyond the area of interest: counted per robot, with how far they lie from the task area, and
// said by every plan whose paths pass there.

#include "core/planners/AreaEdgeCheck.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QTest>

using namespace mcpp;

namespace {

constexpr double west = 500000.0; // uniformProblem's corner
constexpr double north = 4000000.0;

// 10 x 10 pixels of 10 m; the two western columns outside the area of interest, the north-east pixel
// nodata.
PlanningProblem fencedProblem() {
    PlanningProblem problem = test::uniformProblem(10, 10, 10.0, {}, {});
    ClassGrid& grid = problem.grid;
    grid.outside.assign(grid.values.size(), 0);
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < 2; ++column)
            grid.outside[grid.index(column, row)] = ClassGrid::outsideArea;
    grid.outside[grid.index(9, 0)] = ClassGrid::outsideNodata;
    return problem;
}

// A path through points given in metres east and south of the map's north-west corner.
CoveragePath pathThrough(int robot, const std::vector<MapPoint>& eastSouth) {
    CoveragePath path;
    path.robot = robot;
    for (const MapPoint point : eastSouth)
        path.waypoints.push_back(Waypoint{west + point.x, north - point.y});
    return path;
}

} // namespace

class AreaEdgeCheckTest : public QObject {
    Q_OBJECT

  private slots:
    void waypointsBeyondTheAreaAreCountedWithTheirDistance() {
        const ClassGrid grid = fencedProblem().grid;
        const std::vector<CoveragePath> paths{
            pathThrough(0, {{55, 55}, {15, 55}, {5, 45}}), // 5 m and 15 m west of the area's edge at 20 m
            pathThrough(1, {{55, 25}, {95, 5}}),   // inside, and on nodata: the raster's edge, no fence
            pathThrough(2, {{25, 85}, {12, 85}})}; // 8 m beyond
        const WaypointsBeyondArea beyond = waypointsBeyondArea(grid, paths);
        QCOMPARE(beyond.waypoints, 3);
        QCOMPARE(beyond.inNoGoZones, 0);
        QCOMPARE(beyond.robots, (std::vector<int>{0, 2}));
        QCOMPARE(beyond.farthestMetres, 15.0);
        QCOMPARE(beyond.pixelMetres, 10.0);
    }

    void waypointsBeyondTheRasterAreCountedWithTheirDistance() {
        const ClassGrid grid = fencedProblem().grid; // 100 x 100 m
        std::vector<CoveragePath> paths{pathThrough(0, {{55, 55}, {95, 105}, {105, 95}, {100, 100}}),
                                        pathThrough(1, {{-5, -12}}), pathThrough(2, {{5, 5}})};
        for (CoveragePath& path : paths)
            for (Waypoint& waypoint : path.waypoints)
                waypoint.cell = 0;
        const WaypointsBeyondRaster beyond = waypointsBeyondRaster(grid, paths);
        QCOMPARE(beyond.waypoints, 3); // the corner itself is on the raster
        QCOMPARE(beyond.robots, (std::vector<int>{0, 1}));
        QCOMPARE(beyond.farthestMetres, 13.0); // 5 m west and 12 m north
        paths[1].waypoints.front().cell = -1;  // a take-off beside the raster is no coverage waypoint
        QCOMPARE(waypointsBeyondRaster(grid, paths).robots, (std::vector<int>{0}));
    }

    // 5 rows of 10 m pixels, cells of 20 m: the southern row of cells lies half beyond the raster, and
    // MCPP-MLCT covers it whole under the blocked threshold of 0.5, and says so; below it, the cells are
    // left out and the paths stay on the raster.
    void aPlanPassingBeyondTheRasterSaysSo() {
        PlanningProblem problem = test::uniformProblem(6, 5, 10.0, {}, {});
        problem.classes.set({1, "grass", 0x88cc44, 1.0, 10.0, true});
        problem.starts = {{west + 25.0, north - 15.0}};
        const auto warningOf = [](const Plan& plan) {
            return std::find_if(plan.issues.begin(), plan.issues.end(),
                                [](const PlanIssue& issue) { return issue.code == "paths-beyond-raster"; });
        };
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, ProgressReporter{});
        const auto warning = warningOf(plan);
        QVERIFY(warning != plan.issues.end());
        QVERIFY2(warning->message.find("the path of robot 1 passes beyond the raster's edge at 6 sub-cell "
                                       "centres, up to 5 m past it") != std::string::npos,
                 warning->message.c_str());
        problem.planner.parameters.set("blocked_threshold", 0.45);
        const Plan inside = makePlanner("mcpp-mlct")->plan(problem, ProgressReporter{});
        QVERIFY(warningOf(inside) == inside.issues.end());
        QVERIFY(waypointsBeyondRaster(problem.grid, inside.paths).waypoints == 0);
        QVERIFY(inside.metrics.coveredFraction < plan.metrics.coveredFraction);
    }

    void mapsWithoutAnAreaOfInterestHaveNone() {
        ClassGrid grid = fencedProblem().grid;
        for (std::uint8_t& flag : grid.outside)
            flag = flag == ClassGrid::outsideArea ? 0 : flag;
        const std::vector<CoveragePath> paths{pathThrough(0, {{5, 45}, {95, 5}})};
        QCOMPARE(waypointsBeyondArea(grid, paths).waypoints, 0);
        grid.outside.clear();
        QCOMPARE(waypointsBeyondArea(grid, paths).waypoints, 0);
    }

    // An area whose edge cuts the cells of 20 m in half: MCPP-MLCT covers them whole, and says so.
    void aPlanPassingBeyondTheAreaSaysSo() {
        PlanningProblem problem = fencedProblem();
        problem.grid.outside[problem.grid.index(9, 0)] = 0;
        for (int row = 0; row < problem.grid.rows; ++row)
            problem.grid.outside[problem.grid.index(0, row)] = 0;     // the area's edge at 10 m
        problem.classes.set({1, "grass", 0x88cc44, 1.0, 10.0, true}); // cells of 20 m
        problem.starts = {{west + 55.0, north - 55.0}};
        const Plan plan = makePlanner("mcpp-mlct")->plan(problem, ProgressReporter{});
        const auto warning = std::find_if(plan.issues.begin(), plan.issues.end(), [](const PlanIssue& issue) {
            return issue.code == "paths-beyond-area";
        });
        QVERIFY(warning != plan.issues.end());
        // The edge drawn may lie half a pixel (5 m) past those pixels: the waypoints 5 m past them may lie
        // inside it, and a fence on it needs 10 m.
        QVERIFY2(warning->message.find(
                     "the path of robot 1 passes over pixels outside the area of interest at ") !=
                         std::string::npos &&
                     warning->message.find("sub-cell centres, up to 5 m past the task area's pixels") !=
                         std::string::npos,
                 warning->message.c_str());
        QVERIFY2(warning->message.find("so those centres may lie inside the area as drawn") !=
                     std::string::npos,
                 warning->message.c_str());
        QVERIFY2(warning->message.find("draw the area 10 m inside the fence") != std::string::npos,
                 warning->message.c_str());
        // The same edge drawn as a no-go zone inside the area of interest is called that.
        for (std::uint8_t& flag : problem.grid.outside)
            flag = flag == ClassGrid::outsideArea ? ClassGrid::inNoGoZone : flag;
        const Plan noGo = makePlanner("mcpp-mlct")->plan(problem, ProgressReporter{});
        const auto zone = std::find_if(noGo.issues.begin(), noGo.issues.end(), [](const PlanIssue& issue) {
            return issue.code == "paths-beyond-area";
        });
        QVERIFY(zone != noGo.issues.end());
        QVERIFY2(zone->message.find("the path of robot 1 passes over pixels of a no-go zone at ") !=
                     std::string::npos,
                 zone->message.c_str());
        QVERIFY2(zone->message.find("so those centres may lie outside the zone as drawn") !=
                     std::string::npos,
                 zone->message.c_str());
        QVERIFY2(zone->message.find("draw the no-go zone 10 m larger") != std::string::npos,
                 zone->message.c_str());
    }
};

QTEST_APPLESS_MAIN(AreaEdgeCheckTest)
#include "test_area_edge_check.moc"
