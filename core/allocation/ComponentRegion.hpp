#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/RegionAllocation.hpp"

namespace mcpp {

// A single robot's region: every cell connected to its start cell. The rest of the map is unreachable.
[[nodiscard]] RegionAllocation componentRegion(const CellGraph& graph, int startCell);

} // namespace mcpp
