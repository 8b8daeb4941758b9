#include "io/VehicleSettings.hpp"

#include "core/model/HumanUnits.hpp"

namespace mcpp::io {

std::string vehicleTypeKey(VehicleType type) {
    switch (type) {
    case VehicleType::Multirotor:
        return "multirotor";
    case VehicleType::FixedWing:
        return "fixed-wing";
    case VehicleType::Rover:
        break;
    }
    return "rover";
}

std::optional<VehicleType> vehicleTypeFromKey(const std::string& key) {
    for (const VehicleType type : {VehicleType::Rover, VehicleType::Multirotor, VehicleType::FixedWing})
        if (vehicleTypeKey(type) == key)
            return type;
    return std::nullopt;
}

std::string vehicleTypeLabel(VehicleType type) {
    switch (type) {
    case VehicleType::Multirotor:
        return "Multirotor";
    case VehicleType::FixedWing:
        return "Fixed wing";
    case VehicleType::Rover:
        break;
    }
    return "Rover";
}

VehicleSettings VehicleOverrides::over(const VehicleSettings& defaults) const {
    VehicleSettings settings = defaults;
    settings.type = type.value_or(defaults.type);
    settings.altitudeMetres = altitudeMetres.value_or(defaults.altitudeMetres);
    settings.cruiseSpeedMetresPerSecond =
        cruiseSpeedMetresPerSecond.value_or(defaults.cruiseSpeedMetresPerSecond);
    settings.maxWaypoints = maxWaypoints.value_or(defaults.maxWaypoints);
    settings.flightTimeSeconds = flightTimeSeconds.value_or(defaults.flightTimeSeconds);
    settings.turnaroundSeconds = turnaroundSeconds.value_or(defaults.turnaroundSeconds);
    settings.cameraTriggerMetres = cameraTriggerMetres.value_or(defaults.cameraTriggerMetres);
    return settings;
}

VehicleOverrides VehicleOverrides::between(const VehicleSettings& defaults, const VehicleSettings& wanted) {
    VehicleOverrides overrides;
    if (wanted.type != defaults.type)
        overrides.type = wanted.type;
    if (wanted.altitudeMetres != defaults.altitudeMetres)
        overrides.altitudeMetres = wanted.altitudeMetres;
    if (wanted.cruiseSpeedMetresPerSecond != defaults.cruiseSpeedMetresPerSecond)
        overrides.cruiseSpeedMetresPerSecond = wanted.cruiseSpeedMetresPerSecond;
    if (wanted.maxWaypoints != defaults.maxWaypoints)
        overrides.maxWaypoints = wanted.maxWaypoints;
    if (wanted.flightTimeSeconds != defaults.flightTimeSeconds)
        overrides.flightTimeSeconds = wanted.flightTimeSeconds;
    if (wanted.turnaroundSeconds != defaults.turnaroundSeconds)
        overrides.turnaroundSeconds = wanted.turnaroundSeconds;
    if (wanted.cameraTriggerMetres != defaults.cameraTriggerMetres)
        overrides.cameraTriggerMetres = wanted.cameraTriggerMetres;
    return overrides;
}

std::optional<std::string> flightTimeProblem(double seconds) {
    if (seconds == 0.0 || (seconds >= minimumFlightTimeSeconds && seconds <= maximumFlightTimeSeconds))
        return std::nullopt;
    return "must be 0 (no limit) or a flight of 1 min to 1000 h (60 to 3600000 s), not " +
           formatQuantity(seconds, 12) + " s";
}

double climbAndDescentSeconds(const VehicleSettings& vehicle) {
    if (!isAircraft(vehicle.type))
        return 0.0;
    return vehicle.altitudeMetres / climbMetresPerSecond + vehicle.altitudeMetres / descentMetresPerSecond;
}

std::optional<std::string> flightTooShortProblem(const VehicleSettings& vehicle) {
    const double upAndDown = climbAndDescentSeconds(vehicle);
    if (!(vehicle.flightTimeSeconds > 0.0) || upAndDown < vehicle.flightTimeSeconds)
        return std::nullopt;
    return "a flight of " + formatDuration(vehicle.flightTimeSeconds) +
           " leaves no time to survey: climbing to " + formatQuantity(vehicle.altitudeMetres, 4) +
           " m and coming back down take " + formatDuration(upAndDown) + " (at " +
           formatQuantity(climbMetresPerSecond, 3) + " and " + formatQuantity(descentMetresPerSecond, 3) +
           " m/s); give a longer flight time or a lower altitude";
}

std::optional<std::string> turnaroundProblem(double seconds) {
    if (seconds >= 0.0 && seconds <= maximumTurnaroundSeconds)
        return std::nullopt;
    return "must be a time on the ground of 0 to 24 h (0 to 86400 s), not " + formatQuantity(seconds, 12) +
           " s";
}

std::optional<std::string> cameraTriggerProblem(double metres) {
    if (metres == 0.0 || (metres >= minimumCameraTriggerMetres && metres <= maximumCameraTriggerMetres))
        return std::nullopt;
    return "must be 0 (no camera commands) or a distance between photos of 0.1 to 10000 m, not " +
           formatQuantity(metres, 12) + " m";
}

} // namespace mcpp::io
