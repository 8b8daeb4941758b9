#include "core/model/TimelineText.hpp"

#include "core/model/HumanUnits.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mcpp {

namespace {

// What re-allocating saved against the static plan, or how much longer it took.
std::string comparedWithStatic(double seconds, double staticSeconds) {
    const double times = seconds / staticSeconds;
    if (!(times > 1.0))
        return formatPercent(1.0 - times) + " saved";
    if (times < 2.0)
        return "re-allocating takes " + formatPercent(times - 1.0) + " longer";
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << times;
    return "re-allocating takes " + text.str() + " x as long";
}

} // namespace

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
    return text + formatDuration(summary.staticMakespanSeconds) + " (" +
           comparedWithStatic(summary.makespanSeconds, summary.staticMakespanSeconds) + ")";
}

} // namespace mcpp
