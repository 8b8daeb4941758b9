#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/Sortie.hpp"

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace mcpp {

// The time to travel `lengthMetres` from a point at one speed to a point at another: half the way at each.
// At one speed (most steps) the two halves are the same number, worked out once.
[[nodiscard]] inline double travelSeconds(double lengthMetres, double fromSpeed, double toSpeed) {
    const double firstHalf = lengthMetres / 2.0 / fromSpeed;
    return firstHalf + (fromSpeed == toSpeed ? firstHalf : lengthMetres / 2.0 / toSpeed);
}

// A step's length and, where it is not zero, its unit direction.
struct Step {
    double length = 0.0;
    double x = 0.0;
    double y = 0.0;
};

// Most steps of a coverage path run along an axis: those skip the square root and the divisions and give
// the same bits (the square root of a rounded square is the number squared, short of under- or overflow).
[[nodiscard]] inline Step stepOf(double dx, double dy) {
    constexpr double tiny = 1e-150;
    constexpr double huge = 1e150;
    if (dx == 0.0 && std::abs(dy) > tiny && std::abs(dy) < huge)
        return {std::abs(dy), dx, std::copysign(1.0, dy)};
    if (dy == 0.0 && std::abs(dx) > tiny && std::abs(dx) < huge)
        return {std::abs(dx), std::copysign(1.0, dx), dy};
    const double length = std::sqrt(dx * dx + dy * dy);
    if (length == 0.0)
        return {};
    return {length, dx / length, dy / length};
}

// The (cell, sub-cell) a waypoint marks when it sits on a sub-cell centre, the sub-cell as a SubCell's
// number; cell -1 otherwise (a start point off the centres, a point in no cell).
[[nodiscard]] std::pair<int, int> subCellVisited(const Waypoint& waypoint, const CellGraph& graph);

// Direction changes along a polyline; steps of zero length are skipped and a U-turn counts once.
[[nodiscard]] int countTurns(const std::vector<Waypoint>& waypoints);

// Sub-cell centres a path passes again after its first pass, not counting a closed tour's return to the
// sub-cell it began in. Points that are no sub-cell centre (a start point, say) are not visits.
[[nodiscard]] int countRepeatedSubCellVisits(const CoveragePath& path, const CellGraph& graph);

// What a step between sub-cell centres takes beyond the quarter of each cell's side, at its speed, that
// the cells' travel counts for it (the step is timed half at each end's speed, so this may be negative).
[[nodiscard]] inline double secondsBeyondCellTravel(double lengthMetres, double fromCellSize,
                                                    double fromSpeed, double toCellSize, double toSpeed) {
    return travelSeconds(lengthMetres, fromSpeed, toSpeed) - fromCellSize / 4.0 / fromSpeed -
           toCellSize / 4.0 / toSpeed;
}

// secondsBeyondCellTravel over a path's steps between neighbouring cells of different sizes, whose sub-cells
// never lie in one line: the part of path time the lower bound counts like turns.
[[nodiscard]] double connectorSeconds(const std::vector<Waypoint>& waypoints, const CellGraph& graph);

// Seconds lost turning from the unit direction in to the unit direction out, at `price` per 90 degrees, in
// proportion to the angle (none going straight on).
[[nodiscard]] double turnSecondsBetween(double inX, double inY, double outX, double outY, double price);

// Seconds lost turning at `corner` from the way in (dx, dy) to the way out: the angle between them in
// quarter turns, at the corner's cell's price per 90 degrees (none at a point in no cell).
[[nodiscard]] double turnSecondsAt(const Waypoint& corner, double inX, double inY, double outX, double outY,
                                   const CellGraph& graph);

struct PathSeconds {
    double total = 0.0;
    double turning = 0.0; // the part of it spent on turns
};

// The whole time of a path, pauses left out: travelSeconds per segment and, before leaving a point, the
// turn made there, at its cell's price per 90 degrees in proportion to the angle (none at a point in no
// cell). measurePath, cumulativeSeconds and PathClock all time a path this way, in the same order of sums.
[[nodiscard]] PathSeconds pathSeconds(const std::vector<Waypoint>& waypoints, const CellGraph& graph);

// The time from the start to reach each waypoint, pauses included. Waypoints do not store it: a large
// map's paths hold tens of millions of them, and a writer needs the times of one path at a time.
[[nodiscard]] std::vector<double> cumulativeSeconds(const CoveragePath& path, const CellGraph& graph);
// The same times at some waypoints only (`indices`, ascending), the rest not held: an exporter keeps a few
// thousand of a path's hundreds of millions of points.
[[nodiscard]] std::vector<double> cumulativeSecondsAt(const CoveragePath& path, const CellGraph& graph,
                                                      const std::vector<std::size_t>& indices);

// The seconds paused at waypoints first .. last - 1: what the cumulative seconds of `last` hold of pauses
// since `first`.
[[nodiscard]] double pausedSecondsBetween(const std::vector<PathPause>& pauses, std::size_t first,
                                          std::size_t last);

// Travel and turning from a sortie's first waypoint to its last (the charge before it not counted; the
// turn at its first waypoint counted from the way the path came in).
[[nodiscard]] double sortieSeconds(const CoveragePath& path, const Sortie& sortie, const CellGraph& graph);

// A sortie's stretch of the path as a path of its own.
[[nodiscard]] CoveragePath sortiePath(const CoveragePath& path, const Sortie& sortie);

// The longest of a robot's sorties, as sortieSeconds times them.
[[nodiscard]] double longestSortieSeconds(const CoveragePath& path, const std::vector<Sortie>& sorties,
                                          const CellGraph& graph);

struct Direction {
    double x = 0.0;
    double y = 0.0;
};
// The unit direction from a to b as measurements take it; (0, 0) when they coincide.
[[nodiscard]] Direction unitDirection(double fromX, double fromY, double toX, double toY);

// One step of a path's time as pathSeconds adds it up: the turn made at `from` from the way in
// (`direction`, which the step then sets, when it has a length) and the travel to `to`.
void addStepSeconds(PathSeconds& seconds, std::optional<Direction>& direction, const Waypoint& from,
                    const Waypoint& to, const Step& step, const CellGraph& graph);

// The longest of the paths' times: the makespan of measured paths.
[[nodiscard]] double longestPathSeconds(const std::vector<CoveragePath>& paths);

// Fills length, time (pauses included), turns and repeated visits from the waypoints. Each
// segment is travelled half at the speed of the waypoint it leaves and half at the speed of the one it
// reaches. A path whose straight runs were merged keeps the measures it had before.
void measurePath(CoveragePath& path, const CellGraph& graph);
// The length of the line through the waypoints, as measurePath measures it.
[[nodiscard]] double pathLengthMetres(const std::vector<Waypoint>& waypoints);
// Fills only the time (pauses included) and the part of it spent turning, as measurePath does: what a
// planner compares paths by before its last stage. A pass over the waypoints instead of five.
void timePath(CoveragePath& path, const CellGraph& graph);

// Whether a walk whose first waypoint is `first` begins at the robot's start; if not, the path puts the
// start point (in the first waypoint's cell) before the walk, and a closed tour returns to it.
[[nodiscard]] inline bool startIsOnWalk(const Waypoint& first, MapPoint start) {
    return std::hypot(first.x - start.x, first.y - start.y) < 1e-9;
}

// A robot's path from a walk through sub-cell centres: its start point first when the walk does not begin
// there and, for a closed tour, the way back to it at the end. Not yet measured.
[[nodiscard]] CoveragePath pathFromWalk(int robot, MapPoint start, std::vector<Waypoint> walk, bool closed);

} // namespace mcpp
