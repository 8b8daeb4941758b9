#pragma once

// A small hand-built plan for the exporter tests: no planner involved.
//
// Top grid: two 20 m cells side by side at the NLCD raster's origin (EPSG:26912).
//   top cell 0 is split into four 10 m cells: NW and NE belong to robot 0, SE is blocked,
//   SW is active but unreachable (robotOfCell -1);
//   top cell 1 is one active 20 m cell of robot 1.

#include "core/model/Plan.hpp"

namespace mcpp::test {

inline QuadCell makeCell(int level, int row, int column, double minX, double minY, double size, CellState state) {
    QuadCell cell;
    cell.level = level;
    cell.row = row;
    cell.column = column;
    cell.minX = minX;
    cell.minY = minY;
    cell.size = size;
    cell.state = state;
    return cell;
}

inline Waypoint makeWaypoint(double x, double y, int activeCell, std::int32_t classValue, double speed, double fov,
                             double seconds) {
    Waypoint waypoint;
    waypoint.x = x;
    waypoint.y = y;
    waypoint.activeCell = activeCell;
    waypoint.classValue = classValue;
    waypoint.speedMetresPerSecond = speed;
    waypoint.fieldOfViewMetres = fov;
    waypoint.cumulativeSeconds = seconds;
    return waypoint;
}

inline Plan makeFixturePlan(double originX = 301900.0, double originY = 4154080.0) {
    Plan plan;
    plan.planner = "fixture";
    QuadTree& tree = plan.quadTree;
    tree.levels = 2;
    tree.fovMin = 5.0;
    tree.topCellSize = 20.0;
    tree.originX = originX;
    tree.originY = originY;
    tree.topColumns = 2;
    tree.topRows = 1;
    const double top = originY - 20.0;
    tree.cells.push_back(makeCell(1, 0, 0, originX, top, 20.0, CellState::Auxiliary));           // 0
    tree.cells.push_back(makeCell(1, 0, 1, originX + 20.0, top, 20.0, CellState::Active));       // 1
    tree.cells.push_back(makeCell(2, 0, 0, originX, top + 10.0, 10.0, CellState::Active));       // 2 NW
    tree.cells.push_back(makeCell(2, 0, 1, originX + 10.0, top + 10.0, 10.0, CellState::Active)); // 3 NE
    tree.cells.push_back(makeCell(2, 1, 1, originX + 10.0, top, 10.0, CellState::Blocked));      // 4 SE
    tree.cells.push_back(makeCell(2, 1, 0, originX, top, 10.0, CellState::Active));              // 5 SW
    tree.cells[0].children = {2, 3, 4, 5};
    for (int child = 2; child <= 5; ++child) tree.cells[static_cast<std::size_t>(child)].parent = 0;
    tree.activeCells = {2, 3, 5, 1};
    for (std::size_t i = 0; i < tree.activeCells.size(); ++i) {
        QuadCell& cell = tree.cells[static_cast<std::size_t>(tree.activeCells[i])];
        cell.activeIndex = static_cast<int>(i);
        cell.classValue = i == 3 ? 6 : 4;
        cell.speedMetresPerSecond = i == 3 ? 1.5 : 0.5;
    }

    plan.allocation.robotOfCell = {0, 0, -1, 1};
    plan.allocation.startCell = {0, 3};
    plan.allocation.costSeconds = {80.0, 53.3};

    // Robot 0: through NW and NE sub-cell centres; a straight run of three points, then back.
    CoveragePath first;
    first.robot = 0;
    first.waypoints = {
        makeWaypoint(originX + 2.5, originY - 2.5, 0, 4, 0.5, 5, 0),
        makeWaypoint(originX + 7.5, originY - 2.5, 0, 4, 0.5, 5, 10),
        makeWaypoint(originX + 12.5, originY - 2.5, 1, 4, 0.5, 5, 20),
        makeWaypoint(originX + 17.5, originY - 2.5, 1, 4, 0.5, 5, 30),
        makeWaypoint(originX + 17.5, originY - 7.5, 1, 4, 0.5, 5, 40),
        makeWaypoint(originX + 2.5, originY - 7.5, 0, 4, 0.5, 5, 70),
        makeWaypoint(originX + 2.5, originY - 2.5, 0, 4, 0.5, 5, 80),
    };
    first.lengthMetres = 40.0;
    first.timeSeconds = 80.0;
    first.turns = 3;

    // Robot 1: a loop in its 20 m cell with a speed change on the way back.
    CoveragePath second;
    second.robot = 1;
    second.waypoints = {
        makeWaypoint(originX + 25.0, originY - 5.0, 3, 6, 1.5, 10, 0),
        makeWaypoint(originX + 35.0, originY - 5.0, 3, 6, 1.5, 10, 6.67),
        makeWaypoint(originX + 35.0, originY - 15.0, 3, 6, 1.5, 10, 13.33),
        makeWaypoint(originX + 25.0, originY - 15.0, 3, 6, 1.0, 10, 23.33),
        makeWaypoint(originX + 25.0, originY - 5.0, 3, 6, 1.0, 10, 33.33),
    };
    second.lengthMetres = 40.0;
    second.timeSeconds = 33.33;
    second.turns = 4;
    plan.paths = {first, second};

    PlanMetrics& metrics = plan.metrics;
    metrics.robots = {RobotMetrics{0, 2, 200.0, 40.0, 80.0, 80.0, 3}, RobotMetrics{1, 1, 400.0, 40.0, 33.33, 53.3, 4}};
    metrics.makespanSeconds = 80.0;
    metrics.lowerBoundSeconds = 66.65;
    metrics.ratio = 80.0 / 66.65;
    metrics.passableAreaSquareMetres = 700.0;
    metrics.coveredAreaSquareMetres = 600.0;
    metrics.coveredFraction = 600.0 / 700.0;
    metrics.unreachableAreaSquareMetres = 100.0;
    metrics.repeatedFraction = 0.05;
    metrics.stageMilliseconds = {{"quadtree", 1.5}, {"allocation", 2.25}, {"paths", 0.75}};
    plan.warnings = {"fixture warning"};
    return plan;
}

} // namespace mcpp::test
