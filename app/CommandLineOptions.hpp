#pragma once

#include "core/model/MapPoint.hpp"
#include "core/model/SpeedEvent.hpp"
#include "io/VehicleSettings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mcpp::app {

enum class RunMode {
    Gui,         // open the window, optionally with a mission or raster
    Batch,       // plan headless and write the outputs
    Help,        // print the usage and exit
    PlannerHelp, // print one planner's parameters and exit
    Version,     // print the version and exit
};

// A planner parameter set on the command line, checked against the planner's declaration once the
// planner is known (it may come from the mission file).
struct ParameterOverride {
    std::string key;
    std::string value; // as typed
    std::string flag;  // how messages name it: "--param purity_tolerance", "--purity", "--open-paths"
};

// What the command line asked for. Optional fields left empty keep the mission's (or the default) value.
struct CommandLineOptions {
    RunMode mode = RunMode::Gui;
    std::string guiFile;                           // mission or raster to open in GUI mode; may be empty
    std::string helpPlanner;                       // --help-planner
    std::string missionPath;                       // batch mode from a mission file
    std::string rasterPath;                        // batch mode with the mission given by flags
    std::string classesPath;                       // --classes
    std::string preset;                            // --preset
    std::vector<MapPoint> starts;                  // --start, in the order given
    std::string startCrs;                          // --start-crs; empty: the raster's CRS
    std::vector<std::optional<MapPoint>> chargers; // one per start (parse keeps them in step): its --charger
    std::string outputDirectory;
    std::optional<std::string> planner;
    std::optional<int> band;
    std::string areaPath;                      // --area: plan only inside its polygons
    std::string noGoPath;                      // --no-go: leave its polygons out
    std::vector<ParameterOverride> parameters; // --param, --purity, --open-paths, in the order given
    bool missingAsObstacle = false;
    bool quiet = false;
    std::vector<std::string> comparePlanners;   // --compare, resolved to planner names ("all" expanded)
    bool densePaths = false;                    // --dense-paths
    bool cellPolygons = false;                  // --cell-polygons
    std::vector<std::string> outputKeys;        // --outputs: export catalogue keys; empty: the default set
    int threads = 0;                            // --threads; 0: the machine's cores (mcpp::workerThreads)
    std::optional<int> maxWaypoints;            // --max-waypoints: every robot's autopilot item limit
    std::optional<io::VehicleType> vehicleType; // --vehicle: every robot's
    std::optional<double> altitudeMetres;       // --altitude: every robot's waypoint altitude
    std::optional<double> cruiseSpeedMetresPerSecond; // --cruise-speed: every robot's
    std::optional<double> flightTimeSeconds;          // --flight-time: every robot's, for waypoint files
    std::optional<double> turnaroundSeconds;          // --turnaround: every robot's, between mission parts
    std::optional<double> cameraTriggerMetres;        // --camera-trigger: every robot's photo distance
    std::optional<double> fieldOfViewScale;           // --fov-scale: every class's FOV times it
    std::optional<double> fieldOfViewMetres;          // --fov: every class's FOV set to it
    std::vector<SpeedEvent> events;                   // --event, in the order given

    [[nodiscard]] bool missionFromFlags() const { return missionPath.empty(); }
};

} // namespace mcpp::app
