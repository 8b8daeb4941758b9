#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// The turns per sub-cell each robot's path made (from the seconds it spends turning, as measured or as its
// walk's shape gives them), given to every cell of its region: where a region turns often (obstacles,
// narrow strips) its cells cost more in the next allocation, so that the regions balance real time rather
// than travel. Cells of no region keep their rate. Returns whether any rate changed (nothing to do when
// turns are free).
bool calibrateTurnRates(CellGraph& graph, const RegionAllocation& regions,
                        const std::vector<double>& turningSecondsByRobot);

} // namespace mcpp
