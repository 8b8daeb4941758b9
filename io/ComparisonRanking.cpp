#include "io/ComparisonRanking.hpp"

#include <algorithm>
#include <numeric>

namespace mcpp::io {

namespace {

bool planned(const ComparisonRow& row) {
    return row.outcome == ComparisonRow::Outcome::Planned;
}

// Reading groups: the whole job done, less of it done, failed, skipped.
int groupOf(const ComparisonRow& row, double most) {
    switch (row.outcome) {
    case ComparisonRow::Outcome::Planned:
        return coversLessThanMost(row, most) ? 1 : 0;
    case ComparisonRow::Outcome::Failed:
        return 2;
    case ComparisonRow::Outcome::Skipped:
        break;
    }
    return 3;
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

std::vector<std::size_t> rankedRows(const std::vector<ComparisonRow>& rows) {
    const double most = mostCovered(rows);
    std::vector<std::size_t> order(rows.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const ComparisonRow& first = rows[a];
        const ComparisonRow& second = rows[b];
        const int firstGroup = groupOf(first, most);
        const int secondGroup = groupOf(second, most);
        if (firstGroup != secondGroup)
            return firstGroup < secondGroup;
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
    const double most = mostCovered(rows);
    if (first <= 0.0)
        return times;
    for (std::size_t index = 0; index < rows.size(); ++index)
        if (planned(rows[index]) && !coversLessThanMost(rows[index], most))
            times[index] = doneAfterSeconds(rows[index]) / first;
    return times;
}

} // namespace mcpp::io
