#include "core/coverage/PathMeasurement.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/MissionInputs.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/ClassTableJson.hpp"
#include "io/internal/EventsJson.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <string_view>
#include <variant>

namespace mcpp::io {

using internal::JsonValue;

namespace {

// The passable land of each robot's cells, by robot: the plan's covered area shared out, so that the
// robots' add up to it. A region's area_m2 counts its sub-cells whole (what the regions layer draws), and
// sub-cells at an obstacle's edge hold some of it.
std::vector<double> coveredAreaByRobot(const Plan& plan) {
    std::vector<double> covered(plan.metrics.robots.size(), 0.0);
    const std::vector<int>& robotOfCell = plan.regions.robotOfCell;
    for (std::size_t id = 0; id < robotOfCell.size() && id < plan.cells.size(); ++id)
        if (const int robot = robotOfCell[id]; robot >= 0 && static_cast<std::size_t>(robot) < covered.size())
            covered[static_cast<std::size_t>(robot)] +=
                plan.cells.cell(static_cast<int>(id)).passableAreaSquareMetres;
    return covered;
}

double chargingSeconds(const CoveragePath& path) {
    return pausedSecondsBetween(path.pauses, 0, path.waypoints.size());
}

// A battery robot's sorties: how many, their times, the charges between them and what lies out of range.
void addSorties(JsonValue& item, const Plan& plan, const RobotSorties& robot) {
    const CoveragePath& path = plan.paths[static_cast<std::size_t>(robot.robot)];
    item.add("battery_s", robot.enduranceSeconds);
    item.add("sorties", static_cast<int>(robot.sorties.size()));
    item.add("charges", robot.charges());
    item.add("charging_s", chargingSeconds(path));
    JsonValue& times = item.add("sortie_times_s", JsonValue::array());
    double longest = 0.0;
    for (const Sortie& sortie : robot.sorties) {
        const double seconds = sortieSeconds(path, sortie, plan.cells);
        times.push(seconds);
        longest = std::max(longest, seconds);
    }
    item.add("longest_sortie_s", longest);
    item.add("out_of_range_area_m2", robot.outOfRangeAreaSquareMetres);
}

// What the passes see over the targets (lattice cells a robot covers whose land cover can be seen).
void addDetection(JsonValue& root, const DetectionSummary& summary) {
    JsonValue& detection = root.add("detection", JsonValue::object());
    detection.add("required_probability", summary.requiredProbability);
    detection.add("minimum", summary.minimum);
    detection.add("mean", summary.mean);
    detection.add("share_met", summary.shareMet);
    detection.add("targets", static_cast<double>(summary.targets));
    detection.add("unmet_targets", static_cast<double>(summary.unmetTargets));
    detection.add("undetectable_area_m2", summary.undetectableAreaSquareMetres);
}

// A simulated robot: when it was done under the events, what it took over, when the static plan's would be.
void addTimeline(JsonValue& item, const RobotTimeline& robot, bool compared) {
    item.add("completion_s", robot.completionSeconds);
    item.add("stopped", robot.stopped);
    item.add("cells_taken_over", static_cast<int>(robot.cellsTakenOver.size()));
    item.add("taken_over_area_m2", robot.takenOverAreaSquareMetres);
    if (compared)
        item.add("static_completion_s", robot.staticCompletionSeconds); // null: stopped before the end
}

// The events played and what re-allocation saved against the static plan run through them.
void addTimelineSummary(JsonValue& root, const TimelineLayer::Summary& summary) {
    internal::addEvents(root, summary.events);
    root.add("makespan_under_events_s", summary.makespanSeconds);
    if (summary.staticPlanner.empty())
        return;
    root.add("static_planner", summary.staticPlanner);
    root.add("static_makespan_s", summary.staticMakespanSeconds); // null: a robot stopped with work left
    root.add("static_plan_makespan_s", summary.staticPlanMakespanSeconds);
}

std::string sortieColumns(const Plan& plan, const RobotSorties& robot) {
    const CoveragePath& path = plan.paths[static_cast<std::size_t>(robot.robot)];
    const double longest = longestSortieSeconds(path, robot.sorties, plan.cells);
    return "," + std::to_string(robot.sorties.size()) + "," + std::to_string(robot.charges()) + "," +
           internal::formatShortest(chargingSeconds(path)) + "," + internal::formatShortest(longest) + "," +
           internal::formatShortest(robot.outOfRangeAreaSquareMetres);
}

// A plan's message as the run said it: its map points with their degrees, the robots it numbers by name.
std::string forPeople(const ExportContext& context, const std::string& message) {
    return messageForPeople(message, context.georeference, context.grid, context.robotNames);
}

// Robots whose waypoint files are written in parts or sorties: scripts find it among the issues, beside what
// the run printed.
void addMissionFileIssues(JsonValue& issues, JsonValue& warnings, const ExportContext& context) {
    for (const RobotMetrics& robot : context.plan.metrics.robots) {
        const std::string file =
            robotFileStem(robot.robot, static_cast<int>(context.plan.paths.size())) + ".plan";
        const std::string besideWaypoints = ", and the same for its .waypoints file";
        const std::tuple<const char*, const char*, std::string> notes[] = {
            {"information", "mission-split", splitMissionNote(context, robot.robot, file) + besideWaypoints},
            {"warning", "flight-time-exceeded", flightTimeWarning(context, robot.robot, file)},
            {"information", "mission-sorties",
             sortieFilesNote(context, robot.robot, file) + besideWaypoints}};
        for (const auto& [severity, code, message] : notes) {
            if (message.empty() || message == besideWaypoints)
                continue;
            JsonValue& item = issues.push(JsonValue::object());
            item.add("severity", severity);
            item.add("code", code);
            item.add("message", message);
            if (std::string_view(severity) == "warning")
                warnings.push(message);
        }
    }
}

} // namespace

Status writeReportJson(const ExportContext& context, const std::string& path) {
    const PlanMetrics& metrics = context.plan.metrics;
    JsonValue root = JsonValue::object();
    root.add("planner", context.plan.planner);
    JsonValue& parameters = root.add("parameters", JsonValue::object());
    const auto planner = findPlannerDescription(context.plan.planner);
    for (const auto& [key, value] : context.plan.parameters.all()) {
        const ParameterSpec* spec = planner ? findParameter(planner->parameters, key) : nullptr;
        if (spec != nullptr && spec->isAutomatic(value))
            parameters.add(key, spec->automatic);
        else
            std::visit([&, name = key](const auto& held) { parameters.add(name, held); }, value);
    }
    // The class table as the mission gives it; a cruise speed the fleet shares stands in for its speeds in
    // the plan, as the plan's issues say.
    internal::addClassRows(root.add("classes", JsonValue::array()), context.classes);
    JsonValue& robots = root.add("robots", JsonValue::array());
    const SortieLayer* sorties = sortieLayerOf(context.plan);
    const TimelineLayer* timeline = timelineLayerOf(context.plan);
    const std::vector<double> coveredAreas = coveredAreaByRobot(context.plan);
    for (const RobotMetrics& robot : metrics.robots) {
        JsonValue& item = robots.push(JsonValue::object());
        item.add("robot", robotNumber(robot.robot));
        item.add("name", context.robotName(robot.robot));
        item.add("cells", robot.cells);
        item.add("area_m2", robot.areaSquareMetres);
        item.add("covered_area_m2", coveredAreas[static_cast<std::size_t>(robot.robot)]);
        item.add("length_m", robot.lengthMetres);
        item.add("time_s", robot.timeSeconds);
        item.add("turns", robot.turns);
        item.add("turn_time_s", robot.turnSeconds);
        item.add("connector_time_s", robot.connectorSeconds);
        item.add("cost_s", robot.costSeconds);
        const VehicleSettings& vehicle = context.vehicle(robot.robot);
        const AutopilotMission& mission = autopilotMissionOf(context, robot.robot);
        item.add("vehicle", vehicleTypeKey(vehicle.type));
        item.add("max_waypoints", vehicle.maxWaypoints);
        item.add("flight_time_s", vehicle.flightTimeSeconds);
        item.add("camera_trigger_m", vehicle.cameraTriggerMetres);
        item.add("mission_photos", missionPhotos(mission, vehicle));
        item.add("mission_items", mission.items);
        item.add("mission_parts", static_cast<int>(mission.parts.size()));
        item.add("mission_time_s", mission.seconds);
        // The whole mission as one flight from the start and back, an aircraft's climb and descent included:
        // what the console holds against the flight time when it splits the mission.
        if (!mission.parts.empty())
            item.add("mission_one_flight_s",
                     partSeconds(mission, {0, mission.points.size() - 1}, vehicle, context.plan.cells));
        // Each file's own flight, for a battery: an aircraft's with its trips to and from the start.
        JsonValue& partSeconds = item.add("mission_part_seconds", JsonValue::array());
        for (const MissionPart& part : mission.parts)
            partSeconds.push(part.seconds);
        // Each file's items as the autopilot counts them, home included: what its item limit holds.
        JsonValue& partItems = item.add("mission_part_items", JsonValue::array());
        for (const MissionPart& part : mission.parts)
            partItems.push(part.items);
        // All the parts' flights, trips included: what the robot flies; the field time adds the turnarounds.
        const MissionFlights flights = missionFlights(mission, vehicle);
        item.add("mission_flights_s", flights.totalSeconds);
        item.add("mission_longest_part_s", flights.longestSeconds);
        item.add("mission_parts_over_flight_time", static_cast<int>(flights.overFlightTime));
        item.add("turnaround_s", vehicle.turnaroundSeconds);
        item.add("mission_field_s", flights.fieldSeconds);
        if (sorties != nullptr)
            addSorties(item, context.plan, sorties->robots()[static_cast<std::size_t>(robot.robot)]);
        if (timeline != nullptr)
            addTimeline(item, timeline->robots()[static_cast<std::size_t>(robot.robot)],
                        !timeline->summary().staticPlanner.empty());
    }
    root.add("makespan_s", metrics.makespanSeconds);
    root.add("lower_bound_s", metrics.lowerBoundSeconds);
    root.add("lower_bound_kind", lowerBoundKind(metrics));
    root.add("ratio", metrics.ratio);
    // Where robots alone in parts of their own set the bound (else 0): the balance of the robots sharing
    // parts.
    if (metrics.sharedPartsRatio > 0.0)
        root.add("shared_parts_ratio", metrics.sharedPartsRatio);
    // Where missions are split into flights: when the last robot is home, the least any plan takes, and how
    // evenly the robots come home.
    if (metrics.timedInTheField()) {
        root.add("field_makespan_s", metrics.fieldMakespanSeconds);
        root.add("field_lower_bound_s", metrics.fieldLowerBoundSeconds);
        root.add("field_spread", metrics.fieldSpread());
    }
    root.add("covered_fraction", metrics.coveredFraction);
    root.add("passable_area_m2", metrics.passableAreaSquareMetres);
    root.add("covered_area_m2", metrics.coveredAreaSquareMetres);
    root.add("unreachable_area_m2", metrics.unreachableAreaSquareMetres);
    root.add("repeated_fraction", metrics.repeatedFraction);
    if (const DetectionLayer* detection = detectionLayerOf(context.plan))
        addDetection(root, detection->summary());
    if (timeline != nullptr)
        addTimelineSummary(root, timeline->summary());
    JsonValue& timings = root.add("timings_ms", JsonValue::object());
    for (const auto& [stage, milliseconds] : metrics.stageMilliseconds)
        timings.add(stage, milliseconds);
    if (!context.processMilliseconds.empty()) {
        JsonValue& process = root.add("process_ms", JsonValue::object());
        for (const auto& [step, milliseconds] : context.processMilliseconds)
            process.add(step, milliseconds);
    }
    JsonValue& warnings = root.add("warnings", JsonValue::array());
    for (const std::string& warning : context.inputWarnings)
        warnings.push(warning);
    for (const std::string& warning : context.plan.warnings())
        warnings.push(forPeople(context, warning));
    JsonValue& issues = root.add("issues", JsonValue::array());
    for (const std::string& warning : context.inputWarnings) {
        JsonValue& item = issues.push(JsonValue::object());
        item.add("severity", "warning");
        item.add("code", "input");
        item.add("message", warning);
    }
    for (const PlanIssue& issue : context.plan.issues) {
        JsonValue& item = issues.push(JsonValue::object());
        item.add("severity", issue.severity == IssueSeverity::Warning ? "warning" : "information");
        item.add("code", issue.code);
        item.add("message", forPeople(context, issue.message));
    }
    addMissionFileIssues(issues, warnings, context);
    for (const std::string& note : context.outputNotes) {
        JsonValue& item = issues.push(JsonValue::object());
        item.add("severity", "information");
        item.add("code", "output");
        item.add("message", note);
    }
    return internal::writeFileAtomically(path, root.toText(), Sync::BySystem);
}

std::string lowerBoundKind(const PlanMetrics& metrics) {
    return metrics.boundOfDetectionPasses ? "detection_passes" : "coverage_work";
}

Status writeReportCsv(const ExportContext& context, const std::string& path) {
    // Battery plans add their sortie columns at the end, so readers of the others see no change.
    const SortieLayer* sorties = sortieLayerOf(context.plan);
    std::string text = "robot,name,cells,area_m2,length_m,time_s,turns,cost_s,mission_items,mission_parts,"
                       "turn_time_s,connector_time_s,flight_time_s,mission_flights_s,mission_longest_part_s,"
                       "mission_parts_over_flight_time,turnaround_s,mission_field_s";
    // The camera's columns last, after any sortie columns: added later, where readers by place miss them.
    text += sorties == nullptr ? "" : ",sorties,charges,charging_s,longest_sortie_s,out_of_range_area_m2";
    text += ",camera_trigger_m,mission_photos,covered_area_m2\n";
    const std::vector<double> coveredAreas = coveredAreaByRobot(context.plan);
    for (const RobotMetrics& robot : context.plan.metrics.robots) {
        const VehicleSettings& vehicle = context.vehicle(robot.robot);
        const AutopilotMission& mission = autopilotMissionOf(context, robot.robot);
        const MissionFlights flights = missionFlights(mission, vehicle);
        text += std::to_string(robotNumber(robot.robot)) + "," +
                internal::quoteCsvField(context.robotName(robot.robot)) + "," + std::to_string(robot.cells) +
                "," + internal::formatShortest(robot.areaSquareMetres) + "," +
                internal::formatShortest(robot.lengthMetres) + "," +
                internal::formatShortest(robot.timeSeconds) + "," + std::to_string(robot.turns) + "," +
                internal::formatShortest(robot.costSeconds) + "," + std::to_string(mission.items) + "," +
                std::to_string(mission.parts.size()) + "," + internal::formatShortest(robot.turnSeconds) +
                "," + internal::formatShortest(robot.connectorSeconds) + "," +
                internal::formatShortest(vehicle.flightTimeSeconds) + "," +
                internal::formatShortest(flights.totalSeconds) + "," +
                internal::formatShortest(flights.longestSeconds) + "," +
                std::to_string(flights.overFlightTime) + "," +
                internal::formatShortest(vehicle.turnaroundSeconds) + "," +
                internal::formatShortest(flights.fieldSeconds);
        if (sorties != nullptr)
            text += sortieColumns(context.plan, sorties->robots()[static_cast<std::size_t>(robot.robot)]);
        text += "," + internal::formatShortest(vehicle.cameraTriggerMetres) + "," +
                std::to_string(missionPhotos(mission, vehicle)) + "," +
                internal::formatShortest(coveredAreas[static_cast<std::size_t>(robot.robot)]) + "\n";
    }
    return internal::writeFileAtomically(path, text, Sync::BySystem);
}

} // namespace mcpp::io
