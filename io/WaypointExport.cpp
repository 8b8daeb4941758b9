#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/SortieLayer.hpp"
#include "io/AutopilotMission.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/StraightLine.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>

namespace mcpp::io {

namespace {

using internal::appendJsonNumber;
using internal::collinearAndBetween;

// MAVLink numbers used by QGroundControl plans and QGC WPL files.
constexpr int commandWaypoint = 16;               // MAV_CMD_NAV_WAYPOINT
constexpr int commandChangeSpeed = 178;           // MAV_CMD_DO_CHANGE_SPEED
constexpr int commandTakeoff = 22;                // MAV_CMD_NAV_TAKEOFF
constexpr int commandReturnToLaunch = 20;         // MAV_CMD_NAV_RETURN_TO_LAUNCH
constexpr int commandLand = 21;                   // MAV_CMD_NAV_LAND
constexpr int commandCameraTriggerDistance = 206; // MAV_CMD_DO_SET_CAM_TRIGG_DIST
// A fixed-wing aircraft climbs out at no less than this pitch (NAV_TAKEOFF's first parameter); a multirotor
// climbs straight up.
constexpr double fixedWingTakeoffPitchDegrees = 15.0;
constexpr int frameGlobalRelativeAltitude = 3;
constexpr int frameGlobal = 0;
constexpr int frameMission = 2;
constexpr int firmwarePx4 = 12;        // MAV_AUTOPILOT_PX4, as in QGroundControl's samples
constexpr int vehicleGroundRover = 10; // MAV_TYPE_GROUND_ROVER
constexpr int vehicleQuadrotor = 2;    // MAV_TYPE_QUADROTOR
constexpr int vehicleFixedWing = 1;    // MAV_TYPE_FIXED_WING

const CoveragePath* pathOfRobot(const Plan& plan, int robot) {
    for (const CoveragePath& path : plan.paths) {
        if (path.robot == robot)
            return &path;
    }
    return nullptr;
}

struct GeoWaypoint {
    Waypoint waypoint;
    double cumulativeSeconds = 0.0; // time from the start to reach it
    double longitude = 0.0;
    double latitude = 0.0;
};

// Every point of the mission in longitude and latitude, in one transformation; where it takes off elsewhere
// than its first point, that point's after them.
Result<std::vector<LonLat>> lonLatsOf(const ExportContext& context, const AutopilotMission& mission) {
    std::vector<MapPoint> mapPoints;
    mapPoints.reserve(mission.points.size() + 1);
    for (const Waypoint& point : mission.points)
        mapPoints.push_back({point.x, point.y});
    if (mission.takeOff)
        mapPoints.push_back(*mission.takeOff);
    return context.georeference.toWgs84(mapPoints);
}

// The mission a vehicle of these settings flies along the path.
AutopilotMission missionFlownBy(const ExportContext& context, const CoveragePath& coverage,
                                const VehicleSettings& vehicle) {
    return robotMission(context.plan, coverage, vehicle, context.settings);
}

// The robot's cache entry, its mission made.
ExportContext::MissionCache::Entry& missionEntryOf(const ExportContext& context, int robot) {
    std::shared_ptr<ExportContext::MissionCache::Entry> entry;
    {
        const std::lock_guard lock(context.missionCache->mutex);
        auto& slot = context.missionCache->entries[robot];
        if (!slot)
            slot = std::make_shared<ExportContext::MissionCache::Entry>();
        entry = slot;
    }
    std::call_once(entry->made, [&] {
        if (const CoveragePath* coverage = pathOfRobot(context.plan, robot))
            entry->mission = missionFlownBy(context, *coverage, context.vehicle(robot));
    });
    return *entry; // the cache keeps it as long as the context
}

// The robot's mission with its points' longitude and latitude.
const ExportContext::MissionCache::Entry& placedMissionOf(const ExportContext& context, int robot) {
    ExportContext::MissionCache::Entry& entry = missionEntryOf(context, robot);
    std::call_once(entry.placed, [&] {
        auto lonLats = lonLatsOf(context, entry.mission);
        if (lonLats)
            entry.lonLats = std::move(lonLats.value());
        else
            entry.placeError = lonLats.error();
    });
    return entry;
}

// Exact map coordinates as a key: the same point is the same longitude and latitude.
struct MapCoordinatesHash {
    std::size_t operator()(const std::pair<double, double>& point) const {
        return std::hash<double>{}(point.first) * 0x9e3779b97f4a7c15ULL ^ std::hash<double>{}(point.second);
    }
};

// Fills in the longitude and latitude of `points`, the path's points at `kept`. The robot's mission was made
// from the same path and placed on WGS84 once for its waypoint files: a point the mission holds takes its
// place from there, wherever the mission added points along legs or repeated a charger; the rest are
// transformed all in one.
Status placeOnWgs84(const ExportContext& context, int robot, const CoveragePath& path,
                    const std::vector<std::size_t>& kept, std::vector<GeoWaypoint>& points) {
    const ExportContext::MissionCache::Entry& mission = placedMissionOf(context, robot);
    const std::vector<Waypoint>& missionPoints = mission.mission.points;
    const std::size_t placed =
        mission.placeError.empty() ? std::min(mission.lonLats.size(), missionPoints.size()) : 0;
    std::unordered_map<std::pair<double, double>, std::size_t, MapCoordinatesHash> placedAt;
    placedAt.reserve(placed);
    for (std::size_t point = 0; point < placed; ++point)
        placedAt.emplace(std::pair{missionPoints[point].x, missionPoints[point].y}, point);
    std::vector<std::size_t> unplaced;
    std::vector<MapPoint> mapPoints;
    for (std::size_t row = 0; row < kept.size(); ++row) {
        const Waypoint& waypoint = path.waypoints[kept[row]];
        if (const auto found = placedAt.find({waypoint.x, waypoint.y}); found != placedAt.end()) {
            points[row].longitude = mission.lonLats[found->second].longitude;
            points[row].latitude = mission.lonLats[found->second].latitude;
        } else {
            unplaced.push_back(row);
            mapPoints.push_back({waypoint.x, waypoint.y});
        }
    }
    if (unplaced.empty())
        return {};
    auto lonLats = context.georeference.toWgs84(mapPoints);
    if (!lonLats)
        return Status::failure(lonLats.error());
    for (std::size_t k = 0; k < unplaced.size(); ++k) {
        points[unplaced[k]].longitude = lonLats.value()[k].longitude;
        points[unplaced[k]].latitude = lonLats.value()[k].latitude;
    }
    return {};
}

Result<std::vector<GeoWaypoint>> geoWaypoints(const ExportContext& context, int robot,
                                              const std::string& path, bool needCrs) {
    using Points = std::vector<GeoWaypoint>;
    const CoveragePath* coverage = pathOfRobot(context.plan, robot);
    if (coverage == nullptr)
        return Result<Points>::failure(path + ": the plan has no path for robot " +
                                       std::to_string(robotNumber(robot)));
    CoveragePath whole;
    coverage = &pathForWaypointFiles(*coverage, context.plan.cells, context.settings.mergeCollinear, whole);
    if (coverage->waypoints.empty())
        return Result<Points>::failure(path + ": robot " + std::to_string(robotNumber(robot)) +
                                       " has no waypoints");
    if (needCrs && !context.georeference.hasCrs()) {
        return Result<Points>::failure(path +
                                       ": the map has no CRS, so waypoints have no latitude and longitude");
    }
    const std::vector<std::size_t> kept =
        exportedWaypointIndices(*coverage, context.plan.cells, context.settings.mergeCollinear);
    const std::vector<double> seconds = cumulativeSecondsAt(*coverage, context.plan.cells, kept);
    Points points;
    points.reserve(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
        points.push_back({coverage->waypoints[kept[k]], seconds[k], std::nan(""), std::nan("")});
    if (context.georeference.hasCrs()) {
        if (Status placed = placeOnWgs84(context, robot, *coverage, kept, points); !placed)
            return Result<Points>::failure(path + ": " + placed.error());
    }
    return points;
}

// The field of view where a waypoint lies: its cell's (half the cell's side).
double fieldOfViewAt(const Plan& plan, const Waypoint& waypoint) {
    if (waypoint.cell < 0 || static_cast<std::size_t>(waypoint.cell) >= plan.cells.size())
        return 0.0;
    return plan.cells.cell(waypoint.cell).fieldOfView();
}

// The land cover where a waypoint lies: its cell's; none for a point in no cell.
std::optional<std::int32_t> landCoverOf(const CellGraph& cells, const Waypoint& waypoint) {
    if (waypoint.cell < 0 || static_cast<std::size_t>(waypoint.cell) >= cells.size())
        return std::nullopt;
    return cells.cell(waypoint.cell).classValue;
}

} // namespace

std::vector<std::size_t> exportedWaypointIndices(const CoveragePath& path, const CellGraph& cells,
                                                 bool mergeCollinear) {
    const std::vector<Waypoint>& waypoints = path.waypoints;
    std::vector<std::size_t> kept;
    if (!mergeCollinear || waypoints.size() < 3) {
        kept.resize(waypoints.size());
        std::iota(kept.begin(), kept.end(), std::size_t{0});
        return kept;
    }
    kept.push_back(0);
    for (std::size_t i = 1; i + 1 < waypoints.size(); ++i) {
        // Dropping point i is exact when the robot drives the whole of previous -> next at next's speed.
        // Most neighbouring points share a cell, and so its land cover: no need to read it.
        const bool redundant = collinearAndBetween(waypoints[kept.back()], waypoints[i], waypoints[i + 1]) &&
                               waypoints[i].speedMetresPerSecond == waypoints[i + 1].speedMetresPerSecond &&
                               (waypoints[i].cell == waypoints[i + 1].cell ||
                                landCoverOf(cells, waypoints[i]) == landCoverOf(cells, waypoints[i + 1]));
        if (!redundant)
            kept.push_back(i);
    }
    kept.push_back(waypoints.size() - 1);
    return kept;
}

const CoveragePath& pathForWaypointFiles(const CoveragePath& path, const CellGraph& cells,
                                         bool mergeCollinear, CoveragePath& whole) {
    if (mergeCollinear || !path.runsMerged())
        return path;
    whole = withEveryWaypoint(path, cells);
    return whole;
}

std::vector<Waypoint> exportedWaypoints(const CoveragePath& path, const CellGraph& cells,
                                        bool mergeCollinear) {
    std::vector<Waypoint> kept;
    for (const std::size_t index : exportedWaypointIndices(path, cells, mergeCollinear))
        kept.push_back(path.waypoints[index]);
    return kept;
}

std::vector<Waypoint> turningPoints(const CoveragePath& path) {
    if (path.waypoints.size() < 3)
        return path.waypoints;
    std::vector<Waypoint> kept{path.waypoints.front()};
    for (std::size_t i = 1; i + 1 < path.waypoints.size(); ++i) {
        if (!collinearAndBetween(kept.back(), path.waypoints[i], path.waypoints[i + 1]))
            kept.push_back(path.waypoints[i]);
    }
    kept.push_back(path.waypoints.back());
    return kept;
}

namespace {

// The mission's points from `first` to `last` with their longitude and latitude (`lonLats`: those of all the
// mission's points).
std::vector<GeoWaypoint> geoPoints(const AutopilotMission& mission, const MissionPart& part,
                                   const std::vector<LonLat>& lonLats) {
    std::vector<GeoWaypoint> points;
    points.reserve(part.last - part.first + 1);
    for (std::size_t i = part.first; i <= part.last; ++i)
        points.push_back({mission.points[i], 0.0, lonLats[i].longitude, lonLats[i].latitude});
    return points;
}

int mavlinkVehicleType(VehicleType type) {
    switch (type) {
    case VehicleType::Multirotor:
        return vehicleQuadrotor;
    case VehicleType::FixedWing:
        return vehicleFixedWing;
    case VehicleType::Rover:
        break;
    }
    return vehicleGroundRover;
}

// Degrees to eight decimals (about a millimetre), as the waypoint lists write them: an autopilot holds
// seven (MAVLink's degrees times 10^7), and the digits after them made plan files 6 % larger.
void appendDegrees(std::string& out, double degrees) {
    if (!std::isfinite(degrees)) {
        appendJsonNumber(out, degrees); // null, as JSON has no NaN
        return;
    }
    internal::appendRounded(out, degrees, 8);
}

// MAV_CMD_DO_CHANGE_SPEED's speed type: an aeroplane's autopilot flies an airspeed (0), and takes a ground
// speed (1) as the least it may fly over the ground; other vehicles are told their ground speed.
int speedType(VehicleType type) {
    return type == VehicleType::FixedWing ? 0 : 1;
}

// QGroundControl plans hold thousands of items: their text is written straight out, laid out as
// JsonValue lays out a document with its flat objects on one line (an item a line), without building the
// tree of values first, which took three quarters of the writing time.
void appendSpeedChange(std::string& out, int& jumpId, double speed, VehicleType type) {
    out += "      {\"autoContinue\": true, \"command\": " + std::to_string(commandChangeSpeed) +
           ", \"doJumpId\": " + std::to_string(jumpId++) + ", \"frame\": " + std::to_string(frameMission) +
           ", \"params\": [" + std::to_string(speedType(type)) + ", ";
    appendJsonNumber(out, speed);
    out += ", -1, 0, 0, 0, 0], \"type\": \"SimpleItem\"}";
}

// A navigation item at a place: a waypoint, or a takeoff (its first parameter the climb-out pitch).
void appendPlacedItem(std::string& out, int& jumpId, int command, double firstParameter,
                      const GeoWaypoint& point, double altitude) {
    out += "      {\"AMSLAltAboveTerrain\": null, \"Altitude\": ";
    appendJsonNumber(out, altitude);
    out += ", \"AltitudeMode\": 1, \"autoContinue\": true, \"command\": " + std::to_string(command) +
           ", \"doJumpId\": " + std::to_string(jumpId++) +
           ", \"frame\": " + std::to_string(frameGlobalRelativeAltitude) + ", \"params\": [";
    appendJsonNumber(out, firstParameter);
    out += ", 0, 0, null, ";
    appendDegrees(out, point.latitude);
    out += ", ";
    appendDegrees(out, point.longitude);
    out += ", ";
    appendJsonNumber(out, altitude);
    out += "], \"type\": \"SimpleItem\"}";
}

// The camera commands after a part's waypoint `index` of `count`: its distance between photos after the
// first, 0 (stop) after the last; none without a camera.
std::vector<double> cameraTriggersAfter(std::size_t index, std::size_t count,
                                        const VehicleSettings& vehicle) {
    std::vector<double> triggers;
    if (!(vehicle.cameraTriggerMetres > 0.0))
        return triggers;
    if (index == 0)
        triggers.push_back(vehicle.cameraTriggerMetres);
    if (index + 1 == count)
        triggers.push_back(0.0);
    return triggers;
}

// A photo every so many metres from here on, the first at once; 0 stops, with a last photo there (as
// QGroundControl's surveys start and stop the camera).
void appendCameraTrigger(std::string& out, int& jumpId, double metres) {
    out += "      {\"autoContinue\": true, \"command\": " + std::to_string(commandCameraTriggerDistance) +
           ", \"doJumpId\": " + std::to_string(jumpId++) + ", \"frame\": " + std::to_string(frameMission) +
           ", \"params\": [";
    appendJsonNumber(out, metres);
    out += ", 0, 1, 0, 0, 0, 0], \"type\": \"SimpleItem\"}";
}

void appendReturnToLaunch(std::string& out, int& jumpId) {
    out += "      {\"autoContinue\": true, \"command\": " + std::to_string(commandReturnToLaunch) +
           ", \"doJumpId\": " + std::to_string(jumpId++) + ", \"frame\": " + std::to_string(frameMission) +
           ", \"params\": [0, 0, 0, 0, 0, 0, 0], \"type\": \"SimpleItem\"}";
}

double takeoffPitch(VehicleType type) {
    return type == VehicleType::FixedWing ? fixedWingTakeoffPitchDegrees : 0.0;
}

// The items array's body: one item an element, separated as JsonValue separates them. An aircraft takes off
// at home first and returns to it at the end of every part, or lands at the part's last point (a first
// sortie ending at a charger away from the start).
std::string qGroundControlItems(const AutopilotMission& mission, const MissionPart& part,
                                const std::vector<GeoWaypoint>& points, const GeoWaypoint& home,
                                const VehicleSettings& vehicle) {
    std::string out;
    out.reserve(points.size() * 220);
    int jumpId = 1;
    const auto separate = [&] {
        if (!out.empty())
            out += ",\n";
    };
    const double altitude = waypointAltitudeMetres(vehicle);
    if (isAircraft(vehicle.type))
        appendPlacedItem(out, jumpId, commandTakeoff, takeoffPitch(vehicle.type), home, altitude);
    // cruiseSpeed is only QGroundControl's planning default: the vehicle is told its speed by an item, which
    // matters most for a part that begins mid-field.
    if (mission.commandedSpeeds[part.first] > 0.0) {
        separate();
        appendSpeedChange(out, jumpId, mission.commandedSpeeds[part.first], vehicle.type);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::size_t point = part.first + i;
        if (i > 0 && mission.changesSpeedAt(point)) {
            separate();
            appendSpeedChange(out, jumpId, mission.commandedSpeeds[point], vehicle.type);
        }
        separate();
        appendPlacedItem(out, jumpId, commandWaypoint, 0.0, points[i], altitude);
        // Photos along the part's waypoints only: none on the way out from home or back.
        for (const double metres : cameraTriggersAfter(i, points.size(), vehicle)) {
            separate();
            appendCameraTrigger(out, jumpId, metres);
        }
    }
    if (isAircraft(vehicle.type)) {
        separate();
        if (part.landsAtLast)
            appendPlacedItem(out, jumpId, commandLand, 0.0, points.back(), 0.0);
        else
            appendReturnToLaunch(out, jumpId);
    }
    return out;
}

// One QGroundControl plan: for an aircraft a takeoff, the part's first speed as an item and as its cruise
// speed, waypoints and speed changes, and for an aircraft a return to launch or a landing. Home is where the
// part takes off (AutopilotMission::homeOf): the robot's start, or the charger of its sortie.
std::string qGroundControlPlanText(const AutopilotMission& mission, const MissionPart& part,
                                   const std::vector<GeoWaypoint>& points, const GeoWaypoint& home,
                                   const VehicleSettings& vehicle) {
    const double cruise = mission.commandedSpeeds[part.first];
    const std::string items = qGroundControlItems(mission, part, points, home, vehicle);
    std::string out;
    out.reserve(items.size() + 1024);
    out += "{\n"
           "  \"fileType\": \"Plan\",\n"
           "  \"geoFence\": {\"circles\": [], \"polygons\": [], \"version\": 2},\n"
           "  \"groundStation\": \"QGroundControl\",\n"
           "  \"mission\": {\n"
           "    \"cruiseSpeed\": ";
    appendJsonNumber(out, cruise);
    out += ",\n    \"firmwareType\": " + std::to_string(firmwarePx4) +
           ",\n    \"globalPlanAltitudeMode\": 1,\n    \"hoverSpeed\": ";
    appendJsonNumber(out, cruise);
    out += ",\n    \"items\": ";
    if (items.empty()) {
        out += "[]";
    } else {
        out += "[\n";
        out += items;
        out += "\n    ]";
    }
    out += ",\n    \"plannedHomePosition\": [";
    appendDegrees(out, home.latitude);
    out += ", ";
    appendDegrees(out, home.longitude);
    out += ", 0],\n    \"vehicleType\": " + std::to_string(mavlinkVehicleType(vehicle.type)) +
           ",\n"
           "    \"version\": 2\n"
           "  },\n"
           "  \"rallyPoints\": {\"points\": [], \"version\": 2},\n"
           "  \"version\": 1\n"
           "}\n";
    return out;
}

// One QGC WPL 110 file: home (where the part takes off), for an aircraft a takeoff, the speed the part
// starts with, then waypoints and speed changes, and for an aircraft a return to launch or a landing.
std::string waypointListText(const AutopilotMission& mission, const MissionPart& part,
                             const std::vector<GeoWaypoint>& points, const GeoWaypoint& home,
                             const VehicleSettings& vehicle) {
    std::string text = "QGC WPL 110\n";
    text.reserve(points.size() * 120);
    const auto row = [&text](int index, int current, int frame, int command,
                             const std::array<double, 4>& params, double latitude, double longitude,
                             double altitude) {
        text += std::to_string(index);
        for (const int field : {current, frame, command}) {
            text += '\t';
            text += std::to_string(field);
        }
        for (const double param : params) {
            text += '\t';
            internal::appendFixed(text, param, 6);
        }
        text += '\t';
        internal::appendFixed(text, latitude, 8);
        text += '\t';
        internal::appendFixed(text, longitude, 8);
        text += '\t';
        internal::appendFixed(text, altitude, 6);
        text += "\t1\n";
    };
    const auto speedRow = [&](int index, double speed) {
        row(index, 0, frameMission, commandChangeSpeed, {double(speedType(vehicle.type)), speed, -1, 0}, 0, 0,
            0);
    };
    row(0, 1, frameGlobal, commandWaypoint, {0, 0, 0, 0}, home.latitude, home.longitude, 0.0);
    int index = 1;
    if (isAircraft(vehicle.type)) {
        row(index++, 0, frameGlobalRelativeAltitude, commandTakeoff, {takeoffPitch(vehicle.type), 0, 0, 0},
            home.latitude, home.longitude, vehicle.altitudeMetres);
    }
    if (mission.commandedSpeeds[part.first] > 0.0)
        speedRow(index++, mission.commandedSpeeds[part.first]);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::size_t point = part.first + i;
        if (i > 0 && mission.changesSpeedAt(point))
            speedRow(index++, mission.commandedSpeeds[point]);
        row(index++, 0, frameGlobalRelativeAltitude, commandWaypoint, {0, 0, 0, 0}, points[i].latitude,
            points[i].longitude, waypointAltitudeMetres(vehicle));
        for (const double metres : cameraTriggersAfter(i, points.size(), vehicle))
            row(index++, 0, frameMission, commandCameraTriggerDistance, {metres, 0, 1, 0}, 0, 0, 0);
    }
    if (isAircraft(vehicle.type) && part.landsAtLast)
        row(index, 0, frameGlobalRelativeAltitude, commandLand, {0, 0, 0, 0}, points.back().latitude,
            points.back().longitude, 0.0);
    else if (isAircraft(vehicle.type))
        row(index, 0, frameMission, commandReturnToLaunch, {0, 0, 0, 0}, 0, 0, 0);
    return text;
}

using MissionText = std::string (*)(const AutopilotMission&, const MissionPart&,
                                    const std::vector<GeoWaypoint>&, const GeoWaypoint&,
                                    const VehicleSettings&);

// One mission in one file at `path`, or, above the vehicle's item limit, in parts beside it.
Status writeMission(const AutopilotMission& mission, const std::vector<LonLat>& lonLats,
                    const std::string& path, MissionText text, const VehicleSettings& vehicle) {
    for (std::size_t part = 0; part < mission.parts.size(); ++part) {
        const MissionPart& piece = mission.parts[part];
        const GeoWaypoint home =
            mission.takeOff
                ? GeoWaypoint{mission.homeOf(piece), 0.0, lonLats.back().longitude, lonLats.back().latitude}
                : geoPoints(mission, {piece.home, piece.home}, lonLats).front();
        const std::string file = missionFilePath(path, part, mission.parts.size());
        const std::vector<GeoWaypoint> points = geoPoints(mission, piece, lonLats);
        if (auto written = internal::writeFileAtomically(
                file, text(mission, mission.parts[part], points, home, vehicle), Sync::BySystem);
            !written) {
            return written;
        }
    }
    return {};
}

// Each sortie of a robot that flies several as a mission of its own beside the whole one.
Status writeSortieMissions(const ExportContext& context, int robot, const CoveragePath& coverage,
                           const std::string& path, MissionText text) {
    const RobotSorties* sorties = sortiesOfRobot(context.plan, robot);
    if (sorties == nullptr)
        return {}; // no battery plan: files beside `path` named like sorties are not ours to remove
    if (autopilotMissionOf(context, robot).sorties > 0) {
        removeStaleSortieFiles(path, 0); // its mission's parts are its sorties
        return {};
    }
    const std::size_t count = sorties->sorties.size() < 2 ? 0 : sorties->sorties.size();
    for (std::size_t sortie = 0; sortie < count; ++sortie) {
        const CoveragePath flight = sortiePath(coverage, sorties->sorties[sortie]);
        const AutopilotMission mission =
            autopilotMission(flight, context.vehicle(robot), context.settings, context.plan.cells);
        const std::string file = missionSortiePath(path, sortie, count);
        auto lonLats = lonLatsOf(context, mission);
        if (!lonLats)
            return Status::failure(file + ": " + lonLats.error());
        if (auto written = writeMission(mission, lonLats.value(), file, text, context.vehicle(robot));
            !written)
            return written;
        removeStaleMissionFiles(file, mission.parts.size());
    }
    removeStaleSortieFiles(path, count);
    return {};
}

// The robot's mission in one file at `path`, or, above its vehicle's item limit, in parts beside it; and
// for a robot that flies several sorties, each sortie's mission too.
Status writeMissionFiles(const ExportContext& context, int robot, const std::string& path, MissionText text) {
    const CoveragePath* coverage = pathOfRobot(context.plan, robot);
    const std::string number = std::to_string(robotNumber(robot));
    if (coverage == nullptr)
        return Status::failure(path + ": the plan has no path for robot " + number);
    if (coverage->waypoints.empty())
        return Status::failure(path + ": robot " + number + " has no waypoints");
    if (!context.georeference.hasCrs())
        return Status::failure(path + ": the map has no CRS, so waypoints have no latitude and longitude");
    const ExportContext::MissionCache::Entry& entry = placedMissionOf(context, robot);
    if (!entry.placeError.empty())
        return Status::failure(path + ": " + entry.placeError);
    if (auto written = writeMission(entry.mission, entry.lonLats, path, text, context.vehicle(robot));
        !written)
        return written;
    return writeSortieMissions(context, robot, *coverage, path, text);
}

} // namespace

const AutopilotMission& autopilotMissionOf(const ExportContext& context, int robot) {
    return missionEntryOf(context, robot).mission;
}

std::string sortieFilesNote(const ExportContext& context, int robot, const std::string& path) {
    const RobotSorties* sorties = sortiesOfRobot(context.plan, robot);
    if (sorties == nullptr || sorties->sorties.size() < 2 || pathOfRobot(context.plan, robot) == nullptr ||
        autopilotMissionOf(context, robot).sorties > 0)
        return {};
    const auto name = [&](std::size_t sortie) {
        return std::filesystem::path(missionSortiePath(path, sortie, sorties->sorties.size()))
            .filename()
            .string();
    };
    const char* const makes = isAircraft(context.vehicle(robot).type) ? " flies " : " makes ";
    return context.robotName(robot) + makes + std::to_string(sorties->sorties.size()) +
           " sorties from its charger, each also written as a mission of its own (" + name(0) + " to " +
           name(sorties->sorties.size() - 1) + ")";
}

namespace {

// "538 to 607 items, home included", or "607 items, home included" when the parts are as big as one another.
std::string partSizes(const AutopilotMission& mission) {
    const auto [fewest, most] =
        std::minmax_element(mission.parts.begin(), mission.parts.end(),
                            [](const MissionPart& a, const MissionPart& b) { return a.items < b.items; });
    const std::string sizes = fewest->items == most->items
                                  ? std::to_string(most->items)
                                  : std::to_string(fewest->items) + " to " + std::to_string(most->items);
    return sizes + " items, home included";
}

// " and the turnarounds between them", " and the charges between them" for sorties, or nothing where no
// time passes between parts.
std::string betweenPartsIncluded(const VehicleSettings& vehicle, const AutopilotMission& mission) {
    if (mission.chargesBetweenSorties())
        return " and the charges between them";
    return vehicle.turnaroundSeconds > 0.0 ? " and the turnarounds between them" : "";
}

// "; the parts fly 3 h 2 min in all, the longest 24 min 10 s" ("take" for a rover), for a battery, and with
// turnarounds "; with 5 min between parts, done after 3 h 47 min" (sorties: "with 10 min at the charger
// between sorties"); nothing when a speed is unknown.
std::string longestPartNote(const VehicleSettings& vehicle, const AutopilotMission& mission) {
    const MissionFlights flights = missionFlights(mission, vehicle);
    if (!(flights.longestSeconds > 0.0))
        return {};
    const bool charges = mission.chargesBetweenSorties();
    const std::string between =
        charges ? formatDuration(mission.rechargeSeconds) + " at the charger between sorties"
                : formatDuration(vehicle.turnaroundSeconds) + " between parts";
    const std::string turnarounds =
        charges || vehicle.turnaroundSeconds > 0.0
            ? "; with " + between + ", done after " + formatDuration(flights.fieldSeconds)
            : std::string();
    const char* const take = isAircraft(vehicle.type) ? "; the parts fly " : "; the parts take ";
    const char* const trips = mission.sorties > 0 ? ", flights to and from where each takes off included"
                                                  : ", flights to and from the start included";
    return take + formatDuration(flights.totalSeconds) + " in all, the longest " +
           formatDuration(flights.longestSeconds) + (isAircraft(vehicle.type) ? trips : "") + turnarounds;
}

// Why the mission is in parts: "flies 53 sorties from its charger at its start, one part each" (or "from its
// charger, the first from its start"), or
// "has 21 345 items, more than its autopilot's 700" and/or "takes 3 h 10 min, longer than its 25 min
// flight time".
std::string splitReason(const ExportContext& context, int robot, const AutopilotMission& mission) {
    const VehicleSettings& vehicle = context.vehicle(robot);
    std::vector<std::string> reasons;
    if (const std::size_t sorties = mission.sorties; sorties > 0) {
        // Its sorties are its flights: a part each, or more under its item limit or flight time.
        const bool more = mission.parts.size() > sorties;
        return std::string(isAircraft(vehicle.type) ? "flies " : "makes ") + std::to_string(sorties) +
               (mission.firstSortieFromStart ? " sorties from its charger, the first from its start"
                                             : " sorties from its charger at its start") +
               (more ? ", some in more than one part (its item limit or flight time)" : ", one part each");
    }
    if (vehicle.maxWaypoints > 0 && mission.items > vehicle.maxWaypoints)
        reasons.push_back("has " + std::to_string(mission.items) + " items, more than its autopilot's " +
                          std::to_string(vehicle.maxWaypoints));
    const double whole = partSeconds(mission, {0, mission.points.size() - 1}, vehicle, context.plan.cells);
    if (vehicle.flightTimeSeconds > 0.0 && whole > vehicle.flightTimeSeconds)
        reasons.push_back("takes " + formatDuration(whole) +
                          (isAircraft(vehicle.type) ? " as one flight, climb and descent included" : "") +
                          ", longer than its " + formatDuration(vehicle.flightTimeSeconds) + " " +
                          batteryTimeName(vehicle.type));
    std::string reason;
    for (const std::string& each : reasons)
        reason += (reason.empty() ? "" : ", and ") + each;
    return reason;
}

// An item limit that cuts the mission into many more parts than its flight time does: said, with the parts
// the flight time alone would make, as a limit set far too low is an easy slip (autopilots hold hundreds of
// items).
std::string itemLimitNote(const ExportContext& context, int robot, const AutopilotMission& mission) {
    const VehicleSettings& vehicle = context.vehicle(robot);
    const CoveragePath* coverage = pathOfRobot(context.plan, robot);
    if (coverage == nullptr || !(vehicle.maxWaypoints > 0) || mission.items <= vehicle.maxWaypoints ||
        !(vehicle.flightTimeSeconds > 0.0))
        return {};
    VehicleSettings unlimited = vehicle;
    unlimited.maxWaypoints = 0;
    const std::size_t byFlights =
        std::max<std::size_t>(1, missionFlownBy(context, *coverage, unlimited).parts.size());
    constexpr std::size_t manyMore = 2;
    if (mission.parts.size() < manyMore * byFlights)
        return {};
    return "; its item limit (" + std::to_string(vehicle.maxWaypoints) + "), not its " +
           batteryTimeName(vehicle.type) + ", makes that many: " + std::to_string(byFlights) +
           (byFlights == 1 ? " part" : " parts") +
           " without it. Check the limit against the autopilot's (ArduPilot boards hold a few hundred to "
           "about 700 items)";
}

} // namespace

std::string splitMissionNote(const ExportContext& context, int robot, const std::string& path) {
    const AutopilotMission& mission = autopilotMissionOf(context, robot);
    if (mission.parts.size() <= 1)
        return {};
    const VehicleSettings& vehicle = context.vehicle(robot);
    const auto partName = [&](std::size_t part) {
        return std::filesystem::path(missionPartPath(path, part, mission.parts.size())).filename().string();
    };
    const std::string aircraft = !isAircraft(vehicle.type) ? ""
                                 : mission.firstSortieFromStart
                                     ? "; each takes off from the robot's charger and returns to it, but the "
                                       "first sortie, which takes off from its start and lands at the charger"
                                     : "; each takes off from the robot's start and returns to it";
    return context.robotName(robot) + "'s mission " + splitReason(context, robot, mission) + ": written in " +
           std::to_string(mission.parts.size()) + " parts of " + partSizes(mission) +
           ", each beginning where the one before it ended (" + partName(0) + " to " +
           partName(mission.parts.size() - 1) + ")" + aircraft + longestPartNote(vehicle, mission) +
           itemLimitNote(context, robot, mission);
}

namespace {

// Why an aircraft's flights do not fit: "its farthest waypoint lies 11.2 km from its start, and one flight
// at 12 m/s goes at most 6.8 km from its start and back"; the distance alone without a cruise speed. Sorties
// are measured from where each flight takes off, their charger.
std::string outOfReachNote(const VehicleSettings& vehicle, const AutopilotMission& mission) {
    double farthest = 0.0;
    if (mission.sorties > 0) {
        for (const MissionPart& part : mission.parts)
            if (exceedsFlightTime(part, vehicle))
                farthest = std::max(farthest, farthestFromHome(mission, part));
    } else {
        farthest = farthestFromHome(mission, {0, mission.points.size() - 1});
    }
    const double reach = flightReachMetres(vehicle);
    return "its farthest waypoint lies " + formatDistance(farthest) +
           (mission.sorties > 0 ? " from where its flight takes off" : " from its start") +
           (reach > 0.0 ? ", and one flight at " + formatQuantity(vehicle.cruiseSpeedMetresPerSecond, 4) +
                              " m/s goes at most " + formatDistance(reach) + " from its start and back"
                        : std::string());
}

// The files of the parts too long for one flight, so the user knows which to hold back:
// "robot_1_part_041.plan, robot_1_part_042.plan, robot_1_part_047.plan and 81 more".
std::string partsOverFlightTime(const AutopilotMission& mission, const VehicleSettings& vehicle,
                                const std::string& path) {
    constexpr std::size_t named = 3;
    std::vector<std::string> files;
    std::size_t over = 0;
    for (std::size_t part = 0; part < mission.parts.size(); ++part) {
        if (!exceedsFlightTime(mission.parts[part], vehicle))
            continue;
        if (++over <= named)
            files.push_back(
                std::filesystem::path(missionFilePath(path, part, mission.parts.size())).filename().string());
    }
    std::string text;
    for (std::size_t file = 0; file < files.size(); ++file)
        text += (file == 0                                          ? ""
                 : file + 1 == files.size() && over == files.size() ? " and "
                                                                    : ", ") +
                files[file];
    return over > files.size() ? text + " and " + std::to_string(over - files.size()) + " more" : text;
}

} // namespace

std::string flightTimeWarning(const ExportContext& context, int robot, const std::string& path) {
    const VehicleSettings& vehicle = context.vehicle(robot);
    if (!(vehicle.flightTimeSeconds > 0.0))
        return {};
    const AutopilotMission& mission = autopilotMissionOf(context, robot);
    const MissionFlights flights = missionFlights(mission, vehicle);
    if (flights.overFlightTime == 0)
        return {};
    return flightsTooLongLead(context.robotName(robot), vehicle, mission.parts.size(), flights.overFlightTime,
                              flights.longestSeconds) +
           ": " +
           (isAircraft(vehicle.type) ? outOfReachNote(vehicle, mission) : flightsTooLongCause(vehicle)) +
           " (" + partsOverFlightTime(mission, vehicle, path) +
           "; fits_flight 0 in the missions layer of a GeoPackage export). " + flightsTooLongAdvice(vehicle);
}

namespace {

// Robots whose paths take about as long can still be done hours apart: the trips to and from the start and
// the turnarounds of split missions come on top of the paths the division evened out.
std::string unevenFieldTimes(const ExportContext& context, int first, double firstSeconds, int last,
                             double lastSeconds) {
    constexpr double noticeable = 1.1;
    constexpr double minuteOrMore = 60.0;
    if (!(firstSeconds > 0.0) || lastSeconds <= firstSeconds * noticeable ||
        lastSeconds - firstSeconds < minuteOrMore)
        return {};
    const double firstPath = context.plan.paths[static_cast<std::size_t>(first)].timeSeconds;
    const double lastPath = context.plan.paths[static_cast<std::size_t>(last)].timeSeconds;
    const bool pathsEven = firstPath > 0.0 && lastPath > 0.0 &&
                           std::max(firstPath, lastPath) <= std::min(firstPath, lastPath) * noticeable;
    return "; the first, " + context.robotName(first) + ", after " + formatDuration(firstSeconds) +
           (pathsEven ? ": their paths take about as long, but the trips to and from where they take off and "
                        "the turnarounds between flights come on top"
                      : std::string());
}

} // namespace

std::optional<std::size_t> flightsOverBattery(const ExportContext& context) {
    const int robots = static_cast<int>(context.plan.paths.size());
    bool timed = false;
    std::size_t over = 0;
    for (int robot = 0; robot < robots; ++robot) {
        const VehicleSettings& vehicle = context.vehicle(robot);
        if (!(vehicle.flightTimeSeconds > 0.0))
            continue;
        timed = true;
        over += missionFlights(autopilotMissionOf(context, robot), vehicle).overFlightTime;
    }
    return timed ? std::optional<std::size_t>(over) : std::nullopt;
}

std::string fieldBoundNote(const ExportContext& context) {
    const PlanMetrics& metrics = context.plan.metrics;
    if (!(metrics.fieldLowerBoundSeconds > 0.0))
        return {};
    // Far below such a plan's time, which is then no measure of how far the plan is off.
    return "no plan making these turns brings the last robot home before " +
           formatDuration(metrics.fieldLowerBoundSeconds) + " in the field" +
           (metrics.fieldBoundWithoutTrips ? " (the work and the turnarounds alone: with flights longer than "
                                             "a battery, the trips out to the "
                                             "work and back are left out of this bound)"
                                           : std::string());
}

std::string fieldTimeNote(const ExportContext& context) {
    int last = -1;
    int first = -1;
    bool split = false;
    MissionFlights lastFlights;
    double firstSeconds = 0.0;
    for (int robot = 0; robot < static_cast<int>(context.plan.paths.size()); ++robot) {
        const AutopilotMission& mission = autopilotMissionOf(context, robot);
        if (mission.parts.empty()) // a robot without a path has no files
            continue;
        const VehicleSettings& vehicle = context.vehicle(robot);
        split = split || (mission.parts.size() > 1 && splitMissionEndsLater(vehicle));
        const MissionFlights flights = missionFlights(mission, vehicle);
        if (!(flights.fieldSeconds > 0.0))
            return {};
        if (flights.fieldSeconds > lastFlights.fieldSeconds) {
            lastFlights = flights;
            last = robot;
        }
        if (first < 0 || flights.fieldSeconds < firstSeconds) {
            firstSeconds = flights.fieldSeconds;
            first = robot;
        }
    }
    if (!split || last < 0)
        return {};
    const std::size_t over = lastFlights.overFlightTime;
    // Flights beyond one battery are counted as flown: the time is then a floor, as the warnings say.
    const std::string caveat =
        over == 0 ? std::string()
                  : " (" + std::to_string(over) +
                        " of them longer than one battery allows, counted as flown: see the warnings)";
    const VehicleSettings& vehicle = context.vehicle(last);
    const std::size_t parts = autopilotMissionOf(context, last).parts.size();
    // A rover beside split aircraft may drive its mission in one go: "its 1 parts" says nothing.
    const std::string how =
        parts == 1 ? (isAircraft(vehicle.type) ? ", in one flight" : ", in one go")
                   : ", its " + std::to_string(parts) + (isAircraft(vehicle.type) ? " flights" : " parts") +
                         betweenPartsIncluded(vehicle, autopilotMissionOf(context, last)) + " included";
    return "the last robot, " + context.robotName(last) + ", done in the field after " +
           formatDuration(lastFlights.fieldSeconds) + how + caveat +
           unevenFieldTimes(context, first, firstSeconds, last, lastFlights.fieldSeconds);
}

Status writeQGroundControlPlan(const ExportContext& context, int robot, const std::string& path) {
    return writeMissionFiles(context, robot, path, qGroundControlPlanText);
}

Status writeWaypointList(const ExportContext& context, int robot, const std::string& path) {
    return writeMissionFiles(context, robot, path, waypointListText);
}

Status writeWaypointCsv(const ExportContext& context, int robot, const std::string& path) {
    auto points = geoWaypoints(context, robot, path, false);
    if (!points)
        return Status::failure(points.error());
    std::string text = "index,x,y,lon,lat,class,speed_mps,fov_m,cumulative_s\n";
    text.reserve(points.value().size() * 100);
    // Metres and seconds to three decimals, degrees to eight: a millimetre, where every digit of a double
    // made the file half as large again.
    const auto field = [&text](double value, int decimals) {
        text += ',';
        internal::appendRounded(text, value, decimals);
    };
    const auto coordinate = [&text](double value) { // none without a CRS
        text += ',';
        if (!std::isnan(value))
            internal::appendRounded(text, value, 8);
    };
    int index = 0;
    for (const GeoWaypoint& point : points.value()) {
        const Waypoint& waypoint = point.waypoint;
        text += std::to_string(index++);
        field(waypoint.x, 3);
        field(waypoint.y, 3);
        coordinate(point.longitude);
        coordinate(point.latitude);
        text += ',';
        if (const auto landCover = landCoverOf(context.plan.cells, waypoint))
            text += std::to_string(*landCover);
        text += ',';
        internal::appendShortestFloat(text, waypoint.speedMetresPerSecond);
        text += ',';
        internal::appendShortest(text, fieldOfViewAt(context.plan, waypoint));
        field(point.cumulativeSeconds, 3);
        text += '\n';
    }
    return internal::writeFileAtomically(path, text, Sync::BySystem);
}

} // namespace mcpp::io
