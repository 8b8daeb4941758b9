#include "core/coverage/PathShape.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {

void PathShape::add(double x, double y, double speedMetresPerSecond, double turnSecondsPer90Degrees) {
    ++points_;
    const double fromSpeed = lastSpeed_;
    const double cornerPrice = lastTurnPrice_;
    lastSpeed_ = speedMetresPerSecond;
    lastTurnPrice_ = turnSecondsPer90Degrees;
    if (!havePoint_) {
        havePoint_ = true;
        lastX_ = x;
        lastY_ = y;
        return;
    }
    const double dx = x - lastX_;
    const double dy = y - lastY_;
    lastX_ = x;
    lastY_ = y;
    const Step step = stepOf(dx, dy);
    const double length = step.length;
    length_ += length;
    if (fromSpeed > 0.0 && speedMetresPerSecond > 0.0)
        seconds_ += travelSeconds(length, fromSpeed, speedMetresPerSecond);
    if (length < 1e-9)
        return;
    const double ux = step.x;
    const double uy = step.y;
    if (haveDirection_) {
        const double turning = turnSecondsBetween(directionX_, directionY_, ux, uy, cornerPrice);
        seconds_ += turning;
        turningSeconds_ += turning;
    }
    if (haveDirection_ && std::abs(ux * directionY_ - uy * directionX_) +
                                  std::max(0.0, -(ux * directionX_ + uy * directionY_)) >
                              1e-6)
        ++turns_;
    directionX_ = ux;
    directionY_ = uy;
    haveDirection_ = true;
}

bool isQuicker(const PathShape& walk, const PathShape& than) {
    constexpr double sameTime = 1e-9; // relative
    if (walk.seconds() < than.seconds() * (1.0 - sameTime))
        return true;
    if (walk.seconds() > than.seconds() * (1.0 + sameTime))
        return false;
    if (walk.turns() != than.turns())
        return walk.turns() < than.turns();
    return walk.lengthMetres() < than.lengthMetres() - 1e-9;
}

} // namespace mcpp
