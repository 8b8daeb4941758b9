#include "io/AutopilotMission.hpp"

#include "io/internal/StraightLine.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace mcpp::io {
namespace {

using internal::collinearAndBetween;

// Mission items every part has besides its waypoints and speed changes: the home position and the speed
// the vehicle starts with.
constexpr int itemsBesideWaypoints = 2;

// The speed in force at each waypoint: a new one only when it differs enough from the one before.
std::vector<double> commandedSpeeds(const std::vector<Waypoint>& waypoints, const VehicleSettings& vehicle,
                                    double speedTolerance) {
    std::vector<double> speeds(waypoints.size(), vehicle.cruiseSpeedMetresPerSecond);
    if (vehicle.cruiseSpeedMetresPerSecond > 0.0 || waypoints.empty())
        return speeds;
    double current = roundedSpeed(waypoints.front().speedMetresPerSecond);
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
        const double wanted = roundedSpeed(waypoints[i].speedMetresPerSecond);
        // A relative margin keeps a change of exactly the tolerance (1.1 after 1.0 at 10%) below it.
        if (wanted > 0.0 && std::abs(wanted - current) > speedTolerance * current * (1.0 + 1e-9))
            current = wanted;
        speeds[i] = current;
    }
    return speeds;
}

// Each straight leg flown at the slowest speed commanded along it, so that speeds change only at turns:
// never faster than a land cover allows, with no waypoint in the middle of a leg.
void slowestSpeedPerLeg(const std::vector<Waypoint>& points, std::vector<double>& speeds) {
    std::size_t legStart = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const bool legEnds =
            i + 1 == points.size() || !collinearAndBetween(points[i - 1], points[i], points[i + 1]);
        if (!legEnds)
            continue;
        const auto first = speeds.begin() + static_cast<std::ptrdiff_t>(legStart + 1);
        const auto last = speeds.begin() + static_cast<std::ptrdiff_t>(i + 1);
        std::fill(first, last, *std::min_element(first, last));
        legStart = i;
    }
}

// The points the mission keeps and their speeds, read from the whole path without copying it (a large
// map's paths hold tens of millions of points).
void keepPoints(const std::vector<Waypoint>& points, const std::vector<double>& speeds, bool mergeCollinear,
                AutopilotMission& mission) {
    const auto keep = [&](std::size_t i) {
        mission.points.push_back(points[i]);
        mission.commandedSpeeds.push_back(speeds[i]);
    };
    if (points.empty())
        return;
    keep(0);
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        // Dropping point i is exact when the segment after it is commanded the same speed.
        if (mergeCollinear && collinearAndBetween(mission.points.back(), points[i], points[i + 1]) &&
            speeds[i] == speeds[i + 1])
            continue;
        keep(i);
    }
    if (points.size() > 1)
        keep(points.size() - 1);
}

double flightSeconds(const AutopilotMission& mission) {
    double seconds = 0.0;
    for (std::size_t i = 1; i < mission.points.size(); ++i) {
        const double speed = mission.commandedSpeeds[i];
        if (!(speed > 0.0))
            return 0.0;
        const Waypoint& from = mission.points[i - 1];
        const Waypoint& to = mission.points[i];
        seconds += std::hypot(to.x - from.x, to.y - from.y) / speed;
    }
    return seconds;
}

int itemsOf(const AutopilotMission& mission, std::size_t first, std::size_t last) {
    int items = itemsBesideWaypoints + 1;
    for (std::size_t point = first + 1; point <= last; ++point)
        items += mission.changesSpeedAt(point) ? 2 : 1;
    return items;
}

void splitIntoParts(AutopilotMission& mission, int maxWaypoints) {
    const std::size_t count = mission.points.size();
    mission.items = count == 0 ? 0 : itemsOf(mission, 0, count - 1);
    if (count == 0)
        return;
    if (maxWaypoints <= 0 || mission.items <= maxWaypoints || count < 2) {
        mission.parts.push_back({0, count - 1, mission.items});
        return;
    }
    MissionPart part{0, 0, itemsBesideWaypoints + 1};
    for (std::size_t point = 1; point < count; ++point) {
        const int added = mission.changesSpeedAt(point) ? 2 : 1;
        if (part.items + added > maxWaypoints && part.last > part.first) {
            mission.parts.push_back(part);
            part = {part.last, part.last, itemsBesideWaypoints + 1};
        }
        part.last = point;
        part.items += added;
    }
    mission.parts.push_back(part);
}

} // namespace

double roundedSpeed(double metresPerSecond) {
    if (!(metresPerSecond > 0.0) || !std::isfinite(metresPerSecond))
        return 0.0;
    const int digitsBeforePoint = static_cast<int>(std::floor(std::log10(metresPerSecond))) + 1;
    const int decimals = 2 - digitsBeforePoint;
    // Divide by a power of ten rather than multiply by its inverse, so that 0.32 comes out as 0.32.
    if (decimals > 0) {
        const double scale = std::pow(10.0, decimals);
        return std::round(metresPerSecond * scale) / scale;
    }
    const double scale = std::pow(10.0, -decimals);
    return std::round(metresPerSecond / scale) * scale;
}

AutopilotMission autopilotMission(const CoveragePath& path, const VehicleSettings& vehicle,
                                  const ExportSettings& settings) {
    AutopilotMission mission;
    std::vector<double> speeds = commandedSpeeds(path.waypoints, vehicle, settings.speedTolerance);
    if (settings.speedChangesAtTurnsOnly)
        slowestSpeedPerLeg(path.waypoints, speeds);
    keepPoints(path.waypoints, speeds, settings.mergeCollinear, mission);
    splitIntoParts(mission, vehicle.maxWaypoints);
    mission.seconds = flightSeconds(mission);
    return mission;
}

std::string missionPartPath(const std::string& path, std::size_t part) {
    const std::filesystem::path file(path);
    const std::string name =
        file.stem().string() + "_part_" + std::to_string(part + 1) + file.extension().string();
    return (file.parent_path() / name).string();
}

} // namespace mcpp::io
