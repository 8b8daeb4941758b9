#include "core/model/BatteryEndurance.hpp"

#include "core/model/HumanUnits.hpp"

namespace mcpp::BatteryEndurance {

std::optional<std::string> problem(double seconds) {
    if (seconds >= minimumSeconds && seconds <= maximumSeconds)
        return std::nullopt;
    return "must be between " + formatQuantity(minimumSeconds) + " s and " + formatQuantity(maximumSeconds) +
           " s (" + formatDuration(maximumSeconds) + ") of travel on one charge, got " +
           formatQuantity(seconds) + " s";
}

} // namespace mcpp::BatteryEndurance
