#include "core/coverage/StraightRunMerging.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/StraightRunMerger.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {
namespace {

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
    if (path.runsMerged() || !path.pauses.empty() || path.waypoints.size() < 3)
        return;
    StraightRunMerger merger(graph);
    for (const Waypoint& waypoint : path.waypoints)
        merger.add(waypoint);
    merger.finishInto(path);
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
            !graph.contains(kept[i].cell))
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
