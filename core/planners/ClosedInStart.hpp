#pragma once

#include "core/model/Plan.hpp"

#include <optional>
#include <vector>

namespace mcpp {

// What lies behind a robot's start when the other robots' starts are walls: where every region holds its own
// start and no other, all that robot's region can hold.
struct ClosedInStart {
    int robot = 0;
    std::vector<int> closedBy; // the robots whose starts close it in, in order
    double areaSquareMetres = 0.0;
};

// The plan's robot `robot` (from 0) closed in by others' starts, searched until what lies behind its start
// holds `enoughSeconds` of cover (then it is not: nothing). Nothing too for a pocket no start closes (a part
// of the map of its own, which the confined-robot note names).
[[nodiscard]] std::optional<ClosedInStart> closedInStart(const Plan& plan, int robot, double enoughSeconds);

} // namespace mcpp
