#include "core/model/TimelineText.hpp"

#include "core/model/HumanUnits.hpp"

#include <cmath>

namespace mcpp {

std::string timelineSentence(const TimelineLayer::Summary& summary) {
    std::string text = "under " + std::to_string(summary.events.size()) +
                       (summary.events.size() == 1 ? " event" : " events") + ": done in " +
                       formatDuration(summary.makespanSeconds);
    if (summary.staticPlanner.empty())
        return text;
    text += "; the static " + summary.staticPlanner + " plan through the same events: ";
    if (std::isinf(summary.staticMakespanSeconds))
        return text + "never done (a robot stops with work left)";
    return text + formatDuration(summary.staticMakespanSeconds) + " (" +
           formatPercent(1.0 - summary.makespanSeconds / summary.staticMakespanSeconds) + " saved)";
}

} // namespace mcpp
