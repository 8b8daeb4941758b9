#include "core/planners/WorkByDistance.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace mcpp {

namespace {

constexpr std::size_t distanceSteps = 512;

// How far a square of side `side` centred at (x, y) lies from the nearest start: the gap between the squares.
double leastDistance(double x, double y, double side, const std::vector<StartSquare>& starts) {
    double least = std::numeric_limits<double>::infinity();
    for (const StartSquare& start : starts)
        least = std::min(least, start.gapTo(x, y, side));
    return least;
}

double leastDistance(const Cell& cell, const std::vector<StartSquare>& starts) {
    return leastDistance(cell.centreX(), cell.centreY(), cell.size, starts);
}

} // namespace

WorkByDistance::WorkByDistance(const CellGraph& cells, std::vector<StartSquare> starts,
                               const std::function<double(int)>& workOfCell,
                               const std::vector<TurningPath>& turning) {
    if (starts.empty())
        return;
    // Two passes, the first for the farthest work, rather than a list of distances: 8 bytes a cell.
    double farthest = 0.0;
    for (int id = 0; id < static_cast<int>(cells.size()); ++id)
        if (workOfCell(id) > 0.0)
            farthest = std::max(farthest, leastDistance(cells.cell(id), starts));
    if (!(farthest > 0.0))
        return;
    stepMetres_ = farthest / static_cast<double>(distanceSteps);
    secondsBeyond_.assign(distanceSteps + 1, 0.0);
    for (int id = 0; id < static_cast<int>(cells.size()); ++id)
        if (const double work = workOfCell(id); work > 0.0) {
            // Beyond k steps for every k up to floor(distance / step): counted at the last, summed below.
            secondsBeyond_[stepOf(leastDistance(cells.cell(id), starts))] += work;
        }
    for (const TurningPath& path : turning)
        addTurns(cells, starts, path);
    for (std::size_t step = distanceSteps; step-- > 0;)
        secondsBeyond_[step] += secondsBeyond_[step + 1];
}

std::size_t WorkByDistance::stepOf(double metres) const {
    return std::min(distanceSteps, static_cast<std::size_t>(metres / stepMetres_));
}

void WorkByDistance::addTurns(const CellGraph& cells, const std::vector<StartSquare>& starts,
                              const TurningPath& turning) {
    const std::vector<Waypoint>& waypoints = turning.path->waypoints;
    std::vector<double> turns(secondsBeyond_.size(), 0.0);
    double total = 0.0;
    std::optional<Direction> wayIn;
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
        const Waypoint& corner = waypoints[i - 1];
        const Direction wayOut = unitDirection(corner.x, corner.y, waypoints[i].x, waypoints[i].y);
        if (wayOut.x == 0.0 && wayOut.y == 0.0)
            continue;
        if (wayIn) {
            const double seconds = turnSecondsAt(corner, wayIn->x, wayIn->y, wayOut.x, wayOut.y, cells);
            turns[stepOf(leastDistance(corner.x, corner.y, 0.0, starts))] += seconds;
            total += seconds;
        }
        wayIn = wayOut;
    }
    // Never more than the path's own figure, which the share's seconds hold.
    const double scale = total > turning.path->turnSeconds ? turning.path->turnSeconds / total : 1.0;
    for (std::size_t step = 0; step < turns.size(); ++step)
        secondsBeyond_[step] += turning.weight * scale * turns[step];
}

} // namespace mcpp
