#include "core/model/SpeedEventCheck.hpp"

#include "core/model/HumanUnits.hpp"

#include <cmath>

namespace mcpp {

std::optional<SpeedEventProblem> speedEventProblem(const SpeedEvent& event, std::size_t robotCount) {
    if (!std::isfinite(event.timeSeconds) || event.timeSeconds < 0.0)
        return SpeedEventProblem{"time_s",
                                 "must be 0 s or later, got " + formatQuantity(event.timeSeconds) + " s"};
    if (event.robot < 0 || static_cast<std::size_t>(event.robot) >= robotCount) {
        const std::string robots = robotCount == 1
                                       ? "there is one robot, robot 0"
                                       : "the " + std::to_string(robotCount) + " robots are numbered 0 to " +
                                             std::to_string(robotCount - 1);
        return SpeedEventProblem{"robot",
                                 "robot " + std::to_string(event.robot) + " does not exist: " + robots};
    }
    if (!std::isfinite(event.speedFactor) || event.speedFactor < 0.0 ||
        event.speedFactor > largestSpeedFactor)
        return SpeedEventProblem{"speed_factor", "must be from 0 (stopped) to " +
                                                     formatQuantity(largestSpeedFactor) + ", got " +
                                                     formatQuantity(event.speedFactor)};
    return std::nullopt;
}

} // namespace mcpp
