#pragma once

#include "core/model/TimelineLayer.hpp"

#include <string>

namespace mcpp {

// One line for people: "under 2 events: done in 2 d 5 h; the static mcpp-mlct plan through the same
// events: never done (a robot stops with work left)", or "... 2 d 13 h (31.2 % saved)", or, when the
// static plan is the faster, "... (9.1 % less)". The batch summary and the window both say it.
[[nodiscard]] std::string timelineSentence(const TimelineLayer::Summary& summary);

} // namespace mcpp
