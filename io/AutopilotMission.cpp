#include "io/AutopilotMission.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/StraightLine.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

namespace mcpp::io {
namespace {

using internal::collinearAndBetween;

// A commanded speed along a path as steps: each holds from its first waypoint up to the next step's. A step
// begins only where the land cover's speed changes, at most once a cell (two waypoints): a large map's path
// holds tens of millions of waypoints, and a speed per waypoint took 8 bytes each (370 MB for one robot on
// a 69 M-cell map).
struct SpeedStep {
    std::size_t first = 0;
    double speed = 0.0;
};
using SpeedSteps = std::vector<SpeedStep>; // by first waypoint, ascending; the first step begins at 0

// Reads the speed of waypoints taken in ascending order.
class SpeedCursor {
  public:
    explicit SpeedCursor(const SpeedSteps& steps) : steps_(steps) {}
    [[nodiscard]] double at(std::size_t waypoint) {
        while (next_ < steps_.size() && steps_[next_].first <= waypoint)
            speed_ = steps_[next_++].speed;
        return speed_;
    }

  private:
    const SpeedSteps& steps_;
    std::size_t next_ = 0;
    double speed_ = 0.0;
};

// The commanded speed along the path, as steps: a new one only when it differs enough from the one before.
SpeedSteps commandedSpeeds(const std::vector<Waypoint>& waypoints, const VehicleSettings& vehicle,
                           double speedTolerance) {
    SpeedSteps steps{{0, vehicle.cruiseSpeedMetresPerSecond}};
    if (vehicle.cruiseSpeedMetresPerSecond > 0.0 || waypoints.empty())
        return steps;
    double current = roundedSpeed(waypoints.front().speedMetresPerSecond);
    steps.front().speed = current;
    // Runs of waypoints share a land cover's speed: rounded once a run (a logarithm and a power each time).
    float lastSpeed = waypoints.front().speedMetresPerSecond;
    double wanted = current;
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
        if (waypoints[i].speedMetresPerSecond == lastSpeed)
            continue;
        lastSpeed = waypoints[i].speedMetresPerSecond;
        wanted = roundedSpeed(lastSpeed);
        // A relative margin keeps a change of exactly the tolerance (1.1 after 1.0 at 10%) below it.
        if (wanted > 0.0 && std::abs(wanted - current) > speedTolerance * current * (1.0 + 1e-9)) {
            current = wanted;
            steps.push_back({i, current});
        }
    }
    return steps;
}

// The slowest land-cover speed of the waypoints from first to last, rounded down: no segment between them
// is then driven faster than its land cover allows.
double slowestSpeed(const std::vector<Waypoint>& waypoints, std::size_t first, std::size_t last) {
    float slowest = 0.0F;
    for (std::size_t i = first; i <= last; ++i) {
        const float speed = waypoints[i].speedMetresPerSecond;
        if (speed > 0.0F && (slowest == 0.0F || speed < slowest))
            slowest = speed;
    }
    return roundedDownSpeed(internal::decimalDouble(slowest)); // 0.7F as 0.7, not 0.69999998807907
}

// Each straight leg at the slowest speed along it, so that speeds change only at turns, with no waypoint in
// the middle of a leg. The tolerance only keeps a slower speed into a leg that allows a little more, never
// the reverse. A leg's speed holds from the waypoint after its start to its end; the first leg's from the
// path's start.
SpeedSteps slowestSpeedPerLeg(const std::vector<Waypoint>& waypoints, double speedTolerance) {
    SpeedSteps steps{{0, 0.0}};
    double current = 0.0;
    std::size_t legStart = 0;
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
        const bool legEnds = i + 1 == waypoints.size() ||
                             !collinearAndBetween(waypoints[i - 1], waypoints[i], waypoints[i + 1]);
        if (!legEnds)
            continue;
        const double slowest = slowestSpeed(waypoints, legStart, i);
        if (current == 0.0 || slowest < current || slowest > current * (1.0 + speedTolerance) * (1.0 + 1e-9))
            current = slowest;
        if (legStart == 0)
            steps.front().speed = current;
        else if (current != steps.back().speed)
            steps.push_back({legStart + 1, current});
        legStart = i;
    }
    return steps;
}

// The points the mission keeps and their speeds, read from the whole path without copying it (a large
// map's paths hold tens of millions of points).
void keepPoints(const std::vector<Waypoint>& points, const SpeedSteps& speeds, bool mergeCollinear,
                AutopilotMission& mission) {
    SpeedCursor speedHere(speeds);
    SpeedCursor speedNext(speeds);
    const auto keep = [&](std::size_t i) {
        mission.points.push_back(points[i]);
        mission.commandedSpeeds.push_back(speedHere.at(i));
    };
    if (points.empty())
        return;
    keep(0);
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        // Dropping point i is exact when the segment after it is commanded the same speed.
        if (mergeCollinear && collinearAndBetween(mission.points.back(), points[i], points[i + 1]) &&
            speedHere.at(i) == speedNext.at(i + 1))
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

// The parts a mission splits into when each holds at most `capacity` items, filled one after the other.
std::vector<MissionPart> partsFilledUpTo(const AutopilotMission& mission, int capacity, int beside) {
    std::vector<MissionPart> parts;
    MissionPart part{0, 0, beside + 1};
    for (std::size_t point = 1; point < mission.points.size(); ++point) {
        const int added = mission.changesSpeedAt(point) ? 2 : 1;
        if (part.items + added > capacity && part.last > part.first) {
            parts.push_back(part);
            part = {part.last, part.last, beside + 1};
        }
        part.last = point;
        part.items += added;
    }
    parts.push_back(part);
    return parts;
}

// As few parts as the limit allows, as even as they can be: the smallest capacity that needs no more parts
// than filling each to the limit does. Filled to the limit alone, the last part could hold three items.
void splitIntoParts(AutopilotMission& mission, int maxWaypoints, int beside) {
    const std::size_t count = mission.points.size();
    if (count == 0)
        return;
    mission.items = beside + 1;
    for (std::size_t point = 1; point < count; ++point)
        mission.items += mission.changesSpeedAt(point) ? 2 : 1;
    if (maxWaypoints <= 0 || mission.items <= maxWaypoints || count < 2) {
        mission.parts.push_back({0, count - 1, mission.items});
        return;
    }
    const std::size_t fewest = partsFilledUpTo(mission, maxWaypoints, beside).size();
    int tooSmall = beside + 2; // two waypoints with a speed change between them do not fit
    int enough = maxWaypoints; // fits in the fewest parts
    while (enough - tooSmall > 1) {
        const int capacity = tooSmall + (enough - tooSmall) / 2;
        if (partsFilledUpTo(mission, capacity, beside).size() <= fewest)
            enough = capacity;
        else
            tooSmall = capacity;
    }
    mission.parts = partsFilledUpTo(mission, enough, beside);
}

} // namespace

double roundedDownSpeed(double metresPerSecond) {
    if (!(metresPerSecond > 0.0) || !std::isfinite(metresPerSecond))
        return 0.0;
    const int decimals = 1 - static_cast<int>(std::floor(std::log10(metresPerSecond)));
    const double scale = std::pow(10.0, std::abs(decimals));
    // A hair above the product, so that 0.29 * 100 = 28.999999999999996 still rounds down to 29.
    const double down = decimals > 0 ? std::floor(metresPerSecond * scale * (1.0 + 1e-12)) / scale
                                     : std::floor(metresPerSecond / scale * (1.0 + 1e-12)) * scale;
    return down > 0.0 ? down : metresPerSecond;
}

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
    const bool byLeg = settings.speedChangesAtTurnsOnly && !(vehicle.cruiseSpeedMetresPerSecond > 0.0);
    const SpeedSteps speeds = byLeg ? slowestSpeedPerLeg(path.waypoints, settings.speedTolerance)
                                    : commandedSpeeds(path.waypoints, vehicle, settings.speedTolerance);
    keepPoints(path.waypoints, speeds, settings.mergeCollinear, mission);
    splitIntoParts(mission, vehicle.maxWaypoints, itemsBesideWaypoints(vehicle.type));
    const double flight = flightSeconds(mission);
    // Turns are made at the same points, so they cost what the plan priced them at.
    mission.seconds = flight > 0.0 ? flight + path.turnSeconds : 0.0;
    return mission;
}

double partSeconds(const AutopilotMission& mission, const MissionPart& part, const VehicleSettings& vehicle,
                   const CellGraph& cells) {
    // The flight's points and the speed commanded on the leg into each.
    std::vector<std::pair<Waypoint, double>> flight;
    const bool fromHome = isAircraft(vehicle.type);
    if (fromHome)
        flight.emplace_back(mission.points.front(), 0.0);
    for (std::size_t point = part.first; point <= part.last; ++point)
        flight.emplace_back(mission.points[point], mission.commandedSpeeds[point]);
    if (fromHome)
        flight.emplace_back(mission.points.front(), mission.commandedSpeeds[part.last]);
    double seconds = 0.0;
    std::optional<std::pair<double, double>> heading; // of the last leg of non-zero length
    for (std::size_t i = 1; i < flight.size(); ++i) {
        const Waypoint& from = flight[i - 1].first;
        const Waypoint& to = flight[i].first;
        const double dx = to.x - from.x;
        const double dy = to.y - from.y;
        const double length = std::hypot(dx, dy);
        if (length == 0.0)
            continue;
        if (!(flight[i].second > 0.0))
            return 0.0;
        seconds += length / flight[i].second;
        if (heading)
            seconds += turnSecondsAt(from, heading->first, heading->second, dx, dy, cells);
        heading = std::make_pair(dx, dy);
    }
    return seconds;
}

MissionSize missionSize(const CoveragePath& path, const CellGraph& cells, const VehicleSettings& vehicle,
                        const ExportSettings& settings) {
    CoveragePath whole;
    const AutopilotMission mission = autopilotMission(
        pathForWaypointFiles(path, cells, settings.mergeCollinear, whole), vehicle, settings);
    return {mission.items, mission.parts.size()};
}

std::string missionPartPath(const std::string& path, std::size_t part) {
    const std::filesystem::path file(path);
    const std::string name =
        file.stem().string() + "_part_" + std::to_string(part + 1) + file.extension().string();
    return (file.parent_path() / name).string();
}

std::string missionSortiePath(const std::string& path, std::size_t sortie) {
    const std::filesystem::path file(path);
    const std::string name =
        file.stem().string() + "_sortie_" + std::to_string(sortie + 1) + file.extension().string();
    return (file.parent_path() / name).string();
}

bool removeStaleMissionFiles(const std::string& path, std::size_t parts) {
    std::error_code code;
    bool removed = parts > 1 && std::filesystem::remove(path, code);
    for (std::size_t part = parts > 1 ? parts : 0; std::filesystem::remove(missionPartPath(path, part), code);
         ++part)
        removed = true;
    return removed;
}

void removeStaleSortieFiles(const std::string& path, std::size_t written) {
    std::error_code code;
    for (std::size_t sortie = written;; ++sortie) {
        const std::string file = missionSortiePath(path, sortie);
        const bool removed = std::filesystem::remove(file, code);
        if (!removeStaleMissionFiles(file, 0) && !removed)
            break;
    }
}

} // namespace mcpp::io
