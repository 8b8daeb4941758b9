#pragma once

#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/parameters/PlannerChoice.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"
#include "io/Result.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::io {

// The one way a mission (raster, class table, robots, planner) becomes a planning problem, shared by batch
// mode and the window so that both read the same starts, tables and parameters and say the same things.

// The part of a mission a message is about, so each caller can name it in its own terms.
struct MissionField {
    // MissingClassesOption names the switch that treats classes without a row as obstacles, bare: it is
    // offered as advice, not blamed.
    enum class Part { Raster, Classes, MissingClassesOption, Start, StartCrs, Charger, Planner, Parameter };
    Part part = Part::Raster;
    int robot = -1;    // Start, StartCrs, Charger: the robot, counted from 0
    std::string key;   // Parameter: its key
    std::string value; // Parameter: the value advice suggests for it, empty when it names the field alone

    [[nodiscard]] static MissionField of(Part part) { return {part, -1, {}, {}}; }
    [[nodiscard]] static MissionField start(int robot) { return {Part::Start, robot, {}, {}}; }
    [[nodiscard]] static MissionField startCrs(int robot) { return {Part::StartCrs, robot, {}, {}}; }
    [[nodiscard]] static MissionField charger(int robot) { return {Part::Charger, robot, {}, {}}; }
    [[nodiscard]] static MissionField parameter(std::string key, std::string value = {}) {
        return {Part::Parameter, -1, std::move(key), std::move(value)};
    }
};
// How a caller names a field: "mission.json: robots[1].start", "--start 2", "Robot 2's start"...
using FieldNamer = std::function<std::string(const MissionField&)>;
// The fields of a mission file, as docs/mission-format.md names them; a robot's field also by the robot's
// name when it has one ("robots[1].start (beta)").
[[nodiscard]] FieldNamer missionFileFields(const std::string& missionPath,
                                           std::vector<std::string> robotNames = {});

// The raster the mission names, resolved against the mission file's folder, read with the mission's band.
[[nodiscard]] Result<LoadedRaster> loadMissionRaster(const Mission& mission, const std::string& missionPath);
// The same in two steps, for callers that name the raster and the area files apart in their messages: the
// raster alone, then the mission's area of interest (include and exclude polygons) applied to it.
[[nodiscard]] Result<LoadedRaster> loadMissionRasterAlone(const Mission& mission,
                                                          const std::string& missionPath);
[[nodiscard]] Status applyMissionArea(LoadedRaster& raster, const Mission& mission,
                                      const std::string& missionPath);

// The class table the mission plans with: its own rows and, for the values they lack, its preset's rows
// for this raster (docs/mission-format.md), every field of view classes.fov_m where it is given; checked.
[[nodiscard]] Result<ClassTable> missionClasses(const Mission& mission, const LoadedRaster& raster,
                                                const FieldNamer& names);

// Where the mission's preset lists only some of the raster's classes (and its own rows not the rest): a
// warning naming those classes and their share of the map, which are planned with generic rows.
[[nodiscard]] std::optional<std::string> presetGapWarning(const Mission& mission, const LoadedRaster& raster);

// What a start without a start_crs is measured in: the planning CRS's own units (mission files; feet for
// a CRS in feet, the UTM zone's metres for a warped geographic raster), or the raster file's own CRS
// (batch --start, longitude and latitude for a geographic raster).
enum class StartUnits { PlanningCrs, RasterFileCrs };
// Each robot's start in the planning frame (metres).
[[nodiscard]] Result<std::vector<MapPoint>> missionStarts(const Mission& mission, const LoadedRaster& raster,
                                                          StartUnits units, const FieldNamer& names);

// What a user can do about a start the planner refused whatever the raster's coordinates (on an obstacle,
// in another robot's cell), the setting named in the caller's terms: "; move it onto passable land, or ...";
// empty for other problems.
[[nodiscard]] std::string startProblemAdvice(PlanningError::Kind kind, const FieldNamer& names);
// " (robot 1 is robots[0], drone-A; robot 3 is forest)": the robots a message numbers (from 1), by their
// names and, withIndex, their place in a mission file's robots array. A robot whose name says its number
// ("Robot 3") or, without the index, has none is left out; empty when none is left.
[[nodiscard]] std::string robotsNamedIn(const std::string& message,
                                        const std::vector<std::string>& robotNames, bool withIndex);
// A plan's message as people read it, in batch mode and the window alike: the map points it names with
// their degrees (withPointsInDegrees; none without a raster), then the robots it numbers by name.
[[nodiscard]] std::string messageForPeople(const std::string& message, const LoadedRaster* raster,
                                           const std::vector<std::string>& robotNames);
// The same for a map known by its georeference and grid (an export's); without a grid, points stay as given.
[[nodiscard]] std::string messageForPeople(const std::string& message, const GeoReference& georeference,
                                           const ClassGrid* grid, const std::vector<std::string>& robotNames);
// A planning error about one robot's start or one planner parameter, the field named in the caller's terms,
// then the robots its detail numbers by name (robotsNamedIn) and, for a start, startProblemAdvice:
// "mission.json: robots[1].start (beta): ... lies in the same cell as robot 1's start (...) (robot 1 is
// robots[0], alpha); place the starts farther apart, or ..."; nothing for other errors.
[[nodiscard]] std::optional<std::string> planningErrorText(const PlanningError& error,
                                                           const FieldNamer& names,
                                                           const std::vector<std::string>& robotNames = {},
                                                           bool withIndex = false);

// Where robot `robot`'s charger, read in the CRS of its start (the raster's, in metres), was given in
// degrees: "; read as longitude -112.95, latitude 37.45 it lies on the map: give it as (327515.73,
// 4146579.4)", for the refusal of a charger outside the raster; where it was given in a CRS of its start,
// latitude first, that it is longitude first. Empty otherwise.
[[nodiscard]] std::string chargerInDegreesHint(const Mission& mission, const LoadedRaster& raster, int robot);

// Each robot's charger in the planning frame (metres), read like its start; none where it charges at its
// start.
[[nodiscard]] Result<std::vector<std::optional<MapPoint>>> missionChargers(const Mission& mission,
                                                                           const LoadedRaster& raster,
                                                                           StartUnits units,
                                                                           const FieldNamer& names);

// A robot whose start and charger are in the planning frame (as the window holds them), as a mission file
// writes it: in its start_crs where it has one that takes both points, else in the planning CRS's units
// with no start_crs. Degrees and metres are whole to a billionth, so that a point read and written back
// reads as given (7.41, not 7.4099999999999997).
[[nodiscard]] RobotSpec robotAsWritten(RobotSpec robot, const GeoReference& georeference);

// The planner's name is known and every parameter is one it declares, with a value that fits.
[[nodiscard]] Status checkPlannerChoice(const PlannerChoice& choice, const FieldNamer& names);

// Every start on a pixel robots can start from, judged as planningProblem judges them when the planner is
// not to move bad starts itself: for checking a mission once before several planners run on it. A flying
// robot (flyingRobots, by robot) may start anywhere: it takes off there.
[[nodiscard]] Status checkStarts(const LoadedRaster& raster, const ClassTable& classes,
                                 bool missingClassesAsObstacles, const std::vector<MapPoint>& starts,
                                 const FieldNamer& names, const std::vector<bool>& flyingRobots = {});

struct PreparedProblem {
    PlanningProblem problem;
    std::vector<std::string> warnings; // e.g. classes without a row treated as obstacles
};
// The problem to plan: the raster reconciled with the table (missing classes refused, or made obstacles),
// each start checked on its pixel (unless the planner is to move bad starts, or the robot flies: see
// checkStarts), the planner checked.
[[nodiscard]] Result<PreparedProblem> planningProblem(const LoadedRaster& raster, const ClassTable& classes,
                                                      bool missingClassesAsObstacles,
                                                      std::vector<MapPoint> starts,
                                                      const PlannerChoice& choice, const FieldNamer& names,
                                                      const std::vector<bool>& flyingRobots = {});

} // namespace mcpp::io
