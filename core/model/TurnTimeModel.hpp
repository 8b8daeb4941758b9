#pragma once

#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

namespace mcpp {

// What a turn costs. A robot slows down for a change of direction and speeds up again; the time lost is
// counted per 90 degrees of turn (a U-turn costs twice as much, a 45-degree bend half). Either a fixed
// time, or worked out from the speed: braking from v to a stop and accelerating back at a loses v / a.
struct TurnTimeModel {
    double fixedSecondsPer90Degrees = automaticParameterValue; // automatic: from speed and acceleration
    double accelerationMetresPerSecondSquared = 1.0;

    // Seconds lost by one 90-degree turn at this speed. Inline: a cell graph works it out each time it
    // makes a cell whole.
    [[nodiscard]] double secondsPer90Degrees(double speedMetresPerSecond) const {
        if (fixedSecondsPer90Degrees >= 0.0)
            return fixedSecondsPer90Degrees;
        if (!(speedMetresPerSecond > 0.0) || !(accelerationMetresPerSecondSquared > 0.0))
            return 0.0;
        return speedMetresPerSecond / accelerationMetresPerSecondSquared;
    }

    [[nodiscard]] static ParameterSpec turnSecondsParameter();
    [[nodiscard]] static ParameterSpec accelerationParameter();
    // The model from resolved parameter values; keys not given keep the defaults.
    [[nodiscard]] static TurnTimeModel from(const ParameterValues& values);
};

} // namespace mcpp
