#include "core/model/TimelineText.hpp"

#include "core/model/HumanUnits.hpp"

#include <cmath>

namespace mcpp {

std::string timelineSentence(const TimelineLayer::Summary& summary) {
    const std::size_t count = summary.events.size();
    std::string text = (count == 0 ? std::string("without events")
                                   : "under " + std::to_string(count) + (count == 1 ? " event" : " events")) +
                       ": done in " + formatDuration(summary.makespanSeconds);
    if (summary.staticPlanner.empty())
        return text;
    text += "; the static " + summary.staticPlanner + " plan" +
            (count == 0 ? std::string(": ") : std::string(" through the same events: "));
    if (std::isinf(summary.staticMakespanSeconds))
        return text + "never done (a robot stops with work left)";
    const double saved = 1.0 - summary.makespanSeconds / summary.staticMakespanSeconds;
    return text + formatDuration(summary.staticMakespanSeconds) + " (" +
           (saved >= 0.0 ? formatPercent(saved) + " saved)" : formatPercent(-saved) + " less)");
}

} // namespace mcpp
