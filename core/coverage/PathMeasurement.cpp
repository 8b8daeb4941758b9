#include "core/coverage/PathMeasurement.hpp"

#include "core/coverage/PathMeasurer.hpp"
#include "core/coverage/PathShape.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

namespace mcpp {
namespace {

// Whether a closed tour's last sub-cell visit returns to its first: that return is no repeated coverage.
bool returnsToFirstVisit(const CoveragePath& path, const CellGraph& graph) {
    if (!path.closed)
        return false;
    const auto visits = [&](const Waypoint& waypoint) { return subCellVisited(waypoint, graph).first >= 0; };
    const auto firstVisit = std::find_if(path.waypoints.begin(), path.waypoints.end(), visits);
    const auto lastVisit = std::find_if(path.waypoints.rbegin(), path.waypoints.rend(), visits);
    return firstVisit != path.waypoints.end() && firstVisit != lastVisit.base() - 1 &&
           subCellVisited(*firstVisit, graph) == subCellVisited(*lastVisit, graph);
}

// Visits beyond each sub-cell's first, counted by sorting the visits: for a thread without a visit map.
int repeatsBySorting(const CoveragePath& path, const CellGraph& graph) {
    std::vector<std::int64_t> visits;
    visits.reserve(path.waypoints.size());
    for (const Waypoint& waypoint : path.waypoints)
        if (const auto visited = subCellVisited(waypoint, graph); visited.first >= 0)
            visits.push_back(std::int64_t{visited.first} * 4 + visited.second);
    std::sort(visits.begin(), visits.end());
    return static_cast<int>(std::ssize(visits) -
                            (std::unique(visits.begin(), visits.end()) - visits.begin()));
}

// The same with one bit a sub-cell, cleared again afterwards, so a call costs the path's length.
int repeatsByMarking(const CoveragePath& path, const CellGraph& graph, std::vector<std::uint8_t>& seen) {
    int repeats = 0;
    for (const Waypoint& waypoint : path.waypoints) {
        const auto visited = subCellVisited(waypoint, graph);
        if (visited.first < 0)
            continue;
        std::uint8_t& marks = seen[static_cast<std::size_t>(visited.first)];
        const auto bit = static_cast<std::uint8_t>(1U << static_cast<unsigned>(visited.second));
        if ((marks & bit) != 0)
            ++repeats;
        marks = static_cast<std::uint8_t>(marks | bit);
    }
    for (const Waypoint& waypoint : path.waypoints) {
        if (waypoint.cell >= 0 && static_cast<std::size_t>(waypoint.cell) < seen.size())
            seen[static_cast<std::size_t>(waypoint.cell)] = 0;
    }
    return repeats;
}

} // namespace

std::pair<int, int> subCellVisited(const Waypoint& waypoint, const CellGraph& graph) {
    if (!graph.contains(waypoint.cell))
        return {-1, 0};
    const Cell& cell = graph.cell(waypoint.cell);
    const MapPoint point{waypoint.x, waypoint.y};
    const SubCell subCell = cell.subCellAt(point);
    const MapPoint centre = cell.subCellCentre(subCell);
    const bool onCentre = centre.x == point.x && centre.y == point.y; // most points: no distance to work out
    if (!onCentre && std::hypot(centre.x - point.x, centre.y - point.y) > 1e-6 * cell.size)
        return {-1, 0};
    return {waypoint.cell, static_cast<int>(subCell)};
}

int countTurns(const std::vector<Waypoint>& waypoints) {
    PathShape shape;
    for (const Waypoint& waypoint : waypoints)
        shape.add(waypoint.x, waypoint.y);
    return shape.turns();
}

int countRepeatedSubCellVisits(const CoveragePath& path, const CellGraph& graph) {
    // A visit map of one byte a cell, kept by each thread, so a call costs the path's length and not the
    // map's size. A thread without one yet (path balance starts threads for each chain it tries) sorts the
    // visits of a path much shorter than the map rather than clearing a byte a cell first.
    thread_local std::vector<std::uint8_t> seen;
    int repeats = 0;
    if (seen.size() < graph.size() && path.waypoints.size() < graph.size() / 16) {
        repeats = repeatsBySorting(path, graph);
    } else {
        if (seen.size() < graph.size())
            seen.resize(graph.size(), 0);
        repeats = repeatsByMarking(path, graph, seen);
    }
    return returnsToFirstVisit(path, graph) ? repeats - 1 : repeats;
}

namespace {

double segmentLength(const Waypoint& from, const Waypoint& to) {
    return stepOf(to.x - from.x, to.y - from.y).length;
}

} // namespace

double turnSecondsAt(const Waypoint& corner, double inX, double inY, double outX, double outY,
                     const CellGraph& graph) {
    const bool straightOn = inX * outY - inY * outX == 0.0 && inX * outX + inY * outY > 0.0;
    if (straightOn || !graph.contains(corner.cell))
        return 0.0; // straight on, most steps of a path, costs nothing whatever the cell's price
    // At the waypoint's speed: the cell's, or a robot's own where it drives at one (PlanningProblem).
    return turnSecondsBetween(inX, inY, outX, outY,
                              graph.turnSeconds(corner.cell, corner.speedMetresPerSecond));
}

double turnSecondsBetween(double inX, double inY, double outX, double outY, double price) {
    constexpr double quarterTurn = 1.5707963267948966;
    const double cross = inX * outY - inY * outX;
    const double dot = inX * outX + inY * outY;
    if (!(price > 0.0) || (cross == 0.0 && dot > 0.0)) // free, or straight on (most steps of a path)
        return 0.0;
    return std::abs(std::atan2(cross, dot)) / quarterTurn * price;
}

namespace {

// The unit direction of the last step of non-zero length that ends at or before waypoint `index`.
std::optional<Direction> wayInto(const std::vector<Waypoint>& waypoints, std::size_t index) {
    for (std::size_t i = index; i > 0; --i) {
        const double length = segmentLength(waypoints[i - 1], waypoints[i]);
        if (length > 0.0)
            return Direction{(waypoints[i].x - waypoints[i - 1].x) / length,
                             (waypoints[i].y - waypoints[i - 1].y) / length};
    }
    return std::nullopt;
}

// Times waypoints first .. last: travelSeconds per step and, before leaving a point, the turn made there
// (at `first`, from the way the path came in). Calls atWaypoint(i, seconds since first) for each.
template <typename AtWaypoint>
PathSeconds walkSeconds(const std::vector<Waypoint>& waypoints, const CellGraph& graph, std::size_t first,
                        std::size_t last, AtWaypoint&& atWaypoint) {
    PathSeconds seconds;
    if (first >= waypoints.size())
        return seconds;
    std::optional<Direction> direction = wayInto(waypoints, first);
    atWaypoint(first, 0.0);
    for (std::size_t i = first + 1; i <= last && i < waypoints.size(); ++i) {
        const Waypoint& from = waypoints[i - 1];
        const Waypoint& to = waypoints[i];
        addStepSeconds(seconds, direction, from, to, stepOf(to.x - from.x, to.y - from.y), graph);
        atWaypoint(i, seconds.total);
    }
    return seconds;
}

} // namespace

void addStepSeconds(PathSeconds& seconds, std::optional<Direction>& direction, const Waypoint& from,
                    const Waypoint& to, const Step& step, const CellGraph& graph) {
    if (step.length > 0.0) {
        const Direction out{step.x, step.y};
        if (direction) {
            const double turn = turnSecondsAt(from, direction->x, direction->y, out.x, out.y, graph);
            seconds.turning += turn;
            seconds.total += turn;
        }
        direction = out;
    }
    seconds.total += travelSeconds(step.length, from.speedMetresPerSecond, to.speedMetresPerSecond);
}

PathSeconds pathSeconds(const std::vector<Waypoint>& waypoints, const CellGraph& graph) {
    if (waypoints.empty())
        return {};
    return walkSeconds(waypoints, graph, 0, waypoints.size() - 1, [](std::size_t, double) {});
}

std::vector<double> cumulativeSeconds(const CoveragePath& path, const CellGraph& graph) {
    std::vector<double> seconds(path.waypoints.size(), 0.0);
    if (seconds.empty())
        return seconds;
    walkSeconds(path.waypoints, graph, 0, seconds.size() - 1,
                [&seconds](std::size_t i, double total) { seconds[i] = total; });
    // A pause at a waypoint delays every waypoint after it.
    double waited = 0.0;
    std::size_t next = 0;
    for (std::size_t i = 0; i < seconds.size(); ++i) {
        seconds[i] += waited;
        for (; next < path.pauses.size() && path.pauses[next].waypoint == i; ++next)
            waited += path.pauses[next].seconds;
    }
    return seconds;
}

std::vector<double> cumulativeSecondsAt(const CoveragePath& path, const CellGraph& graph,
                                        const std::vector<std::size_t>& indices) {
    std::vector<double> seconds(indices.size(), 0.0);
    if (path.waypoints.empty())
        return seconds;
    std::size_t wanted = 0;
    walkSeconds(path.waypoints, graph, 0, path.waypoints.size() - 1, [&](std::size_t i, double total) {
        for (; wanted < indices.size() && indices[wanted] == i; ++wanted)
            seconds[wanted] = total;
    });
    // A pause at a waypoint delays every waypoint after it, added in the order cumulativeSeconds adds them.
    double waited = 0.0;
    std::size_t next = 0;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        for (; next < path.pauses.size() && path.pauses[next].waypoint < indices[k]; ++next)
            waited += path.pauses[next].seconds;
        seconds[k] += waited;
    }
    return seconds;
}

double sortieSeconds(const CoveragePath& path, const Sortie& sortie, const CellGraph& graph) {
    return walkSeconds(path.waypoints, graph, sortie.firstWaypoint, sortie.lastWaypoint,
                       [](std::size_t, double) {})
        .total;
}

CoveragePath sortiePath(const CoveragePath& path, const Sortie& sortie) {
    CoveragePath flight;
    flight.robot = path.robot;
    flight.closed = true;
    const auto first = path.waypoints.begin() + static_cast<std::ptrdiff_t>(sortie.firstWaypoint);
    flight.waypoints.assign(first,
                            path.waypoints.begin() + static_cast<std::ptrdiff_t>(sortie.lastWaypoint) + 1);
    return flight;
}

double longestSortieSeconds(const CoveragePath& path, const std::vector<Sortie>& sorties,
                            const CellGraph& graph) {
    double longest = 0.0;
    for (const Sortie& sortie : sorties)
        longest = std::max(longest, sortieSeconds(path, sortie, graph));
    return longest;
}

Direction unitDirection(double fromX, double fromY, double toX, double toY) {
    const double alongX = toX - fromX;
    const double alongY = toY - fromY;
    const double length = std::sqrt(alongX * alongX + alongY * alongY);
    if (!(length > 0.0))
        return {};
    return {alongX / length, alongY / length};
}

double longestPathSeconds(const std::vector<CoveragePath>& paths) {
    double longest = 0.0;
    for (const CoveragePath& path : paths)
        longest = std::max(longest, path.timeSeconds);
    return longest;
}

double pausedSecondsBetween(const std::vector<PathPause>& pauses, std::size_t first, std::size_t last) {
    // Pauses are in waypoint order: a sortie's are found without passing the whole path's.
    const auto byWaypoint = [](const PathPause& pause, std::size_t waypoint) {
        return pause.waypoint < waypoint;
    };
    double waited = 0.0;
    for (auto pause = std::lower_bound(pauses.begin(), pauses.end(), first, byWaypoint);
         pause != pauses.end() && pause->waypoint < last; ++pause)
        waited += pause->seconds;
    return waited;
}

double connectorSeconds(const std::vector<Waypoint>& waypoints, const CellGraph& graph) {
    if (graph.hasOneCellSize())
        return 0.0; // a pass over a path of hundreds of millions of points for nothing
    PathMeasurer measurer(graph);
    for (const Waypoint& waypoint : waypoints)
        measurer.add(waypoint);
    return measurer.connectorSeconds();
}

void timePath(CoveragePath& path, const CellGraph& graph) {
    const PathSeconds seconds = pathSeconds(path.waypoints, graph);
    path.timeSeconds = seconds.total + pausedSecondsBetween(path.pauses, 0, path.waypoints.size());
    path.turnSeconds = seconds.turning;
}

double pathLengthMetres(const std::vector<Waypoint>& waypoints) {
    double length = 0.0;
    for (std::size_t i = 1; i < waypoints.size(); ++i)
        length += segmentLength(waypoints[i - 1], waypoints[i]);
    return length;
}

void measurePath(CoveragePath& path, const CellGraph& graph) {
    if (path.runsMerged())
        return;                   // measured before its straight runs were merged, from every waypoint
    PathMeasurer measurer(graph); // length, turns, time and connectors in one pass
    for (const Waypoint& waypoint : path.waypoints)
        measurer.add(waypoint);
    measurer.fill(path);
    path.repeatedSubCellVisits = countRepeatedSubCellVisits(path, graph);
}

CoveragePath pathFromWalk(int robot, MapPoint start, std::vector<Waypoint> walk, bool closed) {
    CoveragePath path;
    path.robot = robot;
    path.closed = closed;
    if (walk.empty())
        return path;
    const Waypoint first = walk.front();
    const bool startIsOnWalk = mcpp::startIsOnWalk(first, start);
    // The walk becomes the path in place: on big regions a copy costs as much as the walk itself.
    path.waypoints = std::move(walk);
    if (!startIsOnWalk) {
        Waypoint origin = first;
        origin.x = start.x;
        origin.y = start.y;
        path.waypoints.insert(path.waypoints.begin(), origin);
        if (closed)
            path.waypoints.push_back(origin);
    }
    return path;
}

} // namespace mcpp
