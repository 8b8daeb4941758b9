#include "io/ComparisonRanking.hpp"

#include <algorithm>
#include <numeric>

namespace mcpp::io {

namespace {

bool planned(const ComparisonRow& row) {
    return row.outcome == ComparisonRow::Outcome::Planned;
}

// Whether some plan covering the most flies every flight of its waypoint files within a battery.
bool someFlyWithinBatteries(const std::vector<ComparisonRow>& rows, double most) {
    return std::any_of(rows.begin(), rows.end(), [most](const ComparisonRow& row) {
        return planned(row) && row.flightsOverBattery == std::size_t{0} && !coversLessThanMost(row, most);
    });
}

// Whether some plan covering the most, and not set apart for flights too long, keeps the robots' own speeds:
// a plan itself set apart sets no other apart.
bool someKeepOwnSpeeds(const std::vector<ComparisonRow>& rows, double most) {
    const bool someFit = someFlyWithinBatteries(rows, most);
    return std::any_of(rows.begin(), rows.end(), [most, someFit](const ComparisonRow& row) {
        const bool tooLong = someFit && row.flightsOverBattery.value_or(0) > 0;
        return planned(row) && !row.metrics.ownSpeedsIgnored && !coversLessThanMost(row, most) && !tooLong;
    });
}

// Why plans in a group are ranked apart: a key for scripts and a few words for people, in one place.
struct RankedApart {
    ReadingGroup group;
    const char* key;
    const char* words;
};
constexpr RankedApart rankedApartGroups[] = {
    {ReadingGroup::OwnSpeedsIgnored, "own_speeds_ignored", "at the class table's speeds"},
    {ReadingGroup::FlightsOverBattery, "flights_over_battery", "flights too long"},
    {ReadingGroup::CoversLess, "covers_less", "covers less"},
};

const RankedApart* rankedApartOf(ReadingGroup readingGroup) {
    for (const RankedApart& apart : rankedApartGroups)
        if (apart.group == readingGroup)
            return &apart;
    return nullptr;
}

} // namespace

double doneAfterSeconds(const ComparisonRow& row) {
    const PlanMetrics& metrics = row.metrics;
    const bool inTheField = metrics.timedInTheField();
    return inTheField ? metrics.fieldMakespanSeconds : metrics.makespanSeconds;
}

double mostCovered(const std::vector<ComparisonRow>& rows) {
    double most = 0.0;
    for (const ComparisonRow& row : rows)
        if (planned(row))
            most = std::max(most, row.metrics.coveredFraction);
    return most;
}

bool coversLessThanMost(const ComparisonRow& row, double most) {
    return planned(row) && row.metrics.coveredFraction < most - coverageShortfall;
}

bool timedUnlikeTheOthers(const ComparisonRow& row, const std::vector<ComparisonRow>& rows) {
    return planned(row) && row.metrics.ownSpeedsIgnored && someKeepOwnSpeeds(rows, mostCovered(rows));
}

bool fliesPastItsBatteries(const ComparisonRow& row, const std::vector<ComparisonRow>& rows) {
    const double most = mostCovered(rows);
    return planned(row) && row.flightsOverBattery.value_or(0) > 0 && !coversLessThanMost(row, most) &&
           someFlyWithinBatteries(rows, most);
}

std::string rankedApartReason(ReadingGroup readingGroup) {
    const RankedApart* apart = rankedApartOf(readingGroup);
    return apart != nullptr ? apart->words : std::string();
}

std::string rankedApartKey(ReadingGroup readingGroup) {
    const RankedApart* apart = rankedApartOf(readingGroup);
    return apart != nullptr ? apart->key : std::string();
}

ReadingGroup readingGroup(const ComparisonRow& row, const std::vector<ComparisonRow>& rows) {
    switch (row.outcome) {
    case ComparisonRow::Outcome::Planned:
        if (coversLessThanMost(row, mostCovered(rows)))
            return ReadingGroup::CoversLess;
        if (fliesPastItsBatteries(row, rows))
            return ReadingGroup::FlightsOverBattery;
        return timedUnlikeTheOthers(row, rows) ? ReadingGroup::OwnSpeedsIgnored : ReadingGroup::TimedAlike;
    case ComparisonRow::Outcome::Failed:
        return ReadingGroup::Failed;
    case ComparisonRow::Outcome::Skipped:
        break;
    }
    return ReadingGroup::Skipped;
}

std::vector<std::size_t> rankedRows(const std::vector<ComparisonRow>& rows) {
    std::vector<ReadingGroup> groups;
    for (const ComparisonRow& row : rows)
        groups.push_back(readingGroup(row, rows));
    std::vector<std::size_t> order(rows.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const ComparisonRow& first = rows[a];
        const ComparisonRow& second = rows[b];
        if (groups[a] != groups[b])
            return groups[a] < groups[b];
        if (!planned(first))
            return false;
        if (doneAfterSeconds(first) != doneAfterSeconds(second))
            return doneAfterSeconds(first) < doneAfterSeconds(second);
        return first.planningMilliseconds < second.planningMilliseconds;
    });
    return order;
}

std::vector<int> ranksOf(const std::vector<ComparisonRow>& rows) {
    std::vector<int> ranks(rows.size(), 0);
    int rank = 0;
    for (const std::size_t index : rankedRows(rows))
        if (planned(rows[index]))
            ranks[index] = ++rank;
    return ranks;
}

std::vector<double> timesTheFirst(const std::vector<ComparisonRow>& rows) {
    std::vector<double> times(rows.size(), 0.0);
    const std::vector<std::size_t> order = rankedRows(rows);
    if (order.empty() || !planned(rows[order.front()]))
        return times;
    const double first = doneAfterSeconds(rows[order.front()]);
    if (first <= 0.0)
        return times;
    for (std::size_t index = 0; index < rows.size(); ++index)
        if (readingGroup(rows[index], rows) == ReadingGroup::TimedAlike)
            times[index] = doneAfterSeconds(rows[index]) / first;
    return times;
}

} // namespace mcpp::io
