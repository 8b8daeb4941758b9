#pragma once

#include "io/ComparisonExport.hpp"

#include <cstddef>
#include <vector>

namespace mcpp::io {

// How a comparison of planners is read, in the window's table, batch mode's summary and comparison.csv
// alike: the soonest done among the plans that cover the most land first. A plan covering less than the
// most covered by more than this share is not done sooner, only smaller: it comes after the others.
inline constexpr double coverageShortfall = 0.005;

// When the team is done with a plan: the last robot home where flights split the missions, else the
// makespan.
[[nodiscard]] double doneAfterSeconds(const ComparisonRow& row);

// The largest covered share among the planned rows; 0 with none.
[[nodiscard]] double mostCovered(const std::vector<ComparisonRow>& rows);

// Whether a planned row covers less than the most covered by more than coverageShortfall.
[[nodiscard]] bool coversLessThanMost(const ComparisonRow& row, double most);

// Whether a planned row times its robots at the class table's speeds where another plan covering the most,
// and not set apart for flights longer than a battery, keeps their own (PlanMetrics::ownSpeedsIgnored): its
// times are not to be set beside that plan's.
[[nodiscard]] bool timedUnlikeTheOthers(const ComparisonRow& row, const std::vector<ComparisonRow>& rows);

// Whether a planned row covering the most has waypoint files with flights longer than a battery where
// another plan covering the most flies none (ComparisonRow::flightsOverBattery): its time done is that of
// flights no drone can fly, not to be set beside that plan's.
[[nodiscard]] bool fliesPastItsBatteries(const ComparisonRow& row, const std::vector<ComparisonRow>& rows);

// Where a row is read, in this order: the plans covering the most and timed like the others first.
enum class ReadingGroup {
    TimedAlike,         // planned, covering the most, timed like the others: ranked by time done
    OwnSpeedsIgnored,   // planned at the class table's speeds where others keep the robots' own
    FlightsOverBattery, // with flights longer than a battery where another plan has none
    CoversLess,         // planned, covering less than the most by more than coverageShortfall
    Failed,
    Skipped,
};
[[nodiscard]] ReadingGroup readingGroup(const ComparisonRow& row, const std::vector<ComparisonRow>& rows);
// Why a planned plan in the group is ranked after the first whatever its time, in a few words for a table
// cell or a caption ("flights too long"); empty for plans timed alike and for rows that did not plan.
[[nodiscard]] std::string rankedApartReason(ReadingGroup readingGroup);
// The same as a key scripts can match in comparison.csv and .json ("flights_over_battery"); empty alike.
[[nodiscard]] std::string rankedApartKey(ReadingGroup readingGroup);

// The rows' indices in reading order: by reading group, planned rows in a group by time done (ties by
// planning time, then as given), failed and skipped rows as given.
[[nodiscard]] std::vector<std::size_t> rankedRows(const std::vector<ComparisonRow>& rows);

// Each row's place in that order, from 1; 0 for a row that did not plan.
[[nodiscard]] std::vector<int> ranksOf(const std::vector<ComparisonRow>& rows);

// Each row's time done divided by the first-ranked plan's: the one figure that compares plans, where each
// ratio is to the plan's own bound (its own cells and turns). 0 outside ReadingGroup::TimedAlike (a plan
// covering less is smaller, not slower; one timed unlike the others is not timed alike), or the first done at
// once.
[[nodiscard]] std::vector<double> timesTheFirst(const std::vector<ComparisonRow>& rows);

} // namespace mcpp::io
