// Waypoints beyond the area of interest: counted per robot, with how far they lie from the task area.

#include "core/planners/AreaEdgeCheck.hpp"

#include <QTest>

using namespace mcpp;

namespace {

// 10 x 10 pixels of 10 m; the two western columns outside the area of interest, the north-east pixel nodata.
ClassGrid fencedGrid() {
    ClassGrid grid;
    grid.columns = 10;
    grid.rows = 10;
    grid.originX = 0.0;
    grid.originY = 100.0;
    grid.pixelWidth = 10.0;
    grid.pixelHeight = 10.0;
    grid.values.assign(100, 1);
    grid.outside.assign(100, 0);
    for (int row = 0; row < 10; ++row)
        for (int column = 0; column < 2; ++column)
            grid.outside[grid.index(column, row)] = ClassGrid::outsideArea;
    grid.outside[grid.index(9, 0)] = ClassGrid::outsideNodata;
    return grid;
}

CoveragePath pathThrough(int robot, const std::vector<MapPoint>& points) {
    CoveragePath path;
    path.robot = robot;
    for (const MapPoint point : points)
        path.waypoints.push_back(Waypoint{point.x, point.y});
    return path;
}

} // namespace

class AreaEdgeCheckTest : public QObject {
    Q_OBJECT

  private slots:
    void waypointsBeyondTheAreaAreCountedWithTheirDistance() {
        const ClassGrid grid = fencedGrid();
        const std::vector<CoveragePath> paths{
            pathThrough(0, {{55, 55}, {15, 55}, {5, 45}}), // 5 m and 15 m west of the area's edge at x = 20
            pathThrough(1, {{55, 25}, {95, 95}}),  // inside, and on nodata: the raster's edge, no fence
            pathThrough(2, {{25, 15}, {12, 15}})}; // 8 m beyond
        const WaypointsBeyondArea beyond = waypointsBeyondArea(grid, paths);
        QCOMPARE(beyond.waypoints, 3);
        QCOMPARE(beyond.robots, (std::vector<int>{0, 2}));
        QCOMPARE(beyond.farthestMetres, 15.0);
        QCOMPARE(beyond.pixelMetres, 10.0);
    }

    void mapsWithoutAnAreaOfInterestHaveNone() {
        ClassGrid grid = fencedGrid();
        for (std::uint8_t& flag : grid.outside)
            flag = flag == ClassGrid::outsideArea ? 0 : flag;
        const std::vector<CoveragePath> paths{pathThrough(0, {{5, 45}, {95, 95}})};
        QCOMPARE(waypointsBeyondArea(grid, paths).waypoints, 0);
        grid.outside.clear();
        QCOMPARE(waypointsBeyondArea(grid, paths).waypoints, 0);
    }
};

QTEST_APPLESS_MAIN(AreaEdgeCheckTest)
#include "test_area_edge_check.moc"
