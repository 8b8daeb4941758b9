#include "app/BatchRunner.hpp"

#include "app/BatchFailure.hpp"
#include "app/WriterWarmUp.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/SpeedEventCheck.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/model/TimelineText.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/ComparisonExport.hpp"
#include "io/ComparisonRanking.hpp"
#include "io/ExportCatalogue.hpp"
#include "io/LongPlanCauses.hpp"
#include "io/MissionScale.hpp"
#include "io/PlanExport.hpp"
#include "io/PointsInDegrees.hpp"
#include "render/ComparisonSheet.hpp"
#include "render/PlanImageWriter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sys/resource.h>
#include <system_error>
#include <unistd.h>
#include <utility>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace mcpp::app {
namespace {

// Hands memory the process has freed back to the system: glibc keeps freed heap pages until asked.
void returnFreedMemory() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

using Part = io::MissionField::Part;

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

// io errors usually name their file already; add it when one does not, so the line always says which.
std::string namingFile(const std::string& path, const std::string& message) {
    if (message.find(path) != std::string::npos)
        return message;
    const auto fileName = std::filesystem::path(path).filename().string();
    if (!fileName.empty() && message.find(fileName) != std::string::npos)
        return message;
    return path + ": " + message;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Sets the kernel's high-water mark of resident memory back to what is resident now, so the next
// peakMemoryMegabytes() is the peak since; false where it cannot (not Linux), the peak then the process's.
bool restartPeakMemory() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.close();
    return !clear.fail();
}

// A line of /proc/self/status in megabytes ("VmHWM:", "VmRSS:"); nothing where the system has none.
std::optional<double> statusMegabytes(const char* field) {
    std::ifstream status("/proc/self/status");
    const std::string prefix(field);
    for (std::string line; std::getline(status, line);)
        if (line.rfind(prefix, 0) == 0)
            return std::strtod(line.c_str() + prefix.size(), nullptr) / 1024.0; // given in kB
    return std::nullopt;
}

// The high-water mark of resident memory: since restartPeakMemory() where the kernel keeps one.
double peakMemoryMegabytes() {
    if (const auto peak = statusMegabytes("VmHWM:"))
        return *peak;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

double residentMegabytes() {
    return statusMegabytes("VmRSS:").value_or(0.0);
}

template <typename T> T valueOrBadInput(io::Result<T> result) {
    if (!result)
        badInput(result.error());
    return std::move(result.value());
}

// Where robots alone in parts of their own set the bound, every plan's ratio is theirs: the others' too.
std::string sharedPartsText(const PlanMetrics& metrics) {
    if (!metrics.boundSetByLoneRobots())
        return {};
    return " (set by robots alone in parts of their own; the robots sharing parts: " +
           formatNumber(metrics.sharedPartsRatio, 3) + ")";
}

// A detection plan's bound is of another kind than the others': its ratio says so beside it.
std::string boundKindText(const PlanMetrics& metrics) {
    if (!metrics.boundOfDetectionPasses)
        return {};
    return " (a bound of the passes its targets need, each at the fastest class's speed: looser than other "
           "plans' bounds)";
}

// "the robots need 155 d 13 h for all the raster's land: …": what to change, in the command line's words.
std::string longPlanAdvice(const io::LongPlanCauses& causes, std::size_t robots, double makespanSeconds) {
    std::string advice =
        (robots == 1 ? "the robot needs " : "the robots need ") + formatDuration(makespanSeconds);
    if (causes.wholeRaster)
        advice += " for all the raster's land: to plan part of it, give the area's polygons (--area FILE, or "
                  "area.include in a mission file); for a wider sensor footprint, --fov or --fov-scale";
    if (causes.groundSpeeds)
        advice +=
            std::string(causes.wholeRaster ? "; if" : ": if") +
            " the robots fly, give --vehicle multirotor (or fixed-wing) and --cruise-speed M/S (the class "
            "table's speeds, " +
            formatQuantity(causes.slowestSpeedMetresPerSecond, 3) +
            (causes.fastestSpeedMetresPerSecond > causes.slowestSpeedMetresPerSecond
                 ? " to " + formatQuantity(causes.fastestSpeedMetresPerSecond, 3)
                 : std::string()) +
            " m/s, are a ground robot's)";
    return advice;
}

} // namespace

BatchRunner::BatchRunner(CommandLineOptions options, std::ostream& output, std::ostream& diagnostics)
    : options_(std::move(options)), output_(output), diagnostics_(diagnostics),
      progress_(diagnostics, !options_.quiet) {}

int BatchRunner::run() {
    try {
        if (options_.comparePlanners.empty())
            execute();
        else
            executeComparison();
        return exitCode_;
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
    checkVehicles();
    auto started = std::chrono::steady_clock::now();
    loadRaster();
    processMilliseconds_.emplace_back("read_raster", millisecondsSince(started));
    prepareMission();
    PlanningProblem problem = prepareProblem();
    checkOutputFolder();
    flushPending();
    started = std::chrono::steady_clock::now();
    const bool lent = lendPixelsTo(problem);
    const Plan plan = [&] {
        const WriterWarmUp warmUp(raster_.georeference, workerThreads());
        return runPlanner(problem);
    }();
    processMilliseconds_.emplace_back("plan", millisecondsSince(started));
    sayMissionNotes(plan, problem);
    if (lent) {
        raster_.grid.values = std::move(problem.grid.values);
        raster_.grid.outside = std::move(problem.grid.outside);
    }
    // The writers need the plan and the raster as read, not the problem's copy of its classes; on a large
    // map the planner's freed memory and that copy are a few hundred megabytes the writers can reuse.
    problem = PlanningProblem{};
    returnFreedMemory();
    for (const auto& warning : plan.warnings())
        warn(planMessage(warning));
    writeOutputs(plan, options_.outputDirectory);
    printSummary(plan);
}

// While the planner works, the raster's pixels live only in the problem's copy of them, where the two are
// the same (no class the table lacks was set outside): five bytes a pixel fewer at the planner's peak (160 MB
// on a map of 32 M pixels). Messages meanwhile read the grid's size and place, which it keeps. Every error
// while planning ends the run before anything reads the pixels; values are compared by size only, as
// io::planningProblem copies them unchanged (reconciling a class table sets `outside` alone).
bool BatchRunner::lendPixelsTo(const PlanningProblem& problem) {
    ClassGrid& grid = raster_.grid;
    if (grid.values.size() != problem.grid.values.size() || grid.outside != problem.grid.outside)
        return false;
    std::vector<std::int32_t>().swap(grid.values);
    std::vector<std::uint8_t>().swap(grid.outside);
    return true;
}

void BatchRunner::assembleMission() {
    if (!options_.missionFromFlags()) {
        auto loaded = io::loadMission(options_.missionPath);
        if (!loaded)
            badInput(namingFile(options_.missionPath, loaded.error()));
        mission_ = std::move(loaded.value());
        if (mission_.robots.empty())
            badInput(options_.missionPath + ": robots: the mission has no robots");
        return;
    }
    mission_ = io::Mission{};
    mission_.rasterPath = options_.rasterPath;
    if (!options_.classesPath.empty()) {
        auto table = io::loadClassTableCsv(options_.classesPath, &mission_.classesWithoutColour);
        if (!table)
            badInput(namingFile(options_.classesPath, table.error()));
        mission_.classes = std::move(table.value());
    } else {
        mission_.preset = options_.preset;
    }
    for (std::size_t i = 0; i < options_.starts.size(); ++i) {
        io::RobotSpec robot{"Robot " + std::to_string(i + 1), options_.starts[i], options_.startCrs};
        robot.charger = options_.chargers[i];
        mission_.robots.push_back(std::move(robot));
    }
}

// --event flags join the mission's events once its robots are known.
void BatchRunner::addEventFlags() {
    for (const SpeedEvent& event : options_.events) {
        if (const auto wrong = speedEventProblem(event, mission_.robots.size()))
            badInput("--event " + formatQuantity(event.timeSeconds) + ":" + std::to_string(event.robot) +
                     ":" + formatQuantity(event.speedFactor) + ": " + wrong->field + ": " + wrong->detail);
        mission_.events.push_back(event);
    }
}

void BatchRunner::applyOverrides() {
    if (options_.band)
        mission_.band = *options_.band;
    // Given on the command line, relative to where the command runs, like --raster.
    const auto absolute = [](const std::string& path) { return std::filesystem::absolute(path).string(); };
    if (!options_.areaPath.empty())
        mission_.area.includePath = absolute(options_.areaPath);
    if (!options_.noGoPath.empty())
        mission_.area.excludePath = absolute(options_.noGoPath);
    if (options_.planner)
        mission_.planner = switchPlanner(mission_.planner, *options_.planner);
    if (options_.missingAsObstacle)
        mission_.missingClassesAsObstacles = true;
    if (options_.densePaths)
        mission_.exports.densePaths = true;
    if (options_.cellPolygons)
        mission_.exports.cellPolygons = true;
    applyVehicleFlags();
    addEventFlags();
    const auto planner = findPlannerDescription(mission_.planner.planner);
    if (!planner)
        badInput(fieldName(io::MissionField::of(Part::Planner)) + ": " +
                 unknownPlannerMessage(mission_.planner.planner));
    if (!options_.comparePlanners.empty())
        return; // each compared planner takes the --param values it declares (comparedPlanner)
    for (const ParameterOverride& parameter : options_.parameters) {
        const ParameterSpec* spec = findParameter(planner->parameters, parameter.key);
        if (spec == nullptr)
            badInput(parameter.flag + ": planner " + planner->name + " has no parameter " + parameter.key +
                     " " + knownParametersNote(parameter.key, planner->parameters));
        std::string problem;
        const auto value = spec->parse(parameter.value, &problem);
        if (!value)
            badInput(parameter.flag + ": " + problem);
        mission_.planner.parameters.set(parameter.key, *value);
    }
}

void BatchRunner::loadRaster() {
    const std::string missionPath = options_.missionFromFlags() ? std::string() : options_.missionPath;
    auto loaded = io::loadMissionRasterAlone(mission_, missionPath);
    if (!loaded) {
        const std::string rasterPath = io::resolveRasterPath(mission_, missionPath);
        // A file that is not there, named where it was given: the flag, or the mission file and its key.
        std::error_code error;
        const bool absent = !std::filesystem::exists(rasterPath, error);
        const std::string given = missionPath.empty() ? "--raster: " : missionPath + ": raster.path: ";
        badInput((absent ? given : std::string()) + namingFile(rasterPath, loaded.error()));
    }
    raster_ = std::move(loaded.value());
    if (const io::Status area = io::applyMissionArea(raster_, mission_, missionPath); !area)
        badInput(areaGivenIn(area.error()) +
                 (namesNoGoFile(area.error()) ? "no-go zones: " : "area of interest: ") +
                 area.error()); // the message names the polygon file
    pendingNotes_.insert(pendingNotes_.end(), raster_.notes.begin(), raster_.notes.end());
    pendingWarnings_.insert(pendingWarnings_.end(), raster_.warnings.begin(), raster_.warnings.end());
}

// Whether a message about the area's polygons names the no-go zones' file and not the area's.
bool BatchRunner::namesNoGoFile(const std::string& message) const {
    const auto names = [&](const std::string& path) {
        return !path.empty() &&
               message.find(std::filesystem::path(path).filename().string()) != std::string::npos;
    };
    return names(mission_.area.excludePath) && !names(mission_.area.includePath);
}

// Where the polygon file a message names was given: its flag, or the mission file and its key.
std::string BatchRunner::areaGivenIn(const std::string& message) const {
    if (namesNoGoFile(message))
        return options_.noGoPath.empty() ? options_.missionPath + ": area.exclude: " : "--no-go: ";
    return options_.areaPath.empty() ? options_.missionPath + ": area.include: " : "--area: ";
}

void BatchRunner::prepareMission() {
    const io::FieldNamer names = fieldNamer();
    if (mission_.classes.empty() && mission_.preset.empty()) {
        // Neither rows nor a preset: the table the raster's product or legend gives, read once and said.
        io::OpeningClassTable opening = io::openingClassTable(raster_);
        note(opening.explanation);
        mission_.classes = std::move(opening.table);
    }
    classes_ = valueOrBadInput(io::missionClasses(mission_, raster_, names));
    if (auto gap = io::presetGapWarning(mission_, raster_))
        pendingWarnings_.push_back(std::move(*gap));
    if (options_.fieldOfViewScale)
        scaleFieldsOfView(*options_.fieldOfViewScale);
    if (options_.fieldOfViewMetres)
        setFieldsOfView(*options_.fieldOfViewMetres);
    warnIfLarge();
    // The batch contract takes --start in the raster file's CRS; mission files keep planning-CRS units.
    const auto units =
        options_.missionFromFlags() ? io::StartUnits::RasterFileCrs : io::StartUnits::PlanningCrs;
    starts_ = valueOrBadInput(io::missionStarts(mission_, raster_, units, names));
    chargers_ = valueOrBadInput(io::missionChargers(mission_, raster_, units, names));
}

// Settings each fine alone that no vehicle can fly together, checked once flags and robots' own are merged.
void BatchRunner::checkVehicles() const {
    const auto problem = io::fleetFlightProblem(mission_);
    if (!problem)
        return;
    // Where the settings are given: the flags that set them, else the mission's robots and exports.
    std::vector<std::string> flags;
    if (options_.vehicleType)
        flags.push_back("--vehicle");
    if (options_.flightTimeSeconds)
        flags.push_back("--flight-time");
    if (options_.altitudeMetres)
        flags.push_back("--altitude");
    if (options_.missionFromFlags() && flags.empty())
        flags = {"--flight-time", "--altitude"};
    std::string given;
    for (const std::string& flag : flags)
        given += (given.empty() ? "" : ", ") + flag;
    if (options_.missionFromFlags())
        badInput(*problem + " (" + given + ")");
    badInput(
        options_.missionPath + ": " + *problem +
        " (robots[].flight_time_s and altitude_m, or exports.flight_time_s and altitude_m for every robot" +
        (given.empty() ? std::string() : "; given here by " + given) + ")");
}

void BatchRunner::refuseMission(const std::string& error) {
    if (auto otherProduct = io::presetOfAnotherProductWarning(mission_, raster_))
        warn(*otherProduct);
    badInput(error);
}

PlanningProblem BatchRunner::prepareProblem() {
    auto problem = io::planningProblem(raster_, classes_, mission_.missingClassesAsObstacles, starts_,
                                       mission_.planner, fieldNamer(), io::flyingRobots(mission_));
    if (!problem)
        refuseMission(problem.error());
    io::PreparedProblem prepared = std::move(problem.value());
    pendingWarnings_.insert(pendingWarnings_.end(), prepared.warnings.begin(), prepared.warnings.end());
    io::applyRobotSettings(mission_, raster_, prepared.problem);
    prepared.problem.chargers = chargers_; // its notes are said with the plan (sayMissionNotes)
    return std::move(prepared.problem);
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
    // A folder made and removed again: the permission bits do not tell for root or special file systems.
    std::string probe = (folder / ".mcpp-write-check-XXXXXX").string();
    if (::access(folder.c_str(), W_OK | X_OK) != 0 || ::mkdtemp(probe.data()) == nullptr) {
        badInput("--out: cannot write folder " + quotedFolder + ": \"" + folder.string() +
                 "\" is not writable");
    }
    fs::remove(probe, code);
}

// Messages number robots from 1, as the --start flags do: robots given by those flags need no names.
std::vector<std::string> BatchRunner::robotNamesForMessages() const {
    return options_.missionFromFlags() ? std::vector<std::string>{} : io::robotNames(mission_);
}

std::string BatchRunner::planMessage(const std::string& message) const {
    return io::messageForPeople(message, &raster_, robotNamesForMessages());
}

Plan BatchRunner::runPlanner(const PlanningProblem& problem) {
    const auto planner = makePlanner(problem.planner.planner);
    if (!planner)
        badInput(fieldName(io::MissionField::of(Part::Planner)) + ": " +
                 unknownPlannerMessage(problem.planner.planner));
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
        // Its map points with their degrees, as the starts checked before planning are given (the raster
        // lent its pixels, not its size and place).
        if (const auto named = io::planningErrorText(error, fieldNamer(), robotNamesForMessages(), true))
            refuseMission(io::withPointsInDegrees(*named, raster_.georeference, raster_.grid) +
                          (error.aboutCharger() && error.kind() == PlanningError::Kind::StartOutsideArea
                               ? io::chargerInDegreesHint(mission_, raster_, error.robot())
                               : std::string()));
        badInput(options_.missionFromFlags() ? std::string(error.what())
                                             : options_.missionPath + ": " + error.what());
    }
}

void BatchRunner::writeOutputs(const Plan& plan, const std::string& folder) {
    namespace fs = std::filesystem;
    const fs::path directory(folder);
    std::error_code code;
    fs::create_directories(directory, code);
    if (code || !fs::is_directory(directory)) {
        badInput("--out: cannot create folder \"" + folder + "\"" +
                 (code ? ": " + code.message() : std::string(": a file of that name exists")));
    }
    io::ExportContext context{plan, raster_.georeference, classes_, mission_.exports};
    context.grid = &raster_.grid;
    context.area = &raster_.area;
    context.drawImage = render::planImageWriter(planImageSide);
    context.robotNames = io::robotNames(mission_);
    context.vehicles = io::robotVehicles(mission_);
    context.inputWarnings = inputWarnings_;
    context.inputWarnings.insert(context.inputWarnings.end(), plannerWarnings_.begin(),
                                 plannerWarnings_.end());
    const int robots = static_cast<int>(plan.paths.size());

    struct Output {
        const io::ExportFormat* format;
        int robot; // -1 for whole-plan formats
        std::string name;
    };
    std::vector<Output> outputs; // catalogue order, in which results are reported
    std::string withoutCrs;      // outputs a map without a CRS cannot have
    const auto asked = [&](const io::ExportFormat& format) {
        const std::vector<std::string>& keys = options_.outputKeys;
        return keys.empty() ? format.inBatchOutputs
                            : std::find(keys.begin(), keys.end(), format.key) != keys.end();
    };
    for (const io::ExportFormat& format : io::exportFormats()) {
        if (!asked(format))
            continue;
        if (!io::formatApplies(format, plan)) {
            // Left from a plan that had it, it would describe another plan.
            std::error_code failed;
            if (!format.perRobot && !format.batchFileName.empty() &&
                !fs::remove(directory / format.batchFileName, failed) && failed)
                warn("cannot remove " + format.batchFileName +
                     " left by an earlier run, which describes another "
                     "plan: " +
                     failed.message());
            continue;
        }
        if (format.needsLongitudeLatitude && !raster_.georeference.hasCrs()) {
            withoutCrs += (withoutCrs.empty() ? "" : ", ") + io::batchOutputName(format);
            continue;
        }
        if (!format.perRobot) {
            outputs.push_back({&format, -1, format.batchFileName});
            continue;
        }
        for (int robot = 0; robot < robots; ++robot)
            outputs.push_back({&format, robot, io::robotFileName(robot, robots, format)});
    }
    if (!withoutCrs.empty())
        warn("the map has no CRS, so these outputs, in longitude and latitude, are not written: " +
             withoutCrs);
    const auto isReport = [&](std::size_t i) { return outputs[i].format->key == "report-json"; };
    // report.json comes last, so that it can say how long the others took; the picture, the longest on
    // small plans, first, so that the rest are written beside it. The robots' files come next: the
    // picture traces the region outlines, which the other whole-plan files wait for, and meanwhile the
    // second thread has the robots' files to write (on a 69 M-cell map it otherwise idled for 3 s).
    const auto rank = [&](std::size_t i) {
        if (outputs[i].format->key == "png")
            return 0;
        return outputs[i].robot >= 0 ? 1 : 2;
    };
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < outputs.size(); ++i)
        if (!isReport(i))
            order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
    std::vector<io::Status> results(outputs.size());
    const auto write = [&](std::size_t i) {
        results[i] =
            outputs[i].format->write(context, outputs[i].robot, (directory / outputs[i].name).string());
    };
    const auto started = std::chrono::steady_clock::now();
    std::mutex progressMutex;
    std::size_t finished = 0;
    parallelFor(order.size(), [&](std::size_t k, int) {
        write(order[k]);
        const std::lock_guard lock(progressMutex);
        progress_.report("writing outputs",
                         static_cast<double>(++finished) / static_cast<double>(outputs.size()));
    });
    context.processMilliseconds = processMilliseconds_;
    context.processMilliseconds.emplace_back("write_outputs", millisecondsSince(started));
    for (std::size_t i = 0; i < outputs.size(); ++i)
        if (results[i] && outputs[i].format->noteOf)
            if (std::string said = outputs[i].format->noteOf(context, (directory / outputs[i].name).string());
                !said.empty())
                context.outputNotes.push_back(std::move(said));
    for (std::size_t i = 0; i < outputs.size(); ++i)
        if (isReport(i))
            write(i);
    progress_.report("writing outputs", 1.0);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (results[i])
            continue;
        if (outputs[i].format->requiredInBatch)
            internalError(namingFile((directory / outputs[i].name).string(), results[i].error()));
        warn(outputs[i].name + " not written: " + results[i].error());
    }
    for (const std::string& said : context.outputNotes)
        note(said);
    // Parts of each robot's autopilot files this run wrote (0: none), by robot and format key.
    std::map<std::pair<int, std::string>, std::size_t> partsWritten;
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const io::ExportFormat& format = *outputs[i].format;
        if (format.splitByItemLimit && results[i])
            partsWritten[{outputs[i].robot, format.key}] =
                io::autopilotMissionOf(context, outputs[i].robot).parts.size();
    }
    for (int robot = 0; robot < robots; ++robot)
        if (partsWritten.count({robot, "qgc-plan"}) != 0)
            noteMissionFiles(context, robot);
    if (!partsWritten.empty()) {
        fieldTimeNote_ = io::fieldTimeNote(context);
        fieldBoundNote_ = io::fieldBoundNote(context);
    }
    // After the writers, which made the missions on both cores (report.json always counts the flights).
    flightsOverBattery_ = io::flightsOverBattery(context);
    removeStaleRobotFiles(robots, partsWritten, folder);
}

// --fov-scale: every class's field of view times the factor, checked as a table is.
void BatchRunner::scaleFieldsOfView(double factor) {
    std::vector<LandCoverClass> classes = classes_.classes();
    for (LandCoverClass& landCover : classes)
        landCover.fieldOfViewMetres *= factor;
    classes_ = ClassTable(std::move(classes));
    if (const auto problem = classes_.validate())
        badInput("--fov-scale " + formatQuantity(factor) + ": " + *problem);
    note("every class's field of view times " + formatQuantity(factor) + " (--fov-scale)");
}

// --fov: every class's field of view the same, as a camera's footprint is over any land cover.
// Said before the work starts: a mission of tens of millions of cells plans for minutes (a comparison of
// every planner for hours) and writes gigabytes. Counted on a uniform grid where some planner plans on one.
void BatchRunner::warnIfLarge() {
    std::vector<PlannerChoice> planners;
    if (options_.comparePlanners.empty())
        planners.push_back(mission_.planner);
    for (const std::string& name : options_.comparePlanners) {
        if (findPlannerDescription(name)->singleRobot && mission_.robots.size() > 1)
            continue;
        try {
            planners.push_back(comparedPlanner(name));
        } catch (const BatchFailure&) {
            // a value its parameter refuses: said on its row when it runs
        }
    }
    const auto remedy = [&](double factor) {
        if (options_.fieldOfViewMetres)
            return "--fov " + formatQuantity(*options_.fieldOfViewMetres * factor, 2);
        return "--fov-scale " + formatQuantity(options_.fieldOfViewScale.value_or(1.0) * factor, 2);
    };
    auto warning = io::largeMissionWarning(mission_, raster_, classes_, planners, remedy);
    if (!warning)
        return;
    // Every planner's waypoint files of a large map run to thousands of files and gigabytes.
    if (!options_.comparePlanners.empty() && options_.outputKeys.empty())
        *warning += "; --outputs png leaves out each planner's waypoint files and vector layers";
    pendingWarnings_.push_back(std::move(*warning));
}

void BatchRunner::setFieldsOfView(double metres) {
    classes_.setEveryFieldOfView(metres);
    note("every class's field of view set to " + formatQuantity(metres) + " m (--fov)");
}

// Vehicle flags set every robot's value: the mission's default, and no robot keeps its own.
void BatchRunner::applyVehicleFlags() {
    io::VehicleSettings& fleet = mission_.exports.vehicle;
    const auto apply = [this](const auto& flag, auto& setting, auto member) {
        if (!flag)
            return;
        setting = *flag;
        for (io::RobotSpec& robot : mission_.robots)
            (robot.vehicle.*member).reset();
    };
    apply(options_.maxWaypoints, fleet.maxWaypoints, &io::VehicleOverrides::maxWaypoints);
    apply(options_.vehicleType, fleet.type, &io::VehicleOverrides::type);
    apply(options_.altitudeMetres, fleet.altitudeMetres, &io::VehicleOverrides::altitudeMetres);
    apply(options_.cruiseSpeedMetresPerSecond, fleet.cruiseSpeedMetresPerSecond,
          &io::VehicleOverrides::cruiseSpeedMetresPerSecond);
    apply(options_.flightTimeSeconds, fleet.flightTimeSeconds, &io::VehicleOverrides::flightTimeSeconds);
    apply(options_.turnaroundSeconds, fleet.turnaroundSeconds, &io::VehicleOverrides::turnaroundSeconds);
    apply(options_.cameraTriggerMetres, fleet.cameraTriggerMetres,
          &io::VehicleOverrides::cameraTriggerMetres);
}

void BatchRunner::noteMissionFiles(const io::ExportContext& context, int robot) {
    // Named by the .plan file; the .waypoints files are split the same way.
    const std::string file = io::robotFileStem(robot, static_cast<int>(context.plan.paths.size())) + ".plan";
    const std::string message = io::splitMissionNote(context, robot, file);
    if (!message.empty())
        note(message + "; the .waypoints file is split into the same parts");
    const std::string sorties = io::sortieFilesNote(context, robot, file);
    if (!sorties.empty())
        note(sorties + ", and as .waypoints files");
    if (const std::string tooLong = io::flightTimeWarning(context, robot, file); !tooLong.empty())
        warn(tooLong);
}

void BatchRunner::removeStaleRobotFiles(
    int robots, const std::map<std::pair<int, std::string>, std::size_t>& partsWritten,
    const std::string& folder) const {
    // Waypoint files a previous run in this folder wrote and this one has not would mislead: those of
    // robots it no longer has or numbered to another width, a whole mission now split into parts, parts of
    // a mission now whole or shorter.
    const std::filesystem::path directory(folder);
    for (const io::ExportFormat& format : io::exportFormats()) {
        if (!format.inBatchOutputs || !format.perRobot)
            continue;
        io::removeStaleRobotFiles(folder, format.extension, robots);
        if (!format.splitByItemLimit)
            continue;
        for (int robot = 0; robot < robots; ++robot) {
            const auto written = partsWritten.find({robot, format.key});
            const std::size_t parts = written == partsWritten.end() ? 0 : written->second;
            io::removeStaleMissionFiles((directory / io::robotFileName(robot, robots, format)).string(),
                                        parts);
        }
    }
}

bool BatchRunner::someComparedPlannerSnapsStarts() const {
    const auto snaps = [&](const std::string& name) {
        try {
            const ParameterValues values =
                resolveParameters(findPlannerDescription(name)->parameters, comparedPlanner(name).parameters);
            return values.has("snap_starts_to_free_cells") && values.boolean("snap_starts_to_free_cells");
        } catch (const std::exception&) {
            return false; // a bad value is said as that planner's failure when its turn comes
        }
    };
    const bool severalRobots = mission_.robots.size() > 1;
    return std::any_of(
        options_.comparePlanners.begin(), options_.comparePlanners.end(), [&](const std::string& name) {
            // One-robot planners are skipped for several robots: their settings do not count.
            return !(severalRobots && findPlannerDescription(name)->singleRobot) && snaps(name);
        });
}

PlannerChoice BatchRunner::comparedPlanner(const std::string& name) const {
    PlannerChoice choice = switchPlanner(mission_.planner, name);
    const auto planner = findPlannerDescription(name);
    for (const ParameterOverride& parameter : options_.parameters) {
        const ParameterSpec* spec = findParameter(planner->parameters, parameter.key);
        if (spec == nullptr)
            continue; // checked against all compared planners in executeComparison
        std::string problem;
        const auto value = spec->parse(parameter.value, &problem);
        if (!value)
            badInput(parameter.flag + ": " + problem);
        choice.parameters.set(parameter.key, *value);
    }
    return choice;
}

void BatchRunner::executeComparison() {
    namespace fs = std::filesystem;
    assembleMission();
    applyOverrides();
    checkVehicles();
    for (const ParameterOverride& parameter : options_.parameters) {
        const bool declared = std::any_of(
            options_.comparePlanners.begin(), options_.comparePlanners.end(), [&](const std::string& name) {
                return findParameter(findPlannerDescription(name)->parameters, parameter.key) != nullptr;
            });
        if (!declared)
            badInput(parameter.flag + ": none of the compared planners has a parameter " + parameter.key);
    }
    auto started = std::chrono::steady_clock::now();
    loadRaster();
    const double readMilliseconds = millisecondsSince(started);
    // Faults of the mission itself (classes, starts) are said once, not once for each planner.
    prepareMission();
    if (!someComparedPlannerSnapsStarts())
        if (const io::Status starts = io::checkStarts(raster_, classes_, mission_.missingClassesAsObstacles,
                                                      starts_, fieldNamer(), io::flyingRobots(mission_));
            !starts)
            refuseMission(starts.error());
    checkOutputFolder();
    flushPending();
    const std::size_t robots = mission_.robots.size();
    std::vector<io::ComparisonRow> rows;
    std::vector<std::optional<Plan>> plans;
    std::set<std::string> saidOnce; // the mission's own warnings and notes, which every plan carries
    returnFreedMemory();
    const double residentWithRaster = residentMegabytes();
    for (std::size_t i = 0; i < options_.comparePlanners.size(); ++i) {
        const std::string& name = options_.comparePlanners[i];
        progress_.report("planner " + std::to_string(i + 1) + " of " +
                             std::to_string(options_.comparePlanners.size()) + ": " + name,
                         0.0);
        io::ComparisonRow row;
        row.planner = name;
        plans.emplace_back();
        if (findPlannerDescription(name)->singleRobot && robots > 1) {
            row.outcome = io::ComparisonRow::Outcome::Skipped;
            row.message = name + " plans for one robot and the mission has " + std::to_string(robots);
            rows.push_back(row);
            continue;
        }
        // What is said while it plans and writes belongs to it: several planners write the same notes.
        plannerPrefix_ = name + ": ";
        try {
            // The plans before this one stay for the comparison sheet: its peak is counted above what they
            // and the heap they freed hold, as if it ran alone on the raster (its problem's copy of the
            // grid included, as there).
            returnFreedMemory();
            const double residentBefore = residentMegabytes();
            const bool ownPeak = restartPeakMemory();
            mission_.planner = comparedPlanner(name);
            const PlanningProblem problem = prepareProblem();
            plannerWarnings_ = pendingWarnings_;
            for (const auto& warning : pendingWarnings_)
                warn(warning);
            pendingWarnings_.clear();
            started = std::chrono::steady_clock::now();
            Plan plan = runPlanner(problem);
            row.planningMilliseconds = millisecondsSince(started);
            sayMissionNotes(plan, problem, &saidOnce);
            sayComparedPlanWarnings(plan, problem, saidOnce);
            processMilliseconds_ = {{"read_raster", readMilliseconds}, {"plan", row.planningMilliseconds}};
            writeOutputs(plan, (fs::path(options_.outputDirectory) / name).string());
            row.metrics = plan.metrics;
            row.flightsOverBattery = flightsOverBattery_;
            row.peakMemoryMegabytes =
                ownPeak ? peakMemoryMegabytes() - residentBefore + residentWithRaster : peakMemoryMegabytes();
            plans.back() = std::move(plan);
        } catch (const BatchFailure& failure) {
            row.outcome = io::ComparisonRow::Outcome::Failed;
            row.message = failure.what();
            plannerPrefix_.clear();
            warn(name + " failed: " + row.message);
        }
        plannerPrefix_.clear();
        rows.push_back(row);
    }
    writeComparison(rows, plans);
    const auto count = [&](io::ComparisonRow::Outcome outcome) {
        return std::count_if(rows.begin(), rows.end(),
                             [&](const io::ComparisonRow& row) { return row.outcome == outcome; });
    };
    // Nothing planned means the mission itself is at fault: bad input, as for one planner.
    if (count(io::ComparisonRow::Outcome::Failed) > 0)
        exitCode_ = count(io::ComparisonRow::Outcome::Planned) > 0 ? BatchFailure::somePlannersFailed
                                                                   : BatchFailure::badInput;
}

namespace {
// Whether a plan's issue is one of the mission's own (a note of the problem), which every plan carries.
bool isOfTheMission(const PlanIssue& issue, const PlanningProblem& problem) {
    return std::any_of(problem.notes.begin(), problem.notes.end(),
                       [&](const PlanIssue& note) { return note.message == issue.message; });
}
} // namespace

// The mission's notes (the problem's) as the plan keeps them: a planner drops one that does not hold for
// its plan, as CPPIED drops "each is timed at its own" speed. Where an aircraft takes off outside the task
// area is said too: the start given is not where its path begins; and a robot that can cover only the part
// of the map it starts in, which planners on cells of other sizes may see joined to the rest.
void BatchRunner::sayMissionNotes(const Plan& plan, const PlanningProblem& problem,
                                  std::set<std::string>* saidOnce) {
    for (const PlanIssue& issue : plan.issues) {
        const bool ofTheMission = isOfTheMission(issue, problem);
        if (issue.severity != IssueSeverity::Information ||
            !(ofTheMission || issue.code == "take-off-outside" || issue.code == "confined-robot"))
            continue;
        // In a comparison, the mission's own notes are every plan's: said once, under no planner.
        const bool once = ofTheMission && saidOnce != nullptr;
        if (once && !saidOnce->insert(issue.message).second)
            continue;
        const std::string prefix = std::exchange(plannerPrefix_, once ? "" : plannerPrefix_);
        note(planMessage(issue.message));
        plannerPrefix_ = prefix;
    }
}

// A compared plan's warnings under its planner's name; those of the mission itself (the problem's notes,
// and the land beyond every aircraft's reach, which every planner on flights leaves out alike), once and
// under none.
void BatchRunner::sayComparedPlanWarnings(const Plan& plan, const PlanningProblem& problem,
                                          std::set<std::string>& saidOnce) {
    for (const PlanIssue& issue : plan.issues) {
        if (issue.severity != IssueSeverity::Warning)
            continue;
        const bool ofTheMission = isOfTheMission(issue, problem) || issue.code == "beyond-flight-reach";
        if (ofTheMission && !saidOnce.insert(issue.message).second)
            continue;
        const std::string prefix = std::exchange(plannerPrefix_, ofTheMission ? "" : plannerPrefix_);
        warn(planMessage(issue.message));
        plannerPrefix_ = prefix;
    }
}

void BatchRunner::writeComparison(const std::vector<io::ComparisonRow>& rows,
                                  const std::vector<std::optional<Plan>>& plans) {
    namespace fs = std::filesystem;
    const fs::path directory(options_.outputDirectory);
    std::error_code code;
    fs::create_directories(directory, code);
    if (const io::Status status = io::writeComparisonCsv(rows, (directory / "comparison.csv").string());
        !status)
        internalError(status.error());
    if (const io::Status status = io::writeComparisonJson(rows, (directory / "comparison.json").string());
        !status)
        internalError(status.error());
    std::vector<const Plan*> planned;
    for (const std::optional<Plan>& plan : plans)
        planned.push_back(plan ? &*plan : nullptr);
    const std::vector<render::ComparisonPanel> panels = render::rankedComparisonPanels(rows, planned);
    QString error;
    if (!render::writeComparisonSheet(raster_.grid, classes_, panels,
                                      QString::fromStdString((directory / "comparison.png").string()), &error,
                                      &raster_.area))
        warn("comparison.png not written: " + error.toStdString());
    if (options_.quiet)
        return;
    const auto skipped = std::count_if(rows.begin(), rows.end(), [](const io::ComparisonRow& row) {
        return row.outcome == io::ComparisonRow::Outcome::Skipped;
    });
    output_ << "mcpp: compared " << rows.size() - static_cast<std::size_t>(skipped) << " planners on "
            << mission_.robots.size() << " robots";
    if (skipped > 0)
        output_ << ", " << skipped << " skipped";
    output_ << '\n';
    printComparisonRows(rows);
    output_ << "mcpp: outputs in " << options_.outputDirectory << '\n' << std::flush;
}

// The rows as the window's table reads them (io::rankedRows): the soonest done of the plans covering the most
// first, each timed against it, and plans covering less after them with the share they leave. Ratios are to
// each plan's own bound, which counts its own cells and turns: they say how even a plan is, not which wins.
void BatchRunner::printComparisonRows(const std::vector<io::ComparisonRow>& rows) const {
    const std::vector<std::size_t> order = io::rankedRows(rows);
    const double most = io::mostCovered(rows);
    const std::vector<double> againstFirst = io::timesTheFirst(rows);
    const io::ComparisonRow* first = nullptr;
    int rank = 0;
    for (const std::size_t index : order) {
        const io::ComparisonRow& row = rows[index];
        if (row.outcome != io::ComparisonRow::Outcome::Planned) {
            output_ << "mcpp:   " << row.planner << ": " << io::outcomeName(row.outcome) << " ("
                    << row.message << ")\n";
            continue;
        }
        output_ << "mcpp:   " << ++rank << ". " << row.planner << ": covered "
                << formatPercent(row.metrics.coveredFraction);
        if (io::coversLessThanMost(row, most))
            output_ << ", " << formatNumber((most - row.metrics.coveredFraction) * 100.0, 1)
                    << " points less than the most covered (" << formatPercent(most) << ")";
        const bool inTheField = row.metrics.timedInTheField();
        // Where flights split the missions, the field team waits for the last robot home.
        output_ << (inTheField ? ", the last robot home after " : ", makespan ")
                << formatDuration(io::doneAfterSeconds(row));
        if (io::fliesPastItsBatteries(row, rows))
            output_ << " with " << *row.flightsOverBattery
                    << (*row.flightsOverBattery == 1 ? " flight" : " flights")
                    << " longer than a battery (not set beside plans whose flights fit)";
        else if (io::timedUnlikeTheOthers(row, rows))
            output_ << " at the class table's speeds (not set beside plans keeping the robots' own)";
        // A plan covering less is not timed against one covering the most: smaller, not quicker.
        if (first == nullptr)
            first = &row;
        else if (againstFirst[index] > 0.0)
            output_ << " (" << formatNumber(againstFirst[index], 2) << " x " << first->planner << "'s)";
        if (inTheField)
            output_ << ", makespan " << formatDuration(row.metrics.makespanSeconds);
        output_ << ", ratio " << formatNumber(row.metrics.ratio, 3) << " to its own bound"
                << boundKindText(row.metrics) << sharedPartsText(row.metrics) << ", "
                << row.metrics.totalTurns() << " turns, planned in "
                << formatNumber(row.planningMilliseconds / 1000.0, 2) << " s\n";
    }
}

void BatchRunner::printSummary(const Plan& plan) const {
    if (options_.quiet)
        return;
    const PlanMetrics& metrics = plan.metrics;
    output_ << "mcpp: planned " << plan.paths.size() << (plan.paths.size() == 1 ? " robot" : " robots")
            << " with " << plan.planner << ": ";
    // Where flights split the missions, the team waits for the last robot home; paths of different
    // lengths that end together in the field are uneven by design, so their ratio comes second.
    const bool inTheField = metrics.timedInTheField();
    if (inTheField)
        output_ << "the last robot home after " << formatDuration(metrics.fieldMakespanSeconds)
                << ", last / first home " << formatNumber(metrics.fieldSpread(), 3) << " (the paths: ";
    output_ << "makespan " << formatDuration(metrics.makespanSeconds) << ", lower bound "
            << formatDuration(metrics.lowerBoundSeconds) << ", ratio " << formatNumber(metrics.ratio, 3)
            << boundKindText(metrics) << sharedPartsText(metrics) << (inTheField ? ")" : "") << ", covered "
            << formatPercent(metrics.coveredFraction) << " of the passable area\n";
    // A split mission's flights, trips and turnarounds take longer than the plan's makespan says.
    if (!fieldTimeNote_.empty())
        output_ << "mcpp: " << fieldTimeNote_ << '\n';
    if (!fieldTimeNote_.empty() && !fieldBoundNote_.empty())
        output_ << "mcpp: " << fieldBoundNote_ << '\n';
    if (const TimelineLayer* timeline = timelineLayerOf(plan))
        output_ << "mcpp: " << timelineSentence(timeline->summary()) << '\n';
    if (const auto causes = io::longPlanCauses(metrics.makespanSeconds, mission_, classes_))
        output_ << "mcpp: " << longPlanAdvice(*causes, plan.paths.size(), metrics.makespanSeconds) << '\n';
    output_ << "mcpp: outputs in " << options_.outputDirectory << '\n' << std::flush;
}

void BatchRunner::flushPending() {
    for (const auto& message : pendingNotes_)
        note(message);
    pendingNotes_.clear();
    for (const auto& warning : pendingWarnings_)
        warn(warning);
    inputWarnings_.insert(inputWarnings_.end(), pendingWarnings_.begin(), pendingWarnings_.end());
    pendingWarnings_.clear();
}

void BatchRunner::note(const std::string& message) {
    if (!options_.quiet)
        output_ << "mcpp: " << plannerPrefix_ << message << '\n' << std::flush;
}

void BatchRunner::warn(const std::string& message) {
    if (!options_.quiet)
        diagnostics_ << "mcpp: warning: " << plannerPrefix_ << message << '\n' << std::flush;
}

std::string BatchRunner::fieldName(const io::MissionField& field) const {
    const bool fromFile = !options_.missionFromFlags();
    switch (field.part) {
    case Part::Raster:
        return fromFile ? options_.missionPath + ": raster" : "--raster";
    case Part::Classes:
        if (fromFile)
            return options_.missionPath + ": classes";
        if (!options_.classesPath.empty())
            return options_.classesPath;
        return options_.preset.empty() ? "the class table recognised for --raster" : "--preset";
    case Part::MissingClassesOption:
        return fromFile ? "classes.missing_as_obstacles (or --missing-as-obstacle)" : "--missing-as-obstacle";
    case Part::Start:
        if (!fromFile)
            return "--start " + std::to_string(field.robot + 1);
        break;
    case Part::StartCrs:
        if (!fromFile)
            return "--start-crs";
        break;
    case Part::Charger:
        if (!fromFile)
            return "--charger after --start " + std::to_string(field.robot + 1);
        break;
    case Part::Planner:
        if (options_.planner || !fromFile)
            return "--planner";
        break;
    case Part::Parameter: {
        // The last flag that set it wins, as it does for the value.
        const auto& overrides = options_.parameters;
        const auto last =
            std::find_if(overrides.rbegin(), overrides.rend(),
                         [&](const ParameterOverride& given) { return given.key == field.key; });
        const std::string suggested = field.value.empty() ? std::string() : "=" + field.value;
        if (last != overrides.rend())
            return last->flag + suggested;
        if (!fromFile)
            return "--param " + field.key + suggested;
        // Advice for a mission file: its field, or the flag that sets it for one run.
        if (!field.value.empty())
            return io::missionFileFields(options_.missionPath, io::robotNames(mission_))(field) +
                   " (or --param " + field.key + suggested + ")";
        break;
    }
    }
    return io::missionFileFields(options_.missionPath, io::robotNames(mission_))(field);
}

io::FieldNamer BatchRunner::fieldNamer() const {
    return [this](const io::MissionField& field) { return fieldName(field); };
}

} // namespace mcpp::app
