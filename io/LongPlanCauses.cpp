#include "io/LongPlanCauses.hpp"

#include <algorithm>

namespace mcpp::io {

namespace {

bool everyRobotAtGroundSpeeds(const Mission& mission) {
    const std::vector<VehicleSettings> vehicles = robotVehicles(mission);
    return std::all_of(vehicles.begin(), vehicles.end(), [](const VehicleSettings& vehicle) {
        return vehicle.type == VehicleType::Rover && vehicle.cruiseSpeedMetresPerSecond <= 0.0;
    });
}

} // namespace

std::optional<LongPlanCauses> longPlanCauses(double makespanSeconds, const Mission& mission,
                                             const ClassTable& classes) {
    if (!(makespanSeconds > longPlanSeconds))
        return std::nullopt;
    LongPlanCauses causes;
    causes.wholeRaster = mission.area.empty();
    causes.groundSpeeds = everyRobotAtGroundSpeeds(mission);
    for (const LandCoverClass& landCover : classes.classes()) {
        if (!landCover.isTraversable())
            continue;
        const double speed = landCover.speedMetresPerSecond;
        const bool first = causes.fastestSpeedMetresPerSecond == 0.0;
        causes.slowestSpeedMetresPerSecond =
            first ? speed : std::min(causes.slowestSpeedMetresPerSecond, speed);
        causes.fastestSpeedMetresPerSecond = std::max(causes.fastestSpeedMetresPerSecond, speed);
    }
    // Speeds a drone would fly are no ground robot's: nothing to say of them.
    constexpr double droneSpeedMetresPerSecond = 5.0;
    causes.groundSpeeds =
        causes.groundSpeeds && causes.fastestSpeedMetresPerSecond < droneSpeedMetresPerSecond;
    if (!causes.wholeRaster && !causes.groundSpeeds)
        return std::nullopt;
    return causes;
}

} // namespace mcpp::io
