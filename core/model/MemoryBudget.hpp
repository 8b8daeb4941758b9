#pragma once

#include <cstdint>

namespace mcpp {

// What planning takes per cell of the finest grid for a planner not measured on large maps (4.8 million
// cells planned and exported in 1.86 GB before cells and waypoints shrank): the cells and their neighbours,
// the regions, the paths through four sub-cells each, and the exports' grids. A planner measured at scale
// declares its own figure (PlannerDescription::bytesPerBottomCell).
inline constexpr std::int64_t unmeasuredBytesPerBottomCell = 400;

// The memory a plan may use. The program sets it from the machine's memory at start; until then 8 GiB.
[[nodiscard]] std::int64_t memoryBudgetBytes();
void setMemoryBudgetBytes(std::int64_t bytes);

} // namespace mcpp
