#pragma once

#include "core/model/Plan.hpp"
#include "core/planners/PlannerDescription.hpp"

#include <string>

namespace mcpp {

// Robots that come home far apart in the field (their flights, the trips out to the work and back, and the
// turnarounds between them): "robot 3 comes home after 12 d 22 h in the field, 1.91 times as long as
// robot 1 (6 d 18 h 11 min)", why, and what evens them out. The summary's last / first figure alone reads
// as a measure, not as something to mend. Empty where they come home within a quarter of each other, where
// times in the field are not measured, and where robots are confined to pockets (their pockets set it).
[[nodiscard]] std::string unevenFieldMessage(const Plan& plan, const PlannerDescription& planner);

} // namespace mcpp
