#include "io/ComparisonExport.hpp"

#include "io/ComparisonRanking.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>

namespace mcpp::io {

namespace {

using internal::formatShortest;
using internal::JsonValue;

template <typename Field> std::string joined(const PlanMetrics& metrics, Field field) {
    std::string text;
    for (const RobotMetrics& robot : metrics.robots)
        text += (text.empty() ? "" : ";") + formatShortest(field(robot));
    return text;
}

double stageMilliseconds(const PlanMetrics& metrics, const std::string& stage) {
    for (const auto& [name, milliseconds] : metrics.stageMilliseconds)
        if (name == stage)
            return milliseconds;
    return 0.0;
}

// Every stage any planner reported, in order of first appearance, for the CSV's columns.
std::vector<std::string> stageNames(const std::vector<ComparisonRow>& rows) {
    std::vector<std::string> names;
    for (const ComparisonRow& row : rows)
        for (const auto& [name, milliseconds] : row.metrics.stageMilliseconds)
            if (std::find(names.begin(), names.end(), name) == names.end())
                names.push_back(name);
    return names;
}

// A stage's column: "straight borders" gives straight_borders_ms, a name scripts can use unquoted.
std::string stageColumn(std::string stage) {
    std::replace(stage.begin(), stage.end(), ' ', '_');
    return stage + "_ms";
}

// Where flights split the missions: when the last robot is home and the bound there (as report.json).
bool inTheField(const ComparisonRow& row) {
    return row.outcome == ComparisonRow::Outcome::Planned && row.metrics.timedInTheField();
}

std::string fieldFigure(const ComparisonRow& row, double seconds) {
    return inTheField(row) ? formatShortest(seconds) : std::string();
}

// Why a planned row is ranked after the plans timed alike (ComparisonRanking's ReadingGroup), in words
// scripts can match; empty for those.
std::string rankedApart(const ComparisonRow& row, const std::vector<ComparisonRow>& rows) {
    return rankedApartKey(readingGroup(row, rows));
}

} // namespace

std::string outcomeName(ComparisonRow::Outcome outcome) {
    switch (outcome) {
    case ComparisonRow::Outcome::Planned:
        return "planned";
    case ComparisonRow::Outcome::Failed:
        return "failed";
    case ComparisonRow::Outcome::Skipped:
        break;
    }
    return "skipped";
}

Status writeComparisonCsv(const std::vector<ComparisonRow>& rows, const std::string& path) {
    const std::vector<std::string> stages = stageNames(rows);
    // time_vs_first after the columns earlier versions wrote, so that scripts reading them by place still
    // find them there.
    std::string text =
        "planner,outcome,rank,makespan_s,lower_bound_s,ratio,total_length_m,turns,covered_fraction,"
        "repeated_fraction,unreachable_area_m2,robot_length_m,robot_time_s,robot_turns,"
        "planning_ms,peak_memory_mb,field_makespan_s,field_lower_bound_s,field_spread,time_vs_first,"
        "lower_bound_kind,ranked_apart,flights_over_battery";
    for (const std::string& stage : stages)
        text += "," + stageColumn(stage);
    text += ",message\n";
    const std::vector<int> ranks = ranksOf(rows);
    const std::vector<double> againstFirst = timesTheFirst(rows);
    for (std::size_t index = 0; index < rows.size(); ++index) {
        const ComparisonRow& row = rows[index];
        const PlanMetrics& metrics = row.metrics;
        const bool planned = row.outcome == ComparisonRow::Outcome::Planned;
        const auto figure = [&](double value) { return planned ? formatShortest(value) : std::string(); };
        text += internal::quoteCsvField(row.planner) + "," + outcomeName(row.outcome) + "," +
                (planned ? std::to_string(ranks[index]) : std::string()) + "," +
                figure(metrics.makespanSeconds) + "," + figure(metrics.lowerBoundSeconds) + "," +
                figure(metrics.ratio) + "," + figure(metrics.totalLengthMetres()) + "," +
                (planned ? std::to_string(metrics.totalTurns()) : std::string()) + "," +
                figure(metrics.coveredFraction) + "," + figure(metrics.repeatedFraction) + "," +
                figure(metrics.unreachableAreaSquareMetres) + "," +
                joined(metrics, [](const RobotMetrics& robot) { return robot.lengthMetres; }) + "," +
                joined(metrics, [](const RobotMetrics& robot) { return robot.timeSeconds; }) + "," +
                joined(metrics, [](const RobotMetrics& robot) { return static_cast<double>(robot.turns); }) +
                "," + figure(row.planningMilliseconds) + "," + figure(row.peakMemoryMegabytes) + "," +
                fieldFigure(row, metrics.fieldMakespanSeconds) + "," +
                fieldFigure(row, metrics.fieldLowerBoundSeconds) + "," +
                fieldFigure(row, metrics.fieldSpread()) + "," +
                (againstFirst[index] > 0.0 ? formatShortest(againstFirst[index]) : std::string()) + "," +
                (planned ? lowerBoundKind(metrics) : std::string()) + "," + rankedApart(row, rows) + "," +
                (planned && row.flightsOverBattery ? std::to_string(*row.flightsOverBattery) : std::string());
        for (const std::string& stage : stages)
            text += "," + (planned ? formatShortest(stageMilliseconds(metrics, stage)) : std::string());
        text += "," + internal::quoteCsvField(row.message) + "\n";
    }
    return internal::writeFileAtomically(path, text, Sync::BySystem);
}

Status writeComparisonJson(const std::vector<ComparisonRow>& rows, const std::string& path) {
    JsonValue root = JsonValue::object();
    JsonValue& planners = root.add("planners", JsonValue::array());
    const std::vector<int> ranks = ranksOf(rows);
    const std::vector<double> againstFirst = timesTheFirst(rows);
    for (std::size_t index = 0; index < rows.size(); ++index) {
        const ComparisonRow& row = rows[index];
        JsonValue& item = planners.push(JsonValue::object());
        item.add("planner", row.planner);
        item.add("outcome", outcomeName(row.outcome));
        if (!row.message.empty())
            item.add("message", row.message);
        if (row.outcome != ComparisonRow::Outcome::Planned)
            continue;
        const PlanMetrics& metrics = row.metrics;
        item.add("rank", ranks[index]);
        if (againstFirst[index] > 0.0)
            item.add("time_vs_first", againstFirst[index]);
        if (const std::string apart = rankedApart(row, rows); !apart.empty())
            item.add("ranked_apart", apart);
        item.add("makespan_s", metrics.makespanSeconds);
        item.add("lower_bound_s", metrics.lowerBoundSeconds);
        item.add("lower_bound_kind", lowerBoundKind(metrics));
        item.add("ratio", metrics.ratio);
        if (metrics.sharedPartsRatio > 0.0) // robots alone in parts of their own: the others' balance
            item.add("shared_parts_ratio", metrics.sharedPartsRatio);
        item.add("total_length_m", metrics.totalLengthMetres());
        item.add("turns", metrics.totalTurns());
        item.add("covered_fraction", metrics.coveredFraction);
        item.add("repeated_fraction", metrics.repeatedFraction);
        item.add("unreachable_area_m2", metrics.unreachableAreaSquareMetres);
        if (row.flightsOverBattery)
            item.add("flights_over_battery", static_cast<std::int64_t>(*row.flightsOverBattery));
        if (inTheField(row)) {
            item.add("field_makespan_s", metrics.fieldMakespanSeconds);
            item.add("field_lower_bound_s", metrics.fieldLowerBoundSeconds);
            item.add("field_spread", metrics.fieldSpread());
        }
        JsonValue& robots = item.add("robots", JsonValue::array());
        for (const RobotMetrics& robot : metrics.robots) {
            JsonValue& entry = robots.push(JsonValue::object());
            entry.add("robot", robotNumber(robot.robot));
            entry.add("length_m", robot.lengthMetres);
            entry.add("time_s", robot.timeSeconds);
            entry.add("turns", robot.turns);
        }
        JsonValue& timings = item.add("timings_ms", JsonValue::object());
        for (const auto& [stage, milliseconds] : metrics.stageMilliseconds)
            timings.add(stage, milliseconds);
        item.add("planning_ms", row.planningMilliseconds);
        item.add("peak_memory_mb", row.peakMemoryMegabytes);
    }
    return internal::writeFileAtomically(path, root.toText(), Sync::BySystem);
}

} // namespace mcpp::io
