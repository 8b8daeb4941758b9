#include "io/MissionInputs.hpp"

#include "core/model/HumanUnits.hpp"
#include "core/model/NameSuggestion.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/RobotNumbers.hpp"
#include "core/model/StartPointCheck.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/AreaOfInterest.hpp"
#include "io/ClassTableSources.hpp"
#include "io/PointsInDegrees.hpp"
#include "io/internal/ClassTablePresets.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace mcpp::io {
namespace {

using Part = MissionField::Part;

std::string robotField(int robot, const char* field, const std::vector<std::string>& names) {
    const auto index = static_cast<std::size_t>(robot);
    const bool named = robot >= 0 && index < names.size() && !names[index].empty();
    return "robots[" + std::to_string(robot) + "]." + field + (named ? " (" + names[index] + ")" : "");
}

} // namespace

FieldNamer missionFileFields(const std::string& missionPath, std::vector<std::string> robotNames) {
    return [missionPath, names = std::move(robotNames)](const MissionField& field) {
        switch (field.part) {
        case Part::Raster:
            return missionPath + ": raster";
        case Part::Classes:
            return missionPath + ": classes";
        case Part::MissingClassesOption:
            return std::string("classes.missing_as_obstacles");
        case Part::Start:
            return missionPath + ": " + robotField(field.robot, "start", names);
        case Part::StartCrs:
            return missionPath + ": " + robotField(field.robot, "start_crs", names);
        case Part::Charger:
            return missionPath + ": " + robotField(field.robot, "charger", names);
        case Part::Planner:
            return missionPath + ": planner.name";
        case Part::Parameter:
            break;
        }
        return missionPath + ": planner.parameters." + field.key +
               (field.value.empty() ? std::string() : "=" + field.value);
    };
}

Result<LoadedRaster> loadMissionRaster(const Mission& mission, const std::string& missionPath) {
    auto raster = loadMissionRasterAlone(mission, missionPath);
    if (!raster)
        return raster;
    if (Status area = applyMissionArea(raster.value(), mission, missionPath); !area)
        return Result<LoadedRaster>::failure(area.error());
    return raster;
}

Result<LoadedRaster> loadMissionRasterAlone(const Mission& mission, const std::string& missionPath) {
    RasterLoadOptions options;
    options.band = mission.band;
    return loadLandCoverRaster(resolveRasterPath(mission, missionPath), options);
}

Status applyMissionArea(LoadedRaster& raster, const Mission& mission, const std::string& missionPath) {
    if (mission.area.empty())
        return {};
    return applyAreaOfInterest(raster, resolveMissionPath(mission.area.includePath, missionPath),
                               resolveMissionPath(mission.area.excludePath, missionPath));
}

namespace {

// The raster's classes that neither the mission's own rows nor its preset list, and their pixels.
struct UnlistedClasses {
    std::vector<std::int32_t> values;
    std::int64_t pixels = 0;
    std::int64_t allPixels = 0;
};

UnlistedClasses unlistedClasses(const Mission& mission, const ClassTable& preset,
                                const LoadedRaster& raster) {
    UnlistedClasses unlisted;
    for (const auto& [value, count] : raster.classPixelCounts) {
        unlisted.allPixels += count;
        if (mission.classes.find(value) == nullptr && preset.find(value) == nullptr) {
            unlisted.values.push_back(value);
            unlisted.pixels += count;
        }
    }
    return unlisted;
}

// "1, 2, 3 and 4 more": the first few values.
std::string someValues(const std::vector<std::int32_t>& values) {
    constexpr std::size_t shown = 8;
    std::string text;
    for (std::size_t i = 0; i < values.size() && i < shown; ++i)
        text += (i == 0 ? "" : ", ") + std::to_string(values[i]);
    if (values.size() > shown)
        text += " and " + std::to_string(values.size() - shown) + " more";
    return text;
}

} // namespace

std::optional<std::string> presetGapWarning(const Mission& mission, const LoadedRaster& raster) {
    if (mission.preset.empty())
        return std::nullopt;
    auto preset = presetClassTable(mission.preset);
    if (!preset)
        return std::nullopt;
    const UnlistedClasses unlisted = unlistedClasses(mission, preset.value(), raster);
    // None listed is refused (missionClasses), not warned about.
    if (unlisted.values.empty() || unlisted.allPixels == 0 ||
        unlisted.values.size() == raster.classPixelCounts.size())
        return std::nullopt;
    const double share = static_cast<double>(unlisted.pixels) / static_cast<double>(unlisted.allPixels);
    const LandCoverClass generic = internal::genericClass(unlisted.values.front());
    return "preset " + mission.preset + " has no row for " +
           (unlisted.values.size() == 1 ? "class " : "classes ") + someValues(unlisted.values) + " (" +
           formatPercent(share) + " of the map): planned as passable at " +
           formatQuantity(generic.speedMetresPerSecond) + " m/s with a " +
           formatQuantity(generic.fieldOfViewMetres) +
           " m field of view; give them rows (--classes), or choose the preset of this raster's product";
}

Result<ClassTable> missionClasses(const Mission& mission, const LoadedRaster& raster,
                                  const FieldNamer& names) {
    const std::string where = names(MissionField::of(Part::Classes));
    if (!mission.preset.empty()) {
        // Asking for the preset alone first turns an unknown name into an error instead of a default table.
        auto preset = presetClassTable(mission.preset);
        if (!preset)
            return Result<ClassTable>::failure(where + ": " + preset.error());
        // A preset that knows none of the map's classes is another product's: its plan would mean nothing.
        const UnlistedClasses unlisted = unlistedClasses(mission, preset.value(), raster);
        const std::string advice =
            "choose this raster's (mcpp --help lists the presets), or give a class table";
        if (!unlisted.values.empty() && unlisted.values.size() == raster.classPixelCounts.size())
            return Result<ClassTable>::failure(
                where + ": preset " + mission.preset + " has a row for none of the raster's " +
                (unlisted.values.size() == 1 ? "class ("
                                             : std::to_string(unlisted.values.size()) + " classes (") +
                someValues(unlisted.values) + "): it is another product's legend; " + advice);
        // One that knows a few of its values by chance still leaves most of the map to the generic row.
        if (unlisted.allPixels > 0 && 2 * unlisted.pixels > unlisted.allPixels)
            return Result<ClassTable>::failure(
                where + ": preset " + mission.preset + " has no row for " +
                (unlisted.values.size() == 1 ? "class " : "classes ") + someValues(unlisted.values) + ", " +
                formatPercent(static_cast<double>(unlisted.pixels) /
                              static_cast<double>(unlisted.allPixels)) +
                " of the map: it is most likely another product's legend; " + advice +
                " with rows for these classes (--classes FILE, or rows beside the preset in a mission file)");
    }
    ClassTable table =
        missionClassTable(mission.classes, mission.preset, raster, mission.classesWithoutColour);
    if (mission.fieldOfViewMetres)
        table.setEveryFieldOfView(*mission.fieldOfViewMetres);
    if (const auto problem = table.validate())
        return Result<ClassTable>::failure(where + ": " + *problem);
    return table;
}

namespace {

// How far from where the window holds it a point may be written: a transform's way there and back can be a
// millimetre off (a datum shift's inverse is approximate), and without this slack a start would creep by
// that much at every save.
constexpr double writtenToleranceMetres = 0.005;

double roundedTo(double value, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

// A planning-frame point in a CRS (crs; empty: the planning CRS's units) with the fewest decimals that lead
// back to within writtenToleranceMetres of it: a point read and written back reads as given (7.41, not
// 7.4099999999999997 or 7.41000001). None where the CRS cannot take it.
std::optional<MapPoint> writtenIn(const std::string& crs, MapPoint point, const GeoReference& georeference) {
    const auto there =
        crs.empty() ? Result<MapPoint>(georeference.toCrsUnits(point)) : georeference.toCrs(crs, point);
    if (!there.ok())
        return std::nullopt;
    constexpr int mostDecimals = 9;
    for (int decimals = 0; decimals < mostDecimals; ++decimals) {
        const MapPoint rounded{roundedTo(there.value().x, decimals), roundedTo(there.value().y, decimals)};
        const auto back = crs.empty() ? Result<MapPoint>(georeference.fromCrsUnits(rounded))
                                      : georeference.fromCrs(crs, rounded);
        if (back.ok() &&
            std::hypot(back.value().x - point.x, back.value().y - point.y) <= writtenToleranceMetres)
            return rounded;
    }
    return MapPoint{roundedTo(there.value().x, mostDecimals), roundedTo(there.value().y, mostDecimals)};
}

} // namespace

RobotSpec robotAsWritten(RobotSpec robot, const GeoReference& georeference) {
    const auto writeIn = [&](const std::string& crs) {
        const std::optional<MapPoint> start = writtenIn(crs, robot.start, georeference);
        const std::optional<MapPoint> charger =
            robot.charger ? writtenIn(crs, *robot.charger, georeference) : std::nullopt;
        if (!start || (robot.charger && !charger))
            return false;
        robot.start = *start;
        robot.charger = charger;
        return true;
    };
    if (robot.startCrs.empty() || !writeIn(robot.startCrs)) {
        robot.startCrs.clear(); // none given, or one the map's points do not go into
        writeIn(std::string());
    }
    return robot;
}

namespace {

// A point of a robot (its start or charger) in the planning frame: from its start_crs when it has one,
// else from the units the caller reads starts in.
Result<MapPoint> toPlanningFrame(const RobotSpec& spec, MapPoint point, const LoadedRaster& raster,
                                 StartUnits units) {
    if (!spec.startCrs.empty())
        return raster.georeference.fromCrs(spec.startCrs, point);
    if (units == StartUnits::RasterFileCrs && raster.warpedFromGeographic) {
        // Only the file CRS's name survives loading; WGS84 is the fallback, metres from any other datum.
        Result<MapPoint> converted = raster.georeference.fromCrs(raster.sourceCrsName, point);
        return converted ? converted : raster.georeference.fromCrs("EPSG:4326", point);
    }
    return raster.georeference.fromCrsUnits(point);
}

// Whether a point of the planning frame lies on the map, inside the task area.
bool onTheMap(const ClassGrid& grid, MapPoint point) {
    const auto pixel = grid.pixelAt(point);
    return pixel && !grid.isOutside(pixel->column, pixel->row);
}

// Why degrees may not convert: a latitude beyond 90 that would be a longitude, and the point the other way
// round converts.
std::string latitudeFirstHint(const RobotSpec& spec, const LoadedRaster& raster, StartUnits units) {
    const MapPoint typed = spec.start;
    if (!(std::fabs(typed.y) > 90.0 && std::fabs(typed.y) <= 180.0 && std::fabs(typed.x) <= 90.0) ||
        !toPlanningFrame(spec, {typed.y, typed.x}, raster, units))
        return {};
    return "; " + formatQuantity(typed.y, 9) +
           " is no latitude (they lie between -90 and 90): a start in degrees is "
           "longitude first (" +
           formatQuantity(typed.y, 9) + "," + formatQuantity(typed.x, 9) + ")";
}

// Why numbers far beyond degrees do not convert, read in a raster's geographic CRS: they are metres of
// some projected CRS, to be named with crsField; where they lie on the map in the planning frame's, which.
std::string metresOnDegreesHint(const RobotSpec& spec, const LoadedRaster& raster, StartUnits units,
                                const std::string& crsField) {
    const MapPoint typed = spec.start;
    // Beyond 360 or 180: not degrees either way round (latitudeFirstHint speaks of those).
    if (!spec.startCrs.empty() || units != StartUnits::RasterFileCrs || !raster.warpedFromGeographic ||
        (std::fabs(typed.x) <= 360.0 && std::fabs(typed.y) <= 180.0))
        return {};
    std::string hint = "; a start is read as longitude,latitude in the raster's CRS, " +
                       raster.sourceCrsName + ", unless " + crsField + " names another";
    if (const std::string planningCrs = raster.georeference.authorityCode(); !planningCrs.empty())
        if (const auto there = raster.georeference.fromCrs(planningCrs, typed);
            there && onTheMap(raster.grid, there.value()))
            return hint + ": as metres of " + raster.georeference.name() + " these numbers lie on the map (" +
                   crsField + " " + planningCrs + ")";
    return hint + " (the CRS these metres are in, e.g. EPSG:32632 for UTM zone 32N)";
}

// A start outside the map whose numbers look like degrees, typed without a CRS saying so (on a raster
// warped from degrees, mission files give starts in its planning metres): where they would lie as
// longitude and latitude (or the other way round), if that is on the map.
// Where longitude and latitude fall in the planning frame, if on the map.
std::optional<MapPoint> degreesOnTheMap(const LoadedRaster& raster, MapPoint lonLat) {
    const auto onMap = raster.georeference.fromCrs("EPSG:4326", lonLat);
    if (!onMap || !onTheMap(raster.grid, onMap.value()))
        return std::nullopt;
    return onMap.value();
}

std::string degreesWithoutCrsHint(const LoadedRaster& raster, MapPoint start, const std::string& crsField) {
    if (!(std::fabs(start.x) <= 180.0 && std::fabs(start.y) <= 180.0))
        return {};
    for (const MapPoint lonLat : {start, MapPoint{start.y, start.x}}) {
        if (std::fabs(lonLat.y) > 90.0)
            continue;
        if (degreesOnTheMap(raster, lonLat))
            return "; as longitude " + formatQuantity(lonLat.x, 9) + ", latitude " +
                   formatQuantity(lonLat.y, 9) + " it lies on the map: give EPSG:4326 as " + crsField +
                   (lonLat.x == start.x ? std::string() : std::string(" and longitude first"));
    }
    return {};
}

// "in the raster's own CRS, ...: give start_crs ..., or leave it out", where a start given in another CRS
// lies on the map read in the raster's.
std::optional<std::string> rasterCrsFitsHint(const RobotSpec& spec, const LoadedRaster& raster) {
    const std::string own = raster.georeference.authorityCode();
    if (spec.startCrs.empty() || own.empty() || spec.startCrs == own ||
        !onTheMap(raster.grid, raster.georeference.fromCrsUnits(spec.start)))
        return std::nullopt;
    return "in the raster's own CRS, " + own + " (" + raster.georeference.name() + "): give start_crs " +
           own + ", or leave it out";
}

// A start given with a start_crs that puts it off the map, whose numbers lie on it in the raster's own CRS
// (EPSG:21781 written for Swiss LV95 coordinates, say): most likely the wrong CRS was named.
std::optional<std::string> otherCrsFitsProblem(const RobotSpec& spec, MapPoint start,
                                               const LoadedRaster& raster) {
    if (onTheMap(raster.grid, start))
        return std::nullopt;
    const auto hint = rasterCrsFitsHint(spec, raster);
    if (!hint)
        return std::nullopt;
    return "in " + spec.startCrs + " the start (" + formatQuantity(spec.start.x, 12) + ", " +
           formatQuantity(spec.start.y, 12) + ") lies off the map, but these numbers lie on it " + *hint;
}

// Where a start's CRS cannot take its numbers at all (metres read as degrees): what they are on the map.
std::string transformFailedHint(const RobotSpec& spec, const LoadedRaster& raster) {
    const auto hint = rasterCrsFitsHint(spec, raster);
    return hint ? "; these numbers lie on the map " + *hint : std::string();
}

// A start as messages name it: its planning-frame coordinates, and its longitude and latitude where the
// raster is georeferenced (what a user who typed degrees recognises; metres of UTM mean little to most).
std::string startName(const LoadedRaster& raster, MapPoint start) {
    const std::string planning = describePoint(start);
    if (!std::isfinite(start.x) || !std::isfinite(start.y))
        return planning;
    const auto lonLat = raster.georeference.toWgs84(start);
    if (!lonLat)
        return planning;
    return planning.substr(0, planning.size() - 1) + "; " + degreesText(lonLat.value()) + ")";
}

// "let the planner start the robot from the nearest free cell (...)", the setting in the caller's terms.
std::string snapStartsAdvice(const FieldNamer& names) {
    return "let the planner start the robot from the nearest free cell (" +
           names(MissionField::parameter("snap_starts_to_free_cells", "true")) + ")";
}

// Whether the point lies on the raster but outside the task area (nodata, outside the area of interest or
// in a no-go zone): the planner can start the robot from the nearest free cell.
bool onTheRasterOutsideTheArea(const ClassGrid& grid, MapPoint point) {
    const auto pixel = grid.pixelAt(point);
    return pixel && grid.isOutside(pixel->column, pixel->row);
}

// Where a ground robot may not start but an aircraft may take off (a road beside the field, a roof): the
// planner's own rule, takesOffThere.
constexpr const char* aircraftTakeOffHint =
    "; an aircraft (vehicle \"multirotor\" or \"fixed-wing\") would take off there and fly to the nearest "
    "free cell";

// What helps with a start the planner cannot use: a hint when longitude and latitude look swapped, and the
// option that moves starts off obstacles.
std::string startAdvice(const LoadedRaster& raster, const StartPointProblem& problem, MapPoint start,
                        int robot, const FieldNamer& names) {
    using Kind = PlanningError::Kind;
    std::string advice;
    if (problem.kind == Kind::StartOutsideArea && std::isfinite(start.x) && std::isfinite(start.y)) {
        advice += degreesWithoutCrsHint(raster, start, names(MissionField::startCrs(robot)));
        if (onTheMap(raster.grid, {start.y, start.x}))
            advice += "; x and y the other way round lie on the map: x (easting) comes first";
        if (const auto lonLat = raster.georeference.toWgs84(start); lonLat) {
            const LonLat& at = lonLat.value();
            const auto swapped = raster.georeference.fromCrs("EPSG:4326", {at.latitude, at.longitude});
            if (swapped && onTheMap(raster.grid, swapped.value()))
                advice += "; longitude and latitude the other way round lie on the map: a start in degrees "
                          "is longitude first";
        }
    }
    if (problem.kind == Kind::StartOutsideArea && std::isfinite(start.x) && std::isfinite(start.y) &&
        onTheRasterOutsideTheArea(raster.grid, start))
        advice += "; move it into the task area, or " + snapStartsAdvice(names);
    return advice + startProblemAdvice(problem.kind, names);
}

// The raster's classes the table lacks refused, or made obstacles where the mission says so.
Status reconcileAsAsked(LoadedRaster& raster, const ClassTable& classes, bool missingClassesAsObstacles,
                        const FieldNamer& names) {
    if (Status status = reconcileRasterWithTable(raster, classes, missingClassesAsObstacles); !status)
        return Status::failure(status.error() + "; " + names(MissionField::of(Part::MissingClassesOption)) +
                               " does the latter");
    return {};
}

// The first start the planner could not use, on a raster already reconciled with the class table.
Status firstStartProblem(const LoadedRaster& reconciled, const ClassTable& classes,
                         const std::vector<MapPoint>& starts, const FieldNamer& names,
                         const std::vector<bool>& flyingRobots) {
    for (std::size_t robot = 0; robot < starts.size(); ++robot) {
        const MapPoint start = starts[robot];
        const auto problem = startPointProblem(reconciled.grid, classes, start, startName(reconciled, start));
        // An aircraft takes off where it stands and flies to the nearest free cell (the planner checks that
        // one flight reaches it).
        if (problem && !robotTakesOffThere(flyingRobots, robot, reconciled.grid, start, *problem))
            return Status::failure(
                names(MissionField::start(static_cast<int>(robot))) + ": " +
                withPointsInDegrees(startRefusal(reconciled.grid, classes, start, *problem),
                                    reconciled.georeference, reconciled.grid) +
                startAdvice(reconciled, *problem, start, static_cast<int>(robot), names) +
                (takesOffThere(reconciled.grid, start, *problem) ? aircraftTakeOffHint : ""));
    }
    return {};
}

} // namespace

std::string startProblemAdvice(PlanningError::Kind kind, const FieldNamer& names) {
    const std::string snap = snapStartsAdvice(names);
    if (kind == PlanningError::Kind::StartOnObstacle)
        return "; move it onto passable land, or " + snap;
    if (kind == PlanningError::Kind::StartsShareCell)
        return "; each robot sets off from a cell of its own: place the starts farther apart, or " + snap;
    return {};
}

namespace {

// What to do about a charger the planner cannot use: unlike a start, it is not moved for the user.
std::string chargerProblemAdvice(PlanningError::Kind kind) {
    if (kind == PlanningError::Kind::StartOnObstacle)
        return "; move it onto passable land";
    if (kind == PlanningError::Kind::StartOutsideArea)
        return "; a charger is read in the same CRS as the robot's start: move it into the task area";
    if (kind == PlanningError::Kind::StartsShareCell)
        return "; each charger needs a cell of its own: place it farther from the other";
    return {};
}

} // namespace

std::string robotsNamedIn(const std::string& message, const std::vector<std::string>& robotNames,
                          bool withIndex) {
    std::string named;
    for (const std::size_t robot : robotNumbersIn(message)) {
        if (robot == 0 || robot > robotNames.size())
            continue;
        const std::string& name = robotNames[robot - 1];
        const std::string number = "robot " + std::to_string(robot);
        const std::string shownName = lowercase(name) == number ? std::string() : name;
        const std::string index = withIndex ? "robots[" + std::to_string(robot - 1) + "]" : std::string();
        if (index.empty() && shownName.empty())
            continue;
        named += (named.empty() ? "" : "; ") + number + " is " + index +
                 (index.empty() || shownName.empty() ? "" : ", ") + shownName;
    }
    return named.empty() ? std::string() : " (" + named + ")";
}

std::string messageForPeople(const std::string& message, const LoadedRaster* raster,
                             const std::vector<std::string>& robotNames) {
    return raster != nullptr ? messageForPeople(message, raster->georeference, &raster->grid, robotNames)
                             : message + robotsNamedIn(message, robotNames, false);
}

std::string messageForPeople(const std::string& message, const GeoReference& georeference,
                             const ClassGrid* grid, const std::vector<std::string>& robotNames) {
    const std::string placed = grid != nullptr ? withPointsInDegrees(message, georeference, *grid) : message;
    return placed + robotsNamedIn(message, robotNames, false);
}

std::optional<std::string> planningErrorText(const PlanningError& error, const FieldNamer& names,
                                             const std::vector<std::string>& robotNames, bool withIndex) {
    const std::string robots = robotsNamedIn(error.detail(), robotNames, withIndex);
    if (error.robot() >= 0 && error.aboutCharger())
        return names(MissionField::charger(error.robot())) + ": " + error.detail() + robots +
               chargerProblemAdvice(error.kind());
    if (error.robot() >= 0)
        return names(MissionField::start(error.robot())) + ": " + error.detail() + robots +
               startProblemAdvice(error.kind(), names);
    if (!error.parameter().empty())
        return names(MissionField::parameter(error.parameter())) + ": " + error.detail() + robots;
    return std::nullopt;
}

Result<std::vector<MapPoint>> missionStarts(const Mission& mission, const LoadedRaster& raster,
                                            StartUnits units, const FieldNamer& names) {
    using Starts = Result<std::vector<MapPoint>>;
    std::vector<MapPoint> starts;
    for (std::size_t i = 0; i < mission.robots.size(); ++i) {
        const auto robot = static_cast<int>(i);
        const RobotSpec& spec = mission.robots[i];
        if (!std::isfinite(spec.start.x) || !std::isfinite(spec.start.y))
            return Starts::failure(names(MissionField::start(robot)) + ": not a finite point");
        const Result<MapPoint> start = toPlanningFrame(spec, spec.start, raster, units);
        if (!start)
            return Starts::failure(
                names(spec.startCrs.empty() ? MissionField::start(robot) : MissionField::startCrs(robot)) +
                ": " + start.error() + latitudeFirstHint(spec, raster, units) +
                metresOnDegreesHint(spec, raster, units, names(MissionField::startCrs(robot))) +
                (spec.startCrs.empty() ? std::string() : transformFailedHint(spec, raster)));
        if (auto problem = otherCrsFitsProblem(spec, start.value(), raster))
            return Starts::failure(names(MissionField::startCrs(robot)) + ": " + *problem);
        starts.push_back(start.value());
    }
    return starts;
}

std::string chargerInDegreesHint(const Mission& mission, const LoadedRaster& raster, int robot) {
    if (robot < 0 || static_cast<std::size_t>(robot) >= mission.robots.size())
        return {};
    const RobotSpec& spec = mission.robots[static_cast<std::size_t>(robot)];
    if (!spec.charger)
        return {};
    const MapPoint given = *spec.charger;
    if (!spec.startCrs.empty()) {
        // In degrees, latitude first is the commonest slip; the start's own hint says it for starts. Figures
        // that cannot be degrees read the other way round are metres of a projected CRS: no hint.
        if (!(std::fabs(given.x) <= 90.0 && std::fabs(given.y) <= 180.0))
            return {};
        const Result<MapPoint> swapped = raster.georeference.fromCrs(spec.startCrs, {given.y, given.x});
        return swapped && onTheMap(raster.grid, swapped.value())
                   ? "; longitude and latitude the other way round lie on the map: a charger in degrees is "
                     "longitude first"
                   : std::string();
    }
    if (!(std::fabs(given.x) <= 180.0 && std::fabs(given.y) <= 90.0))
        return {};
    const auto onMap = degreesOnTheMap(raster, given);
    if (!onMap)
        return {};
    return "; read as longitude " + formatQuantity(given.x, 9) + ", latitude " + formatQuantity(given.y, 9) +
           " it lies on the map: give it as " + describePoint(raster.georeference.toCrsUnits(*onMap));
}

Result<std::vector<std::optional<MapPoint>>> missionChargers(const Mission& mission,
                                                             const LoadedRaster& raster, StartUnits units,
                                                             const FieldNamer& names) {
    using Chargers = Result<std::vector<std::optional<MapPoint>>>;
    std::vector<std::optional<MapPoint>> chargers(mission.robots.size());
    for (std::size_t i = 0; i < mission.robots.size(); ++i) {
        const RobotSpec& spec = mission.robots[i];
        if (!spec.charger)
            continue;
        const Result<MapPoint> charger = toPlanningFrame(spec, *spec.charger, raster, units);
        if (!charger)
            return Chargers::failure(names(MissionField::charger(static_cast<int>(i))) + ": " +
                                     charger.error());
        chargers[i] = charger.value();
    }
    return chargers;
}

Status checkPlannerChoice(const PlannerChoice& choice, const FieldNamer& names) {
    const auto description = findPlannerDescription(choice.planner);
    if (!description)
        return Status::failure(names(MissionField::of(Part::Planner)) + ": " +
                               unknownPlannerMessage(choice.planner));
    try {
        (void)resolveParameters(description->parameters, choice.parameters);
    } catch (const PlanningError& error) {
        return Status::failure(*planningErrorText(error, names));
    }
    return {};
}

namespace {

// The classes on the map the table makes obstacles, where every robot flies: the presets, made for ground
// robots, make built-up land and water so, and drones then neither cover nor cross them without a word
// (a coverage of 98.7 % hides a town).
std::optional<std::string> impassableUnderAircraftNote(const LoadedRaster& raster, const ClassTable& classes,
                                                       const std::vector<bool>& flyingRobots) {
    if (flyingRobots.empty() || !std::all_of(flyingRobots.begin(), flyingRobots.end(), std::identity()))
        return std::nullopt;
    std::int64_t inside = 0;
    for (const auto& [value, count] : raster.classPixelCounts)
        inside += count;
    const double pixelArea = raster.grid.pixelWidth * raster.grid.pixelHeight;
    std::vector<std::string> named;
    for (const auto& [value, count] : raster.classPixelCounts) {
        const LandCoverClass* landCover = classes.find(value);
        // Only those marked impassable: the Passable box is what the note asks to tick.
        if (landCover == nullptr || landCover->passable || count == 0)
            continue;
        const std::string name = landCover->name.empty() ? "class " + std::to_string(value) : landCover->name;
        named.push_back(name + " (" + formatArea(static_cast<double>(count) * pixelArea) + ", " +
                        formatPercent(static_cast<double>(count) / static_cast<double>(inside)) +
                        " of the map)");
    }
    if (named.empty())
        return std::nullopt;
    std::string list;
    for (std::size_t i = 0; i < named.size(); ++i)
        list += (i == 0 ? "" : i + 1 == named.size() ? " and " : ", ") + named[i];
    const bool one = named.size() == 1;
    const bool alone = flyingRobots.size() == 1;
    return std::string(alone ? "the robot flies" : "every robot flies") + ", yet the class table makes " +
           list + (one ? " an obstacle" : " obstacles") +
           (alone ? ": it neither covers nor crosses " : ": the aircraft neither cover nor cross ") +
           (one ? "it" : "them") + ". To cover " + (one ? "it" : "one") + ", or to fly across " +
           (one ? "it" : "one") +
           " to land beyond, make it passable (the class table's Passable column; in a mission file, "
           "classes.table)";
}

} // namespace

Result<PreparedProblem> planningProblem(const LoadedRaster& raster, const ClassTable& classes,
                                        bool missingClassesAsObstacles, std::vector<MapPoint> starts,
                                        const PlannerChoice& choice, const FieldNamer& names,
                                        const std::vector<bool>& flyingRobots) {
    using Prepared = Result<PreparedProblem>;
    if (Status planner = checkPlannerChoice(choice, names); !planner)
        return Prepared::failure(planner.error());
    LoadedRaster reconciled = raster;
    const std::size_t warningsBefore = reconciled.warnings.size();
    if (Status status = reconcileAsAsked(reconciled, classes, missingClassesAsObstacles, names); !status)
        return Prepared::failure(status.error());
    PreparedProblem prepared;
    prepared.warnings.assign(reconciled.warnings.begin() + static_cast<std::ptrdiff_t>(warningsBefore),
                             reconciled.warnings.end());
    const auto description = findPlannerDescription(choice.planner);
    const ParameterValues parameters = resolveParameters(description->parameters, choice.parameters);
    // With snapping the planner moves bad starts itself and warns; without, say exactly what is wrong here.
    const bool snap =
        parameters.has("snap_starts_to_free_cells") && parameters.boolean("snap_starts_to_free_cells");
    if (!snap)
        if (Status startsUsable = firstStartProblem(reconciled, classes, starts, names, flyingRobots);
            !startsUsable)
            return Prepared::failure(startsUsable.error());
    // The raster's values as read: batch mode lends its own to the planner on that ground (only `outside`
    // may differ, where reconciling set classes the table lacks outside).
    prepared.problem.grid = std::move(reconciled.grid);
    prepared.problem.classes = classes;
    prepared.problem.starts = std::move(starts);
    prepared.problem.planner = choice;
    if (auto obstacles = impassableUnderAircraftNote(raster, classes, flyingRobots))
        prepared.problem.notes.push_back(
            {IssueSeverity::Information, "impassable-under-aircraft", std::move(*obstacles)});
    return prepared;
}

Status checkStarts(const LoadedRaster& raster, const ClassTable& classes, bool missingClassesAsObstacles,
                   const std::vector<MapPoint>& starts, const FieldNamer& names,
                   const std::vector<bool>& flyingRobots) {
    LoadedRaster reconciled = raster;
    if (Status status = reconcileAsAsked(reconciled, classes, missingClassesAsObstacles, names); !status)
        return status;
    return firstStartProblem(reconciled, classes, starts, names, flyingRobots);
}

} // namespace mcpp::io
