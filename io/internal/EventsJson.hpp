#pragma once

#include "core/model/SpeedEvent.hpp"
#include "io/internal/JsonValue.hpp"

#include <vector>

namespace mcpp::io::internal {

// The events as mission files and report.json both write them: "events": [{time_s, robot, speed_factor}].
inline void addEvents(JsonValue& parent, const std::vector<SpeedEvent>& events) {
    JsonValue& list = parent.add("events", JsonValue::array());
    for (const SpeedEvent& event : events) {
        JsonValue& item = list.push(JsonValue::object());
        item.add("time_s", event.timeSeconds);
        item.add("robot", event.robot);
        item.add("speed_factor", event.speedFactor);
    }
}

} // namespace mcpp::io::internal
