#pragma once

#include "core/model/SpeedEvent.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace mcpp {

// What is wrong with an event, by its field as mission files name it ("time_s", "robot", "speed_factor").
struct SpeedEventProblem {
    std::string field;
    std::string detail;
};

// The most a speed factor may be: a robot twenty times faster than its land-cover speeds is a typing slip.
inline constexpr double largestSpeedFactor = 20.0;

// Nothing when the event can happen to one of `robotCount` robots.
[[nodiscard]] std::optional<SpeedEventProblem> speedEventProblem(const SpeedEvent& event,
                                                                 std::size_t robotCount);

} // namespace mcpp
