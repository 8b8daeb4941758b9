#pragma once

#include "core/model/ClassTable.hpp"
#include "io/Mission.hpp"

#include <optional>

namespace mcpp::io {

// Why a plan may take weeks when the user meant hours, for each front end to word with its own controls:
// the whole raster planned where a part was meant, or drones planned at a ground robot's speeds.
struct LongPlanCauses {
    bool wholeRaster = false; // no area of interest: every piece of land on the raster is covered
    // Every robot a rover at the class table's speeds, no cruise speed, all of them below a drone's 5 m/s.
    bool groundSpeeds = false;
    double slowestSpeedMetresPerSecond = 0.0; // the class table's passable speeds
    double fastestSpeedMetresPerSecond = 0.0;
};

// Plans longer than this are worth a word on why.
constexpr double longPlanSeconds = 14.0 * 24.0 * 3600.0;

// The causes that apply to a plan of `makespanSeconds`; none where it is shorter than `longPlanSeconds` or
// neither cause applies.
[[nodiscard]] std::optional<LongPlanCauses> longPlanCauses(double makespanSeconds, const Mission& mission,
                                                           const ClassTable& classes);

} // namespace mcpp::io
