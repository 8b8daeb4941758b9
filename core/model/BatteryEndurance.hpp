#pragma once

#include <optional>
#include <string>

// The range a robot's battery endurance may take: one rule for the planner's battery_s, a robot's own
// battery in mission files and the robot table of the window.
namespace mcpp::BatteryEndurance {

inline constexpr double minimumSeconds = 1.0;
inline constexpr double maximumSeconds = 1e7;

// Nothing when the endurance is allowed, else why not, in words ("must be between 1 s and ...").
[[nodiscard]] std::optional<std::string> problem(double seconds);

} // namespace mcpp::BatteryEndurance
