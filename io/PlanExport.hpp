#pragma once

#include "core/model/AreaOutline.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "core/outlines/RegionOutlines.hpp"
#include "io/AutopilotMission.hpp"
#include "io/GeoReference.hpp"
#include "io/Mission.hpp"
#include "io/Result.hpp"

#include <algorithm>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::io {

struct ExportContext;

enum class ImageFormat { Png, Svg };
// Draws the plan as a picture. io has no renderer of its own: the caller lends one (render/).
using ImageWriter =
    std::function<Status(const ExportContext& context, ImageFormat format, const std::string& path)>;

// What every exporter needs besides the plan.
struct ExportContext {
    const Plan& plan;
    const GeoReference& georeference;
    const ClassTable& classes;
    ExportSettings settings;
    const ClassGrid* grid = nullptr;   // the land cover, for pictures
    const AreaOutline* area = nullptr; // the area of interest's and no-go zones' edges: pictures, vectors
    ImageWriter drawImage = {};
    // What the whole run took so far (batch mode: read_raster, plan, write_outputs), for report.json.
    std::vector<std::pair<std::string, double>> processMilliseconds = {};
    // What the inputs gave to warn of before planning (an area reaching past the raster, classes a preset
    // lacks), for report.json beside the plan's own warnings.
    std::vector<std::string> inputWarnings = {};
    // Set from another thread to stop a writer at its next feature, row or file; it then fails with
    // "cancelled" and leaves no file behind.
    const std::atomic<bool>* cancelRequested = nullptr;
    // Each robot's name, by robot index, for the exports that show names.
    std::vector<std::string> robotNames = {};
    // Each robot's vehicle, by robot index; settings.vehicle for a robot not in it.
    std::vector<VehicleSettings> vehicles = {};
    // What the writers of this run said of their files (a KML leaving the waypoint files' parts out), for
    // report.json, written after them.
    std::vector<std::string> outputNotes = {};

    [[nodiscard]] bool cancelled() const { return cancelRequested != nullptr && cancelRequested->load(); }
    // The robot's name from robotNames, or "Robot <number>" when it has none.
    [[nodiscard]] std::string robotName(int robot) const;
    [[nodiscard]] const VehicleSettings& vehicle(int robot) const;
    // The plan's region outlines, traced on first use and shared by every writer of this context (and its
    // copies), whichever thread asks first.
    [[nodiscard]] const RegionOutlines& outlines() const;

    struct OutlineCache {
        std::once_flag traced;
        RegionOutlines outlines;
    };
    std::shared_ptr<OutlineCache> outlineCache = std::make_shared<OutlineCache>(); // for outlines() only

    // Each robot's autopilot mission, made and placed on WGS84 once for its waypoint files, its CSV and the
    // reports. Keyed by robot only: a copy of the context shares it, so a copy must not change settings or
    // vehicles.
    struct MissionCache {
        struct Entry {
            std::once_flag made;
            AutopilotMission mission;
            // Its points' longitude and latitude (then its take-off point's, where that is elsewhere),
            // transformed once for its .plan, .waypoints and CSV files; when they cannot be had, none and the
            // reason.
            std::once_flag placed;
            std::vector<LonLat> lonLats;
            std::string placeError;
        };
        std::mutex mutex; // guards entries
        std::map<int, std::shared_ptr<Entry>> entries;
    };
    std::shared_ptr<MissionCache> missionCache = std::make_shared<MissionCache>(); // WaypointExport.cpp only
};

// Robots are numbered from 1 in every file, as on the map and in the legend; plans index them from 0.
[[nodiscard]] constexpr int robotNumber(int robot) {
    return robot + 1;
}
// The name of a robot's own files without the extension, as batch mode writes them for a plan of `robots`:
// "robot_2", its number padded with zeros to the width of the last one's ("robot_02" of 12) so that a file
// list sorts the robots in order.
[[nodiscard]] inline std::string robotFileStem(int robot, int robots) {
    return "robot_" + paddedNumber(static_cast<std::size_t>(robotNumber(robot)),
                                   static_cast<std::size_t>(std::max(robots, 0)));
}

// RFC 7946 GeoJSON (WGS84) with the batch contract's kinds and properties.
[[nodiscard]] Status writePlanGeoJson(const ExportContext& context, const std::string& path);
// GeoPackage in the raster's CRS: layers regions, paths, starts, unreachable, missions (each waypoint file
// part as a line, with its items and time and whether it fits the flight time), and cells when
// settings.cellPolygons asks for a polygon per cell.
[[nodiscard]] Status writePlanGeoPackage(const ExportContext& context, const std::string& path);
// KML for Google Earth: regions, paths and starts in the robots' colours, and, where some mission is split,
// a missions folder of the waypoint files' parts (up to kmlMostMissionParts; kmlMissionPartsNote says when
// there are more).
[[nodiscard]] Status writePlanKml(const ExportContext& context, const std::string& path);
inline constexpr std::size_t kmlMostMissionParts = 2000;
// What the user should know of a KML written to `path`: that it leaves out the mission parts, where there are
// more than kmlMostMissionParts, and where to find them; empty otherwise.
[[nodiscard]] std::string kmlMissionPartsNote(const ExportContext& context, const std::string& path);
[[nodiscard]] Status writePlanGpx(const ExportContext& context, const std::string& path);
// regions.tif: the robot covering each sub-cell of the planning grid, as a tiled, compressed GeoTIFF in the
// raster's CRS with a colour table in the robots' colours. Value = robot number from 1; 255 for passable land
// no robot reaches; nodata 0 elsewhere (UInt16 with 65535 from 255 robots on).
[[nodiscard]] Status writeRegionRaster(const ExportContext& context, const std::string& path);
// detection.tif, for plans with a detection layer (CPPIED): on the lattice of half grid cells in the
// raster's CRS, band 1 the chance a target is seen, band 2 the chance required (0 where the land cover
// hides targets); Float32, nodata -1 where no robot goes.
[[nodiscard]] Status writeDetectionRaster(const ExportContext& context, const std::string& path);

// The waypoints a robot's waypoint files get: all of them, or, with mergeCollinear, without the points that
// lie on the straight segment between their neighbours at the same speed and land cover (time and shape
// unchanged).
[[nodiscard]] std::vector<Waypoint> exportedWaypoints(const CoveragePath& path, const CellGraph& cells,
                                                      bool mergeCollinear);
// The path a robot's waypoint files are made from: `path`, or, where collinear points are kept and its
// straight runs were merged (large plans), `whole` filled with every waypoint it walked.
[[nodiscard]] const CoveragePath& pathForWaypointFiles(const CoveragePath& path, const CellGraph& cells,
                                                       bool mergeCollinear, CoveragePath& whole);
// The indices in the path of exportedWaypoints' points.
[[nodiscard]] std::vector<std::size_t> exportedWaypointIndices(const CoveragePath& path,
                                                               const CellGraph& cells, bool mergeCollinear);

// The shape of a path as lines in GeoJSON, GeoPackage, KML and GPX: its ends and the points where it changes
// direction; a point on the straight segment between its neighbours is left out, whatever its land cover.
[[nodiscard]] std::vector<Waypoint> turningPoints(const CoveragePath& path);

// What to tell the user when the robot flies several sorties, each written beside `path` as its own mission
// (missionSortiePath); empty when it flies one.
[[nodiscard]] std::string sortieFilesNote(const ExportContext& context, int robot, const std::string& path);

// The mission a robot's autopilot files hold (empty when the plan has no path for it), with the parts its
// vehicle's item limit splits it into; made on first use and shared by the context's copies.
[[nodiscard]] const AutopilotMission& autopilotMissionOf(const ExportContext& context, int robot);
// What a user should know when a robot's mission is written in parts beside `path` (its whole-file name);
// empty when it is written whole.
[[nodiscard]] std::string splitMissionNote(const ExportContext& context, int robot, const std::string& path);
// What a user must know when some of a robot's mission parts take longer than its vehicle's flight time (a
// part holds at least two points: its path goes out of one flight's reach), naming their files beside `path`
// (the whole mission's file name); empty when all fit.
[[nodiscard]] std::string flightTimeWarning(const ExportContext& context, int robot, const std::string& path);
// When the last robot is done in the field where some mission is written in parts: "the last robot, centre,
// done in the field after 5 d 13 h, its 271 flights and the turnarounds between them included"; empty when
// no aircraft's mission and no mission with turnarounds is in parts, or a time is unknown.
[[nodiscard]] std::string fieldTimeNote(const ExportContext& context);
// "no plan making these turns brings the last robot home before 1 d 12 h in the field", and where the
// bound leaves the trips out to the work and back out (PlanMetrics::fieldBoundWithoutTrips), that it does;
// empty where the plan has no bound in the field.
[[nodiscard]] std::string fieldBoundNote(const ExportContext& context);
// How many of the robots' flights (waypoint file parts) take longer than their vehicle's flight time; none
// where no robot has a flight time.
[[nodiscard]] std::optional<std::size_t> flightsOverBattery(const ExportContext& context);

// Per robot waypoint files. Above the vehicle's item limit, a robot's mission is written as consecutive
// parts beside `path` (missionPartPath), each beginning where the one before it ended, and `path` itself is
// not written. A robot that flies several sorties also gets each sortie as a mission of its own
// (missionSortiePath), split the same way.
[[nodiscard]] Status writeQGroundControlPlan(const ExportContext& context, int robot,
                                             const std::string& path);
[[nodiscard]] Status writeWaypointList(const ExportContext& context, int robot,
                                       const std::string& path); // QGC WPL 110
[[nodiscard]] Status writeWaypointCsv(const ExportContext& context, int robot, const std::string& path);

// What report.json and the comparison files call the kind of a plan's lower bound: "detection_passes" for a
// detection plan's (looser than the others': its ratio is not to be set beside theirs), "coverage_work"
// otherwise (the work the robots share, turns and connectors included).
[[nodiscard]] std::string lowerBoundKind(const PlanMetrics& metrics);

// report.json of the batch contract, and the per-robot CSV.
[[nodiscard]] Status writeReportJson(const ExportContext& context, const std::string& path);
[[nodiscard]] Status writeReportCsv(const ExportContext& context, const std::string& path);

} // namespace mcpp::io
