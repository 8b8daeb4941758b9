#pragma once

#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/SpeedEvent.hpp"
#include "core/parameters/PlannerChoice.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/GeoReference.hpp"
#include "io/Result.hpp"
#include "io/VehicleSettings.hpp"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mcpp::io {

struct LoadedRaster;

struct RobotSpec {
    std::string name;
    MapPoint start;
    std::string startCrs;          // empty: the raster's CRS
    VehicleOverrides vehicle = {}; // its own autopilot settings; the rest from the mission's exports
    std::optional<double> batterySeconds = {}; // its own battery, for planners that fly on batteries
    // Where it charges, for planners that fly on batteries, in the start's CRS; none: at its start.
    std::optional<MapPoint> charger = {};

    friend bool operator==(const RobotSpec&, const RobotSpec&) = default;
};

struct ExportSettings {
    VehicleSettings vehicle; // every robot's, unless it has its own
    // A new speed is commanded in waypoint files only where the land-cover speed differs from the one in
    // force by more than this fraction of it.
    double speedTolerance = 0.1;
    // Each straight leg of a waypoint file at the slowest land-cover speed along it: speeds change only at
    // turns, and a leg needs no waypoint in its middle (fewer mission items, a longer flight).
    bool speedChangesAtTurnsOnly = false;
    bool mergeCollinear = true;
    bool densePaths = false;   // vector paths through every sub-cell centre instead of their turning points
    bool cellPolygons = false; // a polygon per cell in the GeoPackage (big on large maps)

    friend bool operator==(const ExportSettings&, const ExportSettings&) = default;
};

// Where to plan on the map: inside the include polygons (the whole map when none), outside the exclude
// polygons (no-go zones). Vector files GDAL reads; paths as written, relative to the mission's folder.
struct AreaOfInterest {
    std::string includePath;
    std::string excludePath;

    [[nodiscard]] bool empty() const { return includePath.empty() && excludePath.empty(); }
    friend bool operator==(const AreaOfInterest&, const AreaOfInterest&) = default;
};

// A mission file (docs/mission-format.md): everything needed to plan again.
struct Mission {
    int version = 2;        // the format version this mcpp writes; files of version 1 are read and upgraded
    std::string rasterPath; // as written in the file: relative to the mission file's folder when relative
    int band = 1;
    AreaOfInterest area;
    std::string preset; // used when classes is empty
    ClassTable classes;
    // The values of `classes` rows that gave no colour: they take the preset's or the raster's
    // (missionClassTable).
    std::set<std::int32_t> classesWithoutColour;
    bool missingClassesAsObstacles = false;
    // classes.fov_m: one field of view over every class, as --fov gives it (a drone camera's
    // footprint on the ground beside a ground robot's preset); applied by missionClasses.
    std::optional<double> fieldOfViewMetres;
    std::vector<RobotSpec> robots;
    std::vector<SpeedEvent> events; // robots slowing down or stopping, for planners that simulate them
    PlannerChoice planner = defaultPlannerChoice(); // every parameter of the planner, defaults filled in
    ExportSettings exports;

    friend bool operator==(const Mission&, const Mission&) = default;
};

[[nodiscard]] Result<Mission> loadMission(const std::string& path);
// A path of the mission file (raster, area files) as the program opens it: relative ones from the
// mission's folder.
[[nodiscard]] std::string resolveMissionPath(const std::string& written, const std::string& missionPath);

// Each robot's name in order, as exports name them.
[[nodiscard]] std::vector<std::string> robotNames(const Mission& mission);
// Each robot's vehicle in order: its own settings over the mission's.
[[nodiscard]] std::vector<VehicleSettings> robotVehicles(const Mission& mission);
// By robot, whether it flies (an aircraft): one may take off outside the task area
// (PlanningProblem::flyingRobots).
[[nodiscard]] std::vector<bool> flyingRobots(const Mission& mission);
// What no robot can fly with its vehicle settings (a flight too short for the climb and descent), naming the
// robots; nothing when every robot can. Batch mode and the window refuse to plan on it alike.
[[nodiscard]] std::optional<std::string> fleetFlightProblem(const Mission& mission);
// What a vehicle's flight time leaves for travel on one battery, for planners that fly on batteries: an
// aircraft's less the climb and descent every flight takes, a rover's whole; 0 without a flight time (or
// when the climb takes it all).
[[nodiscard]] double vehicleBatterySeconds(const VehicleSettings& vehicle);
// Each robot's battery in seconds in order: its own battery_s, else its vehicle's (vehicleBatterySeconds);
// 0 where it has neither (the planner's battery_s then).
[[nodiscard]] std::vector<double> robotBatteries(const Mission& mission);
// The same where the mission's planner flies on batteries; empty for the others, whose plans no battery
// shapes (a flight time changed for the waypoint files leaves their plans current).
[[nodiscard]] std::vector<double> plannerBatteries(const Mission& mission);
// Each robot's time at its charger between sorties in order: its vehicle's turnaround, as the waypoint
// files' field time counts it between flights; 0 without one (a battery planner's recharge_s then).
[[nodiscard]] std::vector<double> robotRecharges(const Mission& mission);
// The same where the mission's planner flies on batteries; empty for the others, whose plans no charging
// shapes.
[[nodiscard]] std::vector<double> plannerRecharges(const Mission& mission);
// The cruise speed the whole fleet flies at, when every robot's vehicle has the same one; 0 when none has
// one or when they differ.
[[nodiscard]] double fleetCruiseSpeed(const Mission& mission);
// Each robot's cruise speed, its own or the mission's; 0 where it takes the land cover's.
[[nodiscard]] std::vector<double> robotCruiseSpeeds(const Mission& mission);

// What a plan's times in the field depend on, where they are measured (some robot's split mission ends later
// than its path, and the planner does not fly on batteries; else nothing): each robot's vehicle and how the
// waypoint files command speeds. A plan made with other settings is out of date: its figures in the field,
// and MCPP-MLCT's division, would differ.
struct FieldTimeInputs {
    std::vector<VehicleSettings> vehicles;
    double speedTolerance = 0.0;
    bool speedChangesAtTurnsOnly = false;
    bool mergeCollinear = false;

    [[nodiscard]] bool measured() const { return !vehicles.empty(); }
    friend bool operator==(const FieldTimeInputs&, const FieldTimeInputs&) = default;
};
[[nodiscard]] FieldTimeInputs fieldTimeInputs(const Mission& mission);
// What a planning problem takes from the mission beside the map and the starts: the robots' batteries, the
// events and, when the whole fleet cruises at one speed, that speed over every passable class in place of
// the land cover's (a drone's speed does not follow the ground under it), so that plan times are the
// vehicles' (the problem's notes then say so). The one place batch and window runs fill them. The raster the
// problem was made of tells which classes take part.
void applyRobotSettings(const Mission& mission, const LoadedRaster& raster, PlanningProblem& problem);
// A preset chosen for a raster recognised as another product (warning preset-of-another-product, which
// applyRobotSettings adds to the problem's notes): also said beside a start the preset's obstacles refuse.
[[nodiscard]] std::optional<std::string> presetOfAnotherProductWarning(const Mission& mission,
                                                                       const LoadedRaster& raster);

// The same from the file's text; path names it in messages and anchors a relative raster path.
[[nodiscard]] Result<Mission> parseMission(const std::string& text, const std::string& path);
[[nodiscard]] Status saveMission(const Mission& mission, const std::string& path); // atomic
// The text saveMission writes: fixed key order, shortest round-trip numbers, so save -> load -> save is
// byte-identical.
[[nodiscard]] std::string missionToJson(const Mission& mission);
// The raster path resolved against the mission file's folder.
[[nodiscard]] std::string resolveRasterPath(const Mission& mission, const std::string& missionPath);

} // namespace mcpp::io
