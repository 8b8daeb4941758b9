#include "core/model/SpeedEventCheck.hpp"

#include "core/model/HumanUnits.hpp"

#include <cmath>

namespace mcpp {

std::optional<SpeedEventProblem> speedEventProblem(const SpeedEvent& event, std::size_t robotCount) {
    if (!std::isfinite(event.timeSeconds) || event.timeSeconds < 0.0)
        return SpeedEventProblem{"time_s",
                                 "must be 0 s or later, got " + formatQuantity(event.timeSeconds) + " s"};
    if (event.robot < 0 || static_cast<std::size_t>(event.robot) >= robotCount)
        return SpeedEventProblem{"robot", "there is no robot " + std::to_string(event.robot) + ": the " +
                                              std::to_string(robotCount) + " robot(s) are numbered 0 to " +
                                              std::to_string(static_cast<int>(robotCount) - 1)};
    if (!std::isfinite(event.speedFactor) || event.speedFactor < 0.0 ||
        event.speedFactor > largestSpeedFactor)
        return SpeedEventProblem{"speed_factor", "must be from 0 (stopped) to " +
                                                     formatQuantity(largestSpeedFactor) + ", got " +
                                                     formatQuantity(event.speedFactor)};
    return std::nullopt;
}

} // namespace mcpp
