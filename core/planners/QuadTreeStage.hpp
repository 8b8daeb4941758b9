#pragma once

#include "core/model/CellGraph.hpp"
#include "core/planners/PlanningRun.hpp"

namespace mcpp {

// MCPP-MLCT's first stages: the quadtree whose cells grow with each land cover's field of view ("quadtree"),
// then its leaves and which of them touch ("topology"), each cell priced for turns by the run's turn
// parameters. The quadtree holds every node of the hierarchy: it is freed once the cell graph is built,
// which leaves room for the paths on large maps. A tree of one level (every class needs the same cell
// size) is made as its grid of cells, without the nodes. Where the run keeps cells for later runs of the
// same problem (PlanningRun::keptCells), the first builds them and the others copy them.
[[nodiscard]] CellGraph quadTreeStage(PlanningRun& run);

} // namespace mcpp
