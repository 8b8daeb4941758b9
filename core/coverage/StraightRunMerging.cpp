#include "core/coverage/StraightRunMerging.hpp"

#include <cmath>

namespace mcpp {
namespace {

bool inGraph(const Waypoint& waypoint, const CellGraph& graph) {
    return waypoint.cell >= 0 && static_cast<std::size_t>(waypoint.cell) < graph.size();
}

// Whether a step from `from` to `to` is one sub-cell of `to`'s cell long (a robot's step between
// neighbouring sub-cell centres of cells of one size).
bool isSubCellStep(const Waypoint& from, const Waypoint& to, double cellSize) {
    const double length = std::hypot(to.x - from.x, to.y - from.y);
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
    waypoints.resize(kept);
    waypoints.shrink_to_fit(); // the point: hand the memory back
    path.walkedWaypoints = walked;
    path.runFollows = std::move(runFollows);
}

std::vector<Waypoint> walkedWaypoints(const CoveragePath& path, const CellGraph& graph) {
    if (!path.runsMerged())
        return path.waypoints;
    std::vector<Waypoint> walked;
    walked.reserve(path.walkedWaypoints);
    for (std::size_t i = 0; i < path.waypoints.size(); ++i) {
        const Waypoint& from = path.waypoints[i];
        walked.push_back(from);
        if (i >= path.runFollows.size() || !path.runFollows[i] || i + 1 == path.waypoints.size() ||
            !inGraph(from, graph))
            continue;
        const Waypoint& to = path.waypoints[i + 1];
        const double step = graph.cell(from.cell).size / 2.0;
        const double length = std::hypot(to.x - from.x, to.y - from.y);
        const auto steps = static_cast<long>(std::llround(length / step));
        if (steps < 2 || std::abs(static_cast<double>(steps) * step - length) > 1e-9 * length)
            continue;
        for (long k = 1; k < steps; ++k) {
            const double share = static_cast<double>(k) / static_cast<double>(steps);
            Waypoint between = from;
            between.x = from.x + (to.x - from.x) * share;
            between.y = from.y + (to.y - from.y) * share;
            const int cell = graph.cellAt({between.x, between.y});
            between.cell = cell >= 0 ? cell : from.cell;
            walked.push_back(between);
        }
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
