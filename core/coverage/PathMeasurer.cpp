#include "core/coverage/PathMeasurer.hpp"

namespace mcpp {

void PathMeasurer::add(const Waypoint& waypoint) {
    if (sharedShape_ == nullptr)
        shape_.add(waypoint.x, waypoint.y);
    if (!havePrevious_) {
        havePrevious_ = true;
        previous_ = waypoint;
        return;
    }
    const Waypoint& from = previous_;
    const Step step = stepOf(waypoint.x - from.x, waypoint.y - from.y);
    addStepSeconds(seconds_, direction_, from, waypoint, step, graph_);
    if (!oneCellSize_)
        addConnector(from, waypoint, step.length);
    previous_ = waypoint;
}

void PathMeasurer::addConnector(const Waypoint& from, const Waypoint& to, double length) {
    if (from.cell == to.cell || !graph_.contains(from.cell) || !graph_.contains(to.cell))
        return;
    const Cell& a = graph_.cell(from.cell);
    const Cell& b = graph_.cell(to.cell);
    if (a.span == b.span || !graph_.areNeighbours(from.cell, to.cell))
        return;
    connectorSeconds_ +=
        secondsBeyondCellTravel(length, a.size, from.speedMetresPerSecond, b.size, to.speedMetresPerSecond);
}

void PathMeasurer::fill(CoveragePath& path) const {
    const PathShape& shape = sharedShape_ != nullptr ? *sharedShape_ : shape_;
    path.lengthMetres = shape.lengthMetres();
    path.turns = shape.turns();
    path.timeSeconds = seconds_.total + pausedSecondsBetween(path.pauses, 0, path.waypoints.size());
    path.turnSeconds = seconds_.turning;
    path.connectorSeconds = connectorSeconds_;
}

} // namespace mcpp
