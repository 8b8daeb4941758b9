#include "app/BatchRunner.hpp"

#include "app/BatchFailure.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/PlanExport.hpp"
#include "render/PlanImage.hpp"

#include <QSize>
#include <QString>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <system_error>
#include <unistd.h>

namespace mcpp::app {
namespace {

constexpr int planImageSide = 1600;
// Progress the planner reports in its first seconds is held back: it checks the starts only after
// building its cells, and an error found then should be the only line on stderr.
constexpr auto startCheckGracePeriod = std::chrono::seconds(3);

[[noreturn]] void badInput(const std::string& message) {
    throw BatchFailure(BatchFailure::badInput, message);
}
[[noreturn]] void internalError(const std::string& message) {
    throw BatchFailure(BatchFailure::internalError, message);
}

std::string formatNumber(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string formatPoint(MapPoint point) {
    return "(" + formatNumber(point.x, 2) + ", " + formatNumber(point.y, 2) + ")";
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items)
        text += (text.empty() ? "" : ", ") + item;
    return text;
}

// io errors usually name their file already; add it when one does not, so the line always says which.
std::string namingFile(const std::string& path, const std::string& message) {
    if (message.find(path) != std::string::npos)
        return message;
    const auto fileName = std::filesystem::path(path).filename().string();
    if (!fileName.empty() && message.find(fileName) != std::string::npos)
        return message;
    return path + ": " + message;
}

} // namespace

BatchRunner::BatchRunner(CommandLineOptions options, std::ostream& output, std::ostream& diagnostics)
    : options_(std::move(options)), output_(output), diagnostics_(diagnostics),
      progress_(diagnostics, !options_.quiet) {}

std::string BatchRunner::robotFileStem(int robot) {
    return "robot_" + std::to_string(robot);
}

int BatchRunner::run() {
    try {
        execute();
        return 0;
    } catch (const BatchFailure& failure) {
        diagnostics_ << "mcpp: " << failure.what() << '\n' << std::flush;
        return failure.exitCode();
    } catch (const std::exception& exception) {
        diagnostics_ << "mcpp: internal error: " << exception.what() << '\n' << std::flush;
        return BatchFailure::internalError;
    }
}

void BatchRunner::execute() {
    assembleMission();
    applyOverrides();
    loadRaster();
    chooseClassTable();
    const auto starts = startsInPlanningFrame();
    checkOutputFolder();
    for (const auto& warning : pendingWarnings_)
        warn(warning);
    pendingWarnings_.clear();
    const Plan plan = runPlanner(starts);
    for (const auto& warning : plan.warnings())
        warn(warning);
    writeOutputs(plan);
    printSummary(plan);
}

void BatchRunner::assembleMission() {
    if (!options_.missionFromFlags()) {
        auto loaded = io::loadMission(options_.missionPath);
        if (!loaded)
            badInput(namingFile(options_.missionPath, loaded.error()));
        mission_ = std::move(loaded.value());
        rasterPath_ = io::resolveRasterPath(mission_, options_.missionPath);
        if (mission_.robots.empty())
            badInput(options_.missionPath + ": robots: the mission has no robots");
        return;
    }
    mission_ = io::Mission{};
    mission_.rasterPath = options_.rasterPath;
    rasterPath_ = options_.rasterPath;
    if (!options_.classesPath.empty()) {
        auto table = io::loadClassTableCsv(options_.classesPath);
        if (!table)
            badInput(namingFile(options_.classesPath, table.error()));
        mission_.classes = std::move(table.value());
    } else {
        mission_.preset = options_.preset;
    }
    for (std::size_t i = 0; i < options_.starts.size(); ++i) {
        mission_.robots.push_back(
            io::RobotSpec{"robot " + std::to_string(i), options_.starts[i], options_.startCrs});
    }
}

void BatchRunner::applyOverrides() {
    if (options_.band)
        mission_.band = *options_.band;
    if (options_.planner)
        mission_.settings.planner = *options_.planner;
    if (options_.purityTolerance)
        mission_.settings.purityTolerance = *options_.purityTolerance;
    if (options_.openPaths)
        mission_.settings.closedTour = false;
    if (options_.missingAsObstacle)
        mission_.missingClassesAsObstacles = true;
}

void BatchRunner::loadRaster() {
    io::RasterLoadOptions loadOptions;
    loadOptions.band = mission_.band;
    auto loaded = io::loadLandCoverRaster(rasterPath_, loadOptions);
    if (!loaded)
        badInput(namingFile(rasterPath_, loaded.error()));
    raster_ = std::move(loaded.value());
    pendingWarnings_.insert(pendingWarnings_.end(), raster_.warnings.begin(), raster_.warnings.end());
}

void BatchRunner::chooseClassTable() {
    if (!mission_.preset.empty()) {
        // Asking for the preset alone first turns an unknown name into an error instead of a default table.
        auto preset = io::presetClassTable(mission_.preset);
        if (!preset)
            badInput(classesLabel() + ": " + preset.error());
    }
    classes_ = io::missionClassTable(mission_.classes, mission_.preset, raster_);
    if (const auto problem = classes_.validate())
        badInput(classesLabel() + ": " + *problem);

    const auto before = raster_.warnings.size();
    const auto reconciled =
        io::reconcileRasterWithTable(raster_, classes_, mission_.missingClassesAsObstacles);
    if (!reconciled) {
        const std::string hint = options_.missionFromFlags()
                                     ? "; --missing-as-obstacle does the latter"
                                     : "; classes.missing_as_obstacles does the latter";
        badInput(namingFile(rasterPath_, reconciled.error()) + hint);
    }
    for (auto i = before; i < raster_.warnings.size(); ++i)
        pendingWarnings_.push_back(raster_.warnings[i]);
}

std::vector<MapPoint> BatchRunner::startsInPlanningFrame() const {
    std::vector<MapPoint> starts;
    for (std::size_t i = 0; i < mission_.robots.size(); ++i) {
        const auto robot = static_cast<int>(i);
        const auto& spec = mission_.robots[i];
        if (!std::isfinite(spec.start.x) || !std::isfinite(spec.start.y))
            badInput(startLabel(robot) + ": not a finite point");
        MapPoint start = spec.start;
        if (!spec.startCrs.empty()) {
            auto converted = raster_.georeference.fromCrs(spec.startCrs, spec.start);
            if (!converted)
                badInput(startCrsLabel(robot) + ": " + converted.error());
            start = converted.value();
        } else if (raster_.warpedFromGeographic && options_.missionFromFlags()) {
            // The batch contract takes --start in the raster's own CRS, here longitude and latitude, while
            // the plan runs in a UTM zone. Only the CRS's name survives loading; WGS84 is the fallback,
            // metres away from any other datum. (Mission files keep planning-frame units:
            // docs/mission-format.md.)
            auto converted = raster_.georeference.fromCrs(raster_.sourceCrsName, spec.start);
            if (!converted)
                converted = raster_.georeference.fromCrs("EPSG:4326", spec.start);
            if (!converted)
                badInput(startLabel(robot) + ": " + converted.error());
            start = converted.value();
        } else {
            // Planning-frame units, scaled to metres when the raster's CRS counts in feet.
            auto converted = io::robotStartInPlanningFrame(spec, raster_.georeference);
            if (!converted)
                badInput(startLabel(robot) + ": " + converted.error());
            start = converted.value();
        }
        // With snapping the planner moves bad starts itself and warns; without, say exactly what is wrong.
        if (!mission_.settings.snapStartsToFreeCells)
            checkStartPixel(robot, start);
        starts.push_back(start);
    }
    return starts;
}

void BatchRunner::checkStartPixel(int robot, MapPoint start) const {
    const ClassGrid& grid = raster_.grid;
    const double column = std::floor((start.x - grid.originX) / grid.pixelWidth);
    const double row = std::floor((grid.originY - start.y) / grid.pixelHeight);
    if (column < 0.0 || row < 0.0 || column >= grid.columns || row >= grid.rows) {
        badInput(startLabel(robot) + ": " + formatPoint(start) + " is outside the raster (x " +
                 formatNumber(grid.originX, 2) + " to " + formatNumber(grid.maxX(), 2) + ", y " +
                 formatNumber(grid.minY(), 2) + " to " + formatNumber(grid.originY, 2) + ")");
    }
    const int c = static_cast<int>(column);
    const int r = static_cast<int>(row);
    if (grid.isOutside(c, r)) {
        badInput(startLabel(robot) + ": " + formatPoint(start) +
                 " is on a nodata pixel, outside the task area");
    }
    const auto value = grid.valueAt(c, r);
    const LandCoverClass* landCover = classes_.find(value);
    if (landCover != nullptr && !landCover->isTraversable()) {
        badInput(startLabel(robot) + ": " + formatPoint(start) + " is on class " + std::to_string(value) +
                 " \"" + landCover->name + "\", which robots cannot cross");
    }
}

void BatchRunner::checkOutputFolder() const {
    // Checked before planning and created only after it, so bad input never leaves an empty folder behind.
    namespace fs = std::filesystem;
    std::error_code code;
    fs::path folder = fs::absolute(fs::path(options_.outputDirectory), code);
    const std::string quotedFolder = "\"" + options_.outputDirectory + "\"";
    if (fs::exists(folder, code) && !fs::is_directory(folder, code))
        badInput("--out: " + quotedFolder + " is a file, not a folder");
    while (!fs::exists(folder, code) && folder.has_relative_path())
        folder = folder.parent_path();
    if (!fs::is_directory(folder, code)) {
        badInput("--out: cannot create folder " + quotedFolder + ": \"" + folder.string() +
                 "\" is not a folder");
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0) {
        badInput("--out: cannot write folder " + quotedFolder + ": \"" + folder.string() +
                 "\" is not writable");
    }
}

Plan BatchRunner::runPlanner(const std::vector<MapPoint>& starts) {
    const auto planner = makePlanner(mission_.settings.planner);
    if (!planner) {
        badInput(plannerLabel() + ": unknown planner \"" + mission_.settings.planner +
                 "\" (available: " + joined(availablePlanners()) + ")");
    }
    PlanningProblem problem;
    problem.grid = raster_.grid;
    problem.classes = classes_;
    problem.starts = starts;
    problem.settings = mission_.settings;
    const ProgressReporter reporter(
        [this](std::string_view stage, double fraction) { progress_.report(stage, fraction); });
    progress_.holdFor(startCheckGracePeriod);
    try {
        Plan plan = planner->plan(problem, reporter);
        progress_.release();
        return plan;
    } catch (const PlanningError& error) {
        progress_.discardHeld();
        if (error.kind() == PlanningError::Kind::Cancelled)
            internalError(std::string("planning cancelled: ") + error.what());
        if (!options_.missionFromFlags())
            badInput(options_.missionPath + ": " + error.what());
        const auto kind = error.kind();
        const bool aboutStarts =
            kind == PlanningError::Kind::StartOutsideArea || kind == PlanningError::Kind::StartOnObstacle ||
            kind == PlanningError::Kind::StartsShareCell || kind == PlanningError::Kind::TooManyRobots;
        badInput(aboutStarts ? "--start: " + std::string(error.what()) +
                                   " (robots are numbered from 0 in --start order)"
                             : std::string(error.what()));
    }
}

void BatchRunner::writeOutputs(const Plan& plan) {
    namespace fs = std::filesystem;
    const fs::path directory(options_.outputDirectory);
    std::error_code code;
    fs::create_directories(directory, code);
    if (code || !fs::is_directory(directory)) {
        badInput("--out: cannot create folder \"" + options_.outputDirectory + "\"" +
                 (code ? ": " + code.message() : std::string(": a file of that name exists")));
    }
    const auto pathOf = [&directory](const std::string& name) { return (directory / name).string(); };
    const io::ExportContext context{plan, raster_.georeference, classes_, mission_.exports};
    const int robots = static_cast<int>(plan.paths.size());

    struct Output {
        std::string name;
        std::function<io::Status(const std::string&)> write;
        bool required;
    };
    std::vector<Output> outputs{
        {"plan.geojson", [&](const std::string& path) { return io::writePlanGeoJson(context, path); }, true},
        {"report.json", [&](const std::string& path) { return io::writeReportJson(context, path); }, true},
        {"report.csv", [&](const std::string& path) { return io::writeReportCsv(context, path); }, false},
        {"plan.gpkg", [&](const std::string& path) { return io::writePlanGeoPackage(context, path); }, false},
    };
    for (int robot = 0; robot < robots; ++robot) {
        const auto stem = robotFileStem(robot);
        outputs.push_back({stem + ".plan",
                           [&context, robot](const std::string& path) {
                               return io::writeQGroundControlPlan(context, robot, path);
                           },
                           true});
        outputs.push_back({stem + ".waypoints",
                           [&context, robot](const std::string& path) {
                               return io::writeWaypointList(context, robot, path);
                           },
                           true});
        outputs.push_back({stem + ".csv",
                           [&context, robot](const std::string& path) {
                               return io::writeWaypointCsv(context, robot, path);
                           },
                           true});
    }
    outputs.push_back({"plan.png",
                       [&](const std::string& path) {
                           QString error;
                           if (render::writePlanPng(raster_.grid, classes_, plan,
                                                    QString::fromStdString(path),
                                                    QSize(planImageSide, planImageSide), &error)) {
                               return io::Status();
                           }
                           return io::Status::failure(path + ": " + error.toStdString());
                       },
                       true});

    const auto total = static_cast<double>(outputs.size());
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        progress_.report("writing outputs", static_cast<double>(i) / total);
        const auto path = pathOf(outputs[i].name);
        const auto status = outputs[i].write(path);
        if (status)
            continue;
        if (outputs[i].required)
            internalError(namingFile(path, status.error()));
        warn(outputs[i].name + " not written: " + status.error());
    }
    progress_.report("writing outputs", 1.0);

    // Waypoint files of robots a previous run in this folder had and this one has not would mislead.
    for (int robot = robots;; ++robot) {
        bool removed = false;
        for (const char* extension : {".plan", ".waypoints", ".csv"}) {
            removed = fs::remove(pathOf(robotFileStem(robot) + extension), code) || removed;
        }
        if (!removed)
            break;
    }
}

void BatchRunner::printSummary(const Plan& plan) const {
    if (options_.quiet)
        return;
    const PlanMetrics& metrics = plan.metrics;
    output_ << "mcpp: planned " << plan.paths.size() << " robots with " << plan.planner << ": makespan "
            << formatNumber(metrics.makespanSeconds, 1) << " s, lower bound "
            << formatNumber(metrics.lowerBoundSeconds, 1) << " s, ratio " << formatNumber(metrics.ratio, 3)
            << ", covered " << formatNumber(metrics.coveredFraction * 100.0, 1) << "% of the passable area\n"
            << "mcpp: outputs in " << options_.outputDirectory << '\n'
            << std::flush;
}

void BatchRunner::warn(const std::string& message) {
    if (!options_.quiet)
        diagnostics_ << "mcpp: warning: " << message << '\n' << std::flush;
}

std::string BatchRunner::startLabel(int robot) const {
    if (options_.missionFromFlags())
        return "--start " + std::to_string(robot + 1);
    return options_.missionPath + ": robots[" + std::to_string(robot) + "].start";
}

std::string BatchRunner::startCrsLabel(int robot) const {
    if (options_.missionFromFlags())
        return "--start-crs";
    return options_.missionPath + ": robots[" + std::to_string(robot) + "].start_crs";
}

std::string BatchRunner::classesLabel() const {
    if (options_.missionFromFlags())
        return options_.classesPath.empty() ? "--preset" : options_.classesPath;
    return options_.missionPath + ": classes";
}

std::string BatchRunner::plannerLabel() const {
    if (options_.planner || options_.missionFromFlags())
        return "--planner";
    return options_.missionPath + ": planner";
}

} // namespace mcpp::app
