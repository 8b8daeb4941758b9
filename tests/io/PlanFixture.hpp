#pragma once

// A small hand-built plan for the exporter tests: no planner involved.
//
// Top grid: two 20 m cells side by side at the NLCD raster's origin (EPSG:26912).
//   top cell 0 is split into four 10 m cells: NW and NE belong to robot 0, SE is blocked,
//   SW is active but unreachable (robotOfCell -1);
//   top cell 1 is one active 20 m cell of robot 1.

#include "core/model/Plan.hpp"

namespace mcpp::test {

inline Cell makeCell(const GridFrame& frame, int column, int row, int span, std::int32_t classValue,
                     double speed) {
    Cell cell;
    cell.column = column;
    cell.row = row;
    cell.span = span;
    cell.level = span == 1 ? 2 : 1;
    cell.minX = frame.x(column);
    cell.size = span * frame.bottomCellSize;
    cell.minY = frame.y(row) - cell.size;
    cell.classValue = classValue;
    cell.speedMetresPerSecond = speed;
    cell.passableAreaSquareMetres = cell.size * cell.size;
    return cell;
}

inline Waypoint makeWaypoint(double x, double y, int cell, double speed) {
    Waypoint waypoint;
    waypoint.x = x;
    waypoint.y = y;
    waypoint.cell = cell;
    waypoint.speedMetresPerSecond = static_cast<float>(speed);
    return waypoint;
}

inline Plan makeFixturePlan(double originX = 301900.0, double originY = 4154080.0) {
    Plan plan;
    plan.planner = "fixture";
    GridFrame frame;
    frame.originX = originX;
    frame.originY = originY;
    frame.bottomCellSize = 10.0;
    frame.columns = 4;
    frame.rows = 2;
    frame.levels = 2;
    // Cells 0 NW, 1 NE, 2 SW of the split top cell (its SE quarter is blocked: no cell), 3 the 20 m cell.
    std::vector<Cell> cells{makeCell(frame, 0, 0, 1, 4, 0.5), makeCell(frame, 1, 0, 1, 4, 0.5),
                            makeCell(frame, 0, 1, 1, 4, 0.5), makeCell(frame, 2, 0, 2, 6, 1.5)};
    plan.cells = CellGraph(frame, std::move(cells), NeighbourTopology({0, 2, 4, 5, 6}, {1, 2, 0, 3, 0, 1}));
    plan.cells.passableAreaSquareMetres = 700.0;

    plan.regions.robotOfCell = {0, 0, -1, 1};
    plan.regions.startCell = {0, 3};
    plan.regions.costSeconds = {80.0, 53.3};

    // Robot 0: through NW and NE sub-cell centres; a straight run of three points, then back.
    CoveragePath first;
    first.robot = 0;
    first.waypoints = {
        makeWaypoint(originX + 2.5, originY - 2.5, 0, 0.5),
        makeWaypoint(originX + 7.5, originY - 2.5, 0, 0.5),
        makeWaypoint(originX + 12.5, originY - 2.5, 1, 0.5),
        makeWaypoint(originX + 17.5, originY - 2.5, 1, 0.5),
        makeWaypoint(originX + 17.5, originY - 7.5, 1, 0.5),
        makeWaypoint(originX + 2.5, originY - 7.5, 0, 0.5),
        makeWaypoint(originX + 2.5, originY - 2.5, 0, 0.5),
    };
    first.lengthMetres = 40.0;
    first.timeSeconds = 80.0;
    first.turns = 3;

    // Robot 1: a loop in its 20 m cell with a speed change on the way back.
    CoveragePath second;
    second.robot = 1;
    second.waypoints = {
        makeWaypoint(originX + 25.0, originY - 5.0, 3, 1.5),
        makeWaypoint(originX + 35.0, originY - 5.0, 3, 1.5),
        makeWaypoint(originX + 35.0, originY - 15.0, 3, 1.5),
        makeWaypoint(originX + 25.0, originY - 15.0, 3, 1.0),
        makeWaypoint(originX + 25.0, originY - 5.0, 3, 1.0),
    };
    second.lengthMetres = 40.0;
    second.timeSeconds = 33.33;
    second.turns = 4;
    plan.paths = {first, second};

    PlanMetrics& metrics = plan.metrics;
    metrics.robots = {RobotMetrics{0, 2, 200.0, 40.0, 80.0, 0.0, 80.0, 3},
                      RobotMetrics{1, 1, 400.0, 40.0, 33.33, 0.0, 53.3, 4}};
    metrics.makespanSeconds = 80.0;
    metrics.lowerBoundSeconds = 66.65;
    metrics.ratio = 80.0 / 66.65;
    metrics.passableAreaSquareMetres = 700.0;
    metrics.coveredAreaSquareMetres = 600.0;
    metrics.coveredFraction = 600.0 / 700.0;
    metrics.unreachableAreaSquareMetres = 100.0;
    metrics.repeatedFraction = 0.05;
    metrics.stageMilliseconds = {{"quadtree", 1.5}, {"allocation", 2.25}, {"paths", 0.75}};
    plan.issues = {{IssueSeverity::Warning, "fixture", "fixture warning"}};
    return plan;
}

} // namespace mcpp::test
