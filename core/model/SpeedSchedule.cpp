#include "core/model/SpeedSchedule.hpp"

#include <algorithm>
#include <limits>

namespace mcpp {

SpeedSchedule::SpeedSchedule(const std::vector<SpeedEvent>& events, int robot) {
    for (const SpeedEvent& event : events)
        if (event.robot == robot)
            changes_.emplace_back(event.timeSeconds, event.speedFactor);
    std::stable_sort(changes_.begin(), changes_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
}

double SpeedSchedule::factorAt(double seconds) const {
    double factor = 1.0;
    for (const auto& [time, value] : changes_) {
        if (time > seconds)
            break;
        factor = value;
    }
    return factor;
}

double SpeedSchedule::nextChangeAfter(double seconds) const {
    for (const auto& change : changes_)
        if (change.first > seconds)
            return change.first;
    return std::numeric_limits<double>::infinity();
}

bool SpeedSchedule::stoppedFrom(double seconds) const {
    if (factorAt(seconds) > 0.0)
        return false;
    for (const auto& change : changes_)
        if (change.first > seconds && change.second > 0.0)
            return false;
    return true;
}

double SpeedSchedule::finishTime(double startSeconds, double nominalSeconds) const {
    double now = startSeconds;
    double left = nominalSeconds;
    while (true) {
        const double factor = factorAt(now);
        const double next = nextChangeAfter(now);
        if (factor > 0.0) {
            const double possible = (next - now) * factor; // infinity when no change follows
            if (left <= possible)
                return now + left / factor;
            left -= possible;
        } else if (left <= 0.0) {
            return now;
        }
        if (next == std::numeric_limits<double>::infinity())
            return next;
        now = next;
    }
}

} // namespace mcpp
