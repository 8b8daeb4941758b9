#pragma once

#include "core/model/PlanMetrics.hpp"
#include "io/Result.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mcpp::io {

// One planner's line in a comparison of planners on the same mission.
struct ComparisonRow {
    enum class Outcome { Planned, Failed, Skipped };
    std::string planner;
    Outcome outcome = Outcome::Planned;
    std::string message; // why it failed or was skipped
    PlanMetrics metrics; // when planned
    double planningMilliseconds = 0.0;
    // Resident peak while it planned and wrote its outputs, less what the plans before it kept resident:
    // about its peak in a run of its own (Linux; elsewhere the process's peak so far).
    double peakMemoryMegabytes = 0.0;
    // Flights of its waypoint files longer than a battery (flightsOverBattery); none where no robot has a
    // flight time.
    std::optional<std::size_t> flightsOverBattery;
};

[[nodiscard]] std::string outcomeName(ComparisonRow::Outcome outcome);

// comparison.csv: a row per planner, in the order asked, with its rank (ComparisonRanking: 1 is the soonest
// done of the plans covering the most; empty where it did not plan), its time done against the first's
// (time_vs_first: ComparisonRanking's timesTheFirst, empty where it has none), why it is ranked after the
// plans timed alike (ranked_apart: own_speeds_ignored where it times the robots at the class table's speeds
// beside plans keeping their own, covers_less where it covers less than the most; empty otherwise) and the
// figures of its report.json, per-robot lengths and times joined by ";" in one field each; comparison.json:
// the same, with per-robot figures as arrays.
[[nodiscard]] Status writeComparisonCsv(const std::vector<ComparisonRow>& rows, const std::string& path);
[[nodiscard]] Status writeComparisonJson(const std::vector<ComparisonRow>& rows, const std::string& path);

} // namespace mcpp::io
