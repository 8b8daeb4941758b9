#include "core/coverage/PathClock.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <cmath>

namespace mcpp {

PathClock::Step PathClock::stepTo(const Waypoint& next) const {
    Step step;
    if (waypoints_.empty())
        return step;
    const Waypoint& last = waypoints_.back();
    const double alongX = next.x - last.x;
    const double alongY = next.y - last.y;
    const double length = std::sqrt(alongX * alongX + alongY * alongY);
    if (length > 0.0 && haveDirection_)
        step.turn = turnSecondsAt(last, directionX_, directionY_, alongX / length, alongY / length, graph_);
    step.travel = travelSeconds(length, last.speedMetresPerSecond, next.speedMetresPerSecond);
    return step;
}

double PathClock::secondsToAppend(const Waypoint& next) const {
    const Step step = stepTo(next);
    return step.turn + step.travel;
}

void PathClock::append(const Waypoint& next) {
    if (!waypoints_.empty()) {
        const Step step = stepTo(next);
        elapsed_ += step.turn; // in pathSeconds' order, so both sums round alike
        elapsed_ += step.travel;
        const Direction direction = unitDirection(waypoints_.back().x, waypoints_.back().y, next.x, next.y);
        if (direction.x != 0.0 || direction.y != 0.0) {
            haveDirection_ = true;
            directionX_ = direction.x;
            directionY_ = direction.y;
        }
    }
    waypoints_.push_back(next);
}

} // namespace mcpp
