#pragma once

#include <optional>
#include <string>

namespace mcpp::io {

// What kind of vehicle flies or drives a robot's waypoint files; it sets the file's vehicle type.
enum class VehicleType { Rover, Multirotor, FixedWing };

// The mission file's name of a vehicle type ("rover", "multirotor", "fixed-wing") and back.
[[nodiscard]] std::string vehicleTypeKey(VehicleType type);
[[nodiscard]] std::optional<VehicleType> vehicleTypeFromKey(const std::string& key);
// For people: "Rover", "Multirotor", "Fixed wing".
[[nodiscard]] std::string vehicleTypeLabel(VehicleType type);

// What a robot's autopilot needs in its waypoint files.
struct VehicleSettings {
    VehicleType type = VehicleType::Rover;
    double altitudeMetres = 30.0;            // waypoint altitude above home
    double cruiseSpeedMetresPerSecond = 0.0; // 0: the land-cover speeds
    // Mission items the autopilot holds, its home included (ArduPilot boards hold a few hundred to about
    // 700); a longer mission is split into consecutive parts. 0: no limit.
    int maxWaypoints = 700;
    // The longest flight one battery allows: a mission whose flight takes longer is split into parts that
    // each fit it, an aircraft's trips from its start and back included. 0: no limit.
    double flightTimeSeconds = 0.0;
    // Time on the ground between two parts of a split mission: a battery swap, the next part uploaded. It
    // adds to the robot's time in the field, not to the plan's balance. 0: not counted.
    double turnaroundSeconds = 0.0;
    // A camera told to take a photo every so many metres along each part's waypoints (a photo survey's
    // MAV_CMD_DO_SET_CAM_TRIGG_DIST, stopped at the part's last waypoint). 0: no camera commands.
    double cameraTriggerMetres = 0.0;

    friend bool operator==(const VehicleSettings&, const VehicleSettings&) = default;
};

// A robot's own values; those it leaves out come from the mission's defaults.
struct VehicleOverrides {
    std::optional<VehicleType> type;
    std::optional<double> altitudeMetres;
    std::optional<double> cruiseSpeedMetresPerSecond;
    std::optional<int> maxWaypoints;
    std::optional<double> flightTimeSeconds;
    std::optional<double> turnaroundSeconds;
    std::optional<double> cameraTriggerMetres;

    [[nodiscard]] bool empty() const {
        return !type && !altitudeMetres && !cruiseSpeedMetresPerSecond && !maxWaypoints &&
               !flightTimeSeconds && !turnaroundSeconds && !cameraTriggerMetres;
    }
    [[nodiscard]] VehicleSettings over(const VehicleSettings& defaults) const;
    // The overrides that make `wanted` from `defaults`: only the values that differ.
    [[nodiscard]] static VehicleOverrides between(const VehicleSettings& defaults,
                                                  const VehicleSettings& wanted);

    friend bool operator==(const VehicleOverrides&, const VehicleOverrides&) = default;
};

// Whether the vehicle flies: its missions then take off from home first and return to it at the end.
[[nodiscard]] constexpr bool isAircraft(VehicleType type) {
    return type != VehicleType::Rover;
}

// The altitude a robot's waypoints are given above home: a rover drives on the ground whatever its settings
// hold (a mission file's altitude is the fleet's, for its aircraft).
[[nodiscard]] constexpr double waypointAltitudeMetres(const VehicleSettings& vehicle) {
    return isAircraft(vehicle.type) ? vehicle.altitudeMetres : 0.0;
}

// What the time one battery allows is called: an aircraft's "flight time", a rover's "battery time".
[[nodiscard]] constexpr const char* batteryTimeName(VehicleType type) {
    return isAircraft(type) ? "flight time" : "battery time";
}

// Whether a mission split into parts ends later than its path takes: an aircraft flies to each part and
// back, and turnarounds wait between parts. A rover's parts without turnarounds end with its path.
[[nodiscard]] inline bool splitMissionEndsLater(const VehicleSettings& vehicle) {
    return isAircraft(vehicle.type) || vehicle.turnaroundSeconds > 0.0;
}

// Mission items every part of a mission holds besides its waypoints and speed changes: the home position
// and the speed the vehicle starts with, for an aircraft its takeoff and its return to launch, and with a
// camera the commands that start and stop its photos.
[[nodiscard]] constexpr int itemsBesideWaypoints(const VehicleSettings& vehicle) {
    return (isAircraft(vehicle.type) ? 4 : 2) + (vehicle.cameraTriggerMetres > 0.0 ? 2 : 0);
}

// The smallest item limit that leaves room, for any vehicle, for a part's items besides its waypoints and
// two waypoints with a speed change between them.
constexpr int minimumMaxWaypoints = 10;
// An item limit an autopilot can work with: none (0), or room for a mission beside its fixed items.
[[nodiscard]] constexpr bool isWorkableItemLimit(int limit) {
    return limit == 0 || limit >= minimumMaxWaypoints;
}

// The shortest flight time a vehicle may be given: below a minute no survey flight is worth a takeoff.
constexpr double minimumFlightTimeSeconds = 60.0;
constexpr double maximumFlightTimeSeconds = 3600.0 * 1000.0;
// What is wrong with a flight time, for any reader to name with its field: 0 (no limit) or 60 s to 1000 h.
[[nodiscard]] std::optional<std::string> flightTimeProblem(double seconds);

// ArduCopter's default climb and descent rates (WPNAV_SPEED_UP, WPNAV_SPEED_DN); a fixed wing climbs and
// glides down faster, so its flights come out a little long, never short.
constexpr double climbMetresPerSecond = 2.5;
constexpr double descentMetresPerSecond = 1.5;
// What an aircraft's climb to its altitude and descent back take on every flight; 0 for a rover.
[[nodiscard]] double climbAndDescentSeconds(const VehicleSettings& vehicle);
// Why the vehicle cannot survey within its flight time: climbing to its altitude and coming back down take
// all of it ("a flight of 1 min leaves no time to survey: ...").
[[nodiscard]] std::optional<std::string> flightTooShortProblem(const VehicleSettings& vehicle);

// Aircraft altitudes above home a user most likely did not mean, said as cautions, not refused: below
// the trees and roofs a survey flies over, or above what drones may fly without a permit in most
// countries (the EU's open category; 400 ft in the US).
constexpr double lowestSurveyAltitudeMetres = 5.0;
constexpr double highestAltitudeWithoutPermitMetres = 120.0;
// The same limit where it is set in feet (the US): 400 ft, not 120 m converted.
constexpr int highestAltitudeWithoutPermitFeet = 400;
// Whether the vehicle is an aircraft flying below or above those.
[[nodiscard]] constexpr bool fliesTooLow(const VehicleSettings& vehicle) {
    return isAircraft(vehicle.type) && vehicle.altitudeMetres < lowestSurveyAltitudeMetres;
}
[[nodiscard]] constexpr bool fliesAbovePermitFreeHeight(const VehicleSettings& vehicle) {
    return isAircraft(vehicle.type) && vehicle.altitudeMetres > highestAltitudeWithoutPermitMetres;
}

// The longest turnaround a vehicle may be given: a day on the ground between two parts.
constexpr double maximumTurnaroundSeconds = 24.0 * 3600.0;
// What is wrong with a turnaround time: 0 to 24 h.
[[nodiscard]] std::optional<std::string> turnaroundProblem(double seconds);

// The shortest and longest distances between two photos a camera may be given.
constexpr double minimumCameraTriggerMetres = 0.1;
constexpr double maximumCameraTriggerMetres = 10000.0;
// What is wrong with a distance between photos: 0 (no camera commands), or 0.1 m to 10 km.
[[nodiscard]] std::optional<std::string> cameraTriggerProblem(double metres);

} // namespace mcpp::io
