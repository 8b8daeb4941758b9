#pragma once

#include "core/decomposition/UniformGridDecomposition.hpp"
#include "core/model/CellGraph.hpp"
#include "core/planners/PlanningRun.hpp"

namespace mcpp {

// The grid planners' first stage: the problem's uniform grid of 2 x Fd_min cells, kept by `rule`, timed
// as "grid", each cell priced for turns by the run's turn parameters.
[[nodiscard]] CellGraph gridStage(PlanningRun& run, GridCellRule rule);

} // namespace mcpp
