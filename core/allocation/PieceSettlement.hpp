#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"

namespace mcpp {

// Evens out regions further than a cell from their fair share, per connected part of the map, with
// BorderExchange: it passes single border cells and, where a donor cannot spare one (a region wrapped in a
// band one cell wide), a cell with what hangs on it, which single-cell moves cannot. Costs are summed again.
// Cancelled through `progress` (throwIfCancelled) between exchanges.
void settleRegionsWithPieces(const CellGraph& graph, RegionAllocation& regions,
                             const ProgressReporter& progress = ProgressReporter{});

} // namespace mcpp
