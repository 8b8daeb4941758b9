#include "core/coverage/StraightRunMerging.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {
namespace {

bool inGraph(const Waypoint& waypoint, const CellGraph& graph) {
    return waypoint.cell >= 0 && static_cast<std::size_t>(waypoint.cell) < graph.size();
}

// Whether a step from `from` to `to` is one sub-cell of `to`'s cell long (a robot's step between
// neighbouring sub-cell centres of cells of one size).
bool isSubCellStep(const Waypoint& from, const Waypoint& to, double cellSize) {
    const double length = stepOf(to.x - from.x, to.y - from.y).length; // no square root along an axis
    return std::abs(length - cellSize / 2.0) <= 1e-9 * cellSize;
}

// Whether the walk goes straight on through waypoint b, in steps of one sub-cell, with one speed, one
// cell size and one land cover from a through b to c: b can be left out and put back from a and c.
bool insideStraightRun(const Waypoint& a, const Waypoint& b, const Waypoint& c, const CellGraph& graph) {
    if (!inGraph(a, graph) || !inGraph(b, graph) || !inGraph(c, graph))
        return false;
    if (a.speedMetresPerSecond != b.speedMetresPerSecond || b.speedMetresPerSecond != c.speedMetresPerSecond)
        return false;
    const Cell& middle = graph.cell(b.cell);
    for (const Waypoint* side : {&a, &c}) {
        const Cell& cell = graph.cell(side->cell);
        if (cell.size != middle.size || cell.classValue != middle.classValue)
            return false; // a change of size or of land cover, which exports show
    }
    const double size = middle.size;
    const double inX = b.x - a.x, inY = b.y - a.y, outX = c.x - b.x, outY = c.y - b.y;
    return inX * outY - inY * outX == 0.0 && inX * outX + inY * outY > 0.0 && isSubCellStep(a, b, size) &&
           isSubCellStep(b, c, size);
}

// The cell holding `point`: `near` when it does (most steps of a run stay in their cell or the next).
int cellHolding(const CellGraph& graph, MapPoint point, int near) {
    const Cell& cell = graph.cell(near);
    if (point.x >= cell.minX && point.x < cell.maxX() && point.y >= cell.minY && point.y < cell.maxY())
        return near;
    return graph.cellAt(point);
}

// The waypoints a merged run from `from` to `to` left out, at most `room` of them: evenly spaced at half the
// cells' side, each put on its sub-cell's centre as the walk put it. Nothing when the run does not divide
// into such steps or would exceed `room` (a damaged plan file).
void putBackRun(const Waypoint& from, const Waypoint& to, const CellGraph& graph, std::size_t room,
                std::vector<Waypoint>& walked) {
    const double step = graph.cell(from.cell).size / 2.0;
    const double length = stepOf(to.x - from.x, to.y - from.y).length;
    const double steps = std::round(length / step);
    if (steps < 2.0 || steps - 1.0 > static_cast<double>(room) ||
        std::abs(steps * step - length) > 1e-9 * length)
        return;
    int cell = from.cell;
    for (double k = 1.0; k < steps; k += 1.0) {
        Waypoint between = from;
        const MapPoint point{from.x + (to.x - from.x) * (k / steps), from.y + (to.y - from.y) * (k / steps)};
        const int holding = cellHolding(graph, point, cell);
        if (holding >= 0) {
            cell = holding;
            const Cell& square = graph.cell(cell);
            const MapPoint centre = square.subCellCentre(square.subCellAt(point));
            between.cell = cell;
            between.x = centre.x;
            between.y = centre.y;
        } else {
            between.x = point.x;
            between.y = point.y;
        }
        walked.push_back(between);
    }
}

} // namespace

void mergeStraightRuns(CoveragePath& path, const CellGraph& graph) {
    std::vector<Waypoint>& waypoints = path.waypoints;
    if (path.runsMerged() || !path.pauses.empty() || waypoints.size() < 3)
        return;
    const std::size_t walked = waypoints.size();
    // In place: a waypoint is written at or before its own index, so waypoints[i - 1] is still the
    // walk's when i is judged.
    std::vector<bool> runFollows;
    std::size_t kept = 1;
    std::size_t lastKept = 0; // the walk's index of the last waypoint kept
    const auto keep = [&](std::size_t i) {
        runFollows.push_back(i - lastKept > 1);
        waypoints[kept++] = waypoints[i];
        lastKept = i;
    };
    for (std::size_t i = 1; i + 1 < walked; ++i)
        if (!insideStraightRun(waypoints[i - 1], waypoints[i], waypoints[i + 1], graph))
            keep(i);
    keep(walked - 1);
    runFollows.push_back(false); // the last waypoint: nothing follows
    if (kept == walked)
        return; // no straight run: the path stays as it was
    waypoints.resize(kept);
    waypoints.shrink_to_fit(); // the point: hand the memory back
    path.walkedWaypoints = walked;
    path.runFollows = std::move(runFollows);
}

std::vector<Waypoint> walkedWaypoints(const CoveragePath& path, const CellGraph& graph) {
    if (!path.runsMerged())
        return path.waypoints;
    const std::vector<Waypoint>& kept = path.waypoints;
    std::vector<Waypoint> walked;
    walked.reserve(std::min(path.walkedWaypoints, kept.size() + mostWalkedWaypointsPerCell * graph.size()));
    for (std::size_t i = 0; i < kept.size(); ++i) {
        walked.push_back(kept[i]);
        if (i >= path.runFollows.size() || !path.runFollows[i] || i + 1 == kept.size() ||
            !inGraph(kept[i], graph))
            continue;
        const std::size_t room =
            path.walkedWaypoints - std::min(path.walkedWaypoints, walked.size() + kept.size() - i - 1);
        putBackRun(kept[i], kept[i + 1], graph, room, walked);
    }
    return walked;
}

CoveragePath withEveryWaypoint(const CoveragePath& path, const CellGraph& graph) {
    CoveragePath whole = path;
    if (!path.runsMerged())
        return whole;
    whole.waypoints = walkedWaypoints(path, graph);
    whole.walkedWaypoints = 0;
    whole.runFollows.clear();
    return whole;
}

} // namespace mcpp
