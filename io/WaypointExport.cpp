#include "io/PlanExport.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/TextFiles.hpp"

#include <cmath>

namespace mcpp::io {

namespace {

using internal::JsonValue;

// MAVLink numbers used by QGroundControl plans and QGC WPL files.
constexpr int commandWaypoint = 16;     // MAV_CMD_NAV_WAYPOINT
constexpr int commandChangeSpeed = 178; // MAV_CMD_DO_CHANGE_SPEED
constexpr int frameGlobalRelativeAltitude = 3;
constexpr int frameGlobal = 0;
constexpr int frameMission = 2;
constexpr int firmwarePx4 = 12;        // MAV_AUTOPILOT_PX4, as in QGroundControl's samples
constexpr int vehicleGroundRover = 10; // MAV_TYPE_GROUND_ROVER

const CoveragePath* pathOfRobot(const Plan& plan, int robot) {
    for (const CoveragePath& path : plan.paths) {
        if (path.robot == robot)
            return &path;
    }
    return nullptr;
}

struct GeoWaypoint {
    Waypoint waypoint;
    double longitude = 0.0;
    double latitude = 0.0;
};

Result<std::vector<GeoWaypoint>> geoWaypoints(const ExportContext& context, int robot,
                                              const std::string& path, bool needCrs) {
    using Points = std::vector<GeoWaypoint>;
    const CoveragePath* coverage = pathOfRobot(context.plan, robot);
    if (coverage == nullptr)
        return Result<Points>::failure(path + ": the plan has no path for robot " +
                                       std::to_string(robotNumber(robot)));
    if (coverage->waypoints.empty())
        return Result<Points>::failure(path + ": robot " + std::to_string(robotNumber(robot)) +
                                       " has no waypoints");
    if (needCrs && !context.georeference.hasCrs()) {
        return Result<Points>::failure(path +
                                       ": the map has no CRS, so waypoints have no latitude and longitude");
    }
    Points points;
    for (const Waypoint& waypoint : exportedWaypoints(*coverage, context.settings.mergeCollinear)) {
        GeoWaypoint point{waypoint, std::nan(""), std::nan("")};
        if (context.georeference.hasCrs()) {
            auto lonLat = context.georeference.toWgs84({waypoint.x, waypoint.y});
            if (!lonLat)
                return Result<Points>::failure(path + ": " + lonLat.error());
            point.longitude = lonLat.value().longitude;
            point.latitude = lonLat.value().latitude;
        }
        points.push_back(point);
    }
    return points;
}

// The field of view where a waypoint lies: its cell's (half the cell's side).
double fieldOfViewAt(const Plan& plan, const Waypoint& waypoint) {
    if (waypoint.cell < 0 || static_cast<std::size_t>(waypoint.cell) >= plan.cells.size())
        return 0.0;
    return plan.cells.cell(waypoint.cell).fieldOfView();
}

// The speed a robot is told to drive on the segment ending at this waypoint.
double commandedSpeed(const ExportContext& context, const Waypoint& waypoint) {
    return context.settings.cruiseSpeedMetresPerSecond > 0.0 ? context.settings.cruiseSpeedMetresPerSecond
                                                             : waypoint.speedMetresPerSecond;
}

bool collinearAndBetween(const Waypoint& a, const Waypoint& b, const Waypoint& c) {
    const double abX = b.x - a.x, abY = b.y - a.y, acX = c.x - a.x, acY = c.y - a.y;
    const double lengthAc = std::hypot(acX, acY);
    if (lengthAc == 0.0)
        return false;
    const double cross = abX * acY - abY * acX;
    const double tolerance = 1e-9 * lengthAc * std::max(lengthAc, 1.0);
    if (std::abs(cross) > tolerance)
        return false;
    const double along = (abX * acX + abY * acY) / (lengthAc * lengthAc);
    return along > 0.0 && along < 1.0;
}

std::string fixed(double value, int decimals) {
    return internal::formatFixed(value, decimals);
}

} // namespace

std::vector<Waypoint> exportedWaypoints(const CoveragePath& path, bool mergeCollinear) {
    if (!mergeCollinear || path.waypoints.size() < 3)
        return path.waypoints;
    std::vector<Waypoint> kept{path.waypoints.front()};
    for (std::size_t i = 1; i + 1 < path.waypoints.size(); ++i) {
        const Waypoint& current = path.waypoints[i];
        const Waypoint& next = path.waypoints[i + 1];
        // Dropping `current` is exact when the robot drives the whole of previous -> next at next's speed.
        const bool redundant = collinearAndBetween(kept.back(), current, next) &&
                               current.speedMetresPerSecond == next.speedMetresPerSecond &&
                               current.classValue == next.classValue;
        if (!redundant)
            kept.push_back(current);
    }
    kept.push_back(path.waypoints.back());
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

Status writeQGroundControlPlan(const ExportContext& context, int robot, const std::string& path) {
    auto points = geoWaypoints(context, robot, path, true);
    if (!points)
        return Status::failure(points.error());
    const double altitude = context.settings.altitudeMetres;
    const GeoWaypoint& home = points.value().front();

    JsonValue items = JsonValue::array();
    int jumpId = 1;
    double currentSpeed = commandedSpeed(context, home.waypoint);
    for (std::size_t i = 0; i < points.value().size(); ++i) {
        const GeoWaypoint& point = points.value()[i];
        const double speed = commandedSpeed(context, point.waypoint);
        if (i > 0 && speed != currentSpeed && speed > 0.0) {
            // Land-cover speeds change along the path: tell the vehicle before it drives the segment.
            JsonValue& change = items.push(JsonValue::object());
            change.add("autoContinue", true);
            change.add("command", commandChangeSpeed);
            change.add("doJumpId", jumpId++);
            change.add("frame", frameMission);
            JsonValue& params = change.add("params", JsonValue::array());
            for (const double value : {1.0, speed, -1.0, 0.0, 0.0, 0.0, 0.0})
                params.push(value);
            change.add("type", "SimpleItem");
            currentSpeed = speed;
        }
        JsonValue& item = items.push(JsonValue::object());
        item.add("AMSLAltAboveTerrain", JsonValue());
        item.add("Altitude", altitude);
        item.add("AltitudeMode", 1);
        item.add("autoContinue", true);
        item.add("command", commandWaypoint);
        item.add("doJumpId", jumpId++);
        item.add("frame", frameGlobalRelativeAltitude);
        JsonValue& params = item.add("params", JsonValue::array());
        params.push(0);
        params.push(0);
        params.push(0);
        params.push(JsonValue());
        params.push(point.latitude);
        params.push(point.longitude);
        params.push(altitude);
        item.add("type", "SimpleItem");
    }

    const double cruise = commandedSpeed(context, home.waypoint);
    JsonValue root = JsonValue::object();
    root.add("fileType", "Plan");
    JsonValue& fence = root.add("geoFence", JsonValue::object());
    fence.add("circles", JsonValue::array());
    fence.add("polygons", JsonValue::array());
    fence.add("version", 2);
    root.add("groundStation", "QGroundControl");
    JsonValue& mission = root.add("mission", JsonValue::object());
    mission.add("cruiseSpeed", cruise);
    mission.add("firmwareType", firmwarePx4);
    mission.add("globalPlanAltitudeMode", 1);
    mission.add("hoverSpeed", cruise);
    mission.add("items", std::move(items));
    JsonValue& homePosition = mission.add("plannedHomePosition", JsonValue::array());
    homePosition.push(home.latitude);
    homePosition.push(home.longitude);
    homePosition.push(0.0);
    mission.add("vehicleType", vehicleGroundRover);
    mission.add("version", 2);
    JsonValue& rally = root.add("rallyPoints", JsonValue::object());
    rally.add("points", JsonValue::array());
    rally.add("version", 2);
    root.add("version", 1);
    return internal::writeFileAtomically(path, root.toText());
}

Status writeWaypointList(const ExportContext& context, int robot, const std::string& path) {
    auto points = geoWaypoints(context, robot, path, true);
    if (!points)
        return Status::failure(points.error());
    const auto row = [](int index, int current, int frame, int command, const std::array<double, 4>& params,
                        double latitude, double longitude, double altitude) {
        std::string text = std::to_string(index) + "\t" + std::to_string(current) + "\t" +
                           std::to_string(frame) + "\t" + std::to_string(command);
        for (const double param : params)
            text += "\t" + fixed(param, 6);
        return text + "\t" + fixed(latitude, 8) + "\t" + fixed(longitude, 8) + "\t" + fixed(altitude, 6) +
               "\t1\n";
    };
    const GeoWaypoint& home = points.value().front();
    std::string text = "QGC WPL 110\n";
    text += row(0, 1, frameGlobal, commandWaypoint, {0, 0, 0, 0}, home.latitude, home.longitude, 0.0);
    int index = 1;
    double currentSpeed = commandedSpeed(context, home.waypoint);
    for (std::size_t i = 0; i < points.value().size(); ++i) {
        const GeoWaypoint& point = points.value()[i];
        const double speed = commandedSpeed(context, point.waypoint);
        if (i > 0 && speed != currentSpeed && speed > 0.0) {
            text +=
                row(index++, 0, frameGlobalRelativeAltitude, commandChangeSpeed, {1, speed, -1, 0}, 0, 0, 0);
            currentSpeed = speed;
        }
        text += row(index++, 0, frameGlobalRelativeAltitude, commandWaypoint, {0, 0, 0, 0}, point.latitude,
                    point.longitude, context.settings.altitudeMetres);
    }
    return internal::writeFileAtomically(path, text);
}

Status writeWaypointCsv(const ExportContext& context, int robot, const std::string& path) {
    auto points = geoWaypoints(context, robot, path, false);
    if (!points)
        return Status::failure(points.error());
    std::string text = "index,x,y,lon,lat,class,speed_mps,fov_m,cumulative_s\n";
    int index = 0;
    for (const GeoWaypoint& point : points.value()) {
        const Waypoint& waypoint = point.waypoint;
        const auto coordinate = [](double value) {
            return std::isnan(value) ? std::string() : internal::formatShortest(value);
        };
        text += std::to_string(index++) + "," + internal::formatShortest(waypoint.x) + "," +
                internal::formatShortest(waypoint.y) + "," + coordinate(point.longitude) + "," +
                coordinate(point.latitude) + "," + std::to_string(waypoint.classValue) + "," +
                internal::formatShortest(waypoint.speedMetresPerSecond) + "," +
                internal::formatShortest(fieldOfViewAt(context.plan, waypoint)) + "," +
                internal::formatShortest(waypoint.cumulativeSeconds) + "\n";
    }
    return internal::writeFileAtomically(path, text);
}

} // namespace mcpp::io
