#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// The turns per sub-cell each robot's measured path made, given to every cell of its region: where a
// region turns often (obstacles, narrow strips) its cells cost more in the next allocation, so that the
// regions balance real time rather than travel. Cells of no region keep their rate. Paths must be
// measured. Returns whether any rate changed (nothing to do when turns are free).
bool calibrateTurnRates(CellGraph& graph, const RegionAllocation& regions,
                        const std::vector<CoveragePath>& paths);
// The same from each robot's time spent turning, as its path would measure it.
bool calibrateTurnRates(CellGraph& graph, const RegionAllocation& regions,
                        const std::vector<double>& turningSecondsByRobot);

} // namespace mcpp
