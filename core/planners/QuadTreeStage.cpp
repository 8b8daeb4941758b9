#include "core/planners/QuadTreeStage.hpp"

#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"

#include <utility>

namespace mcpp {

CellGraph quadTreeStage(PlanningRun& run) {
    QuadTree tree = run.stage("quadtree", [&] {
        return QuadTreeBuilder{}.build(run.problem().grid, run.problem().classes,
                                       DecompositionOptions::from(run.parameters(), run.bytesPerBottomCell()),
                                       run.progress());
    });
    return run.stage("topology", [&] {
        run.progress().report("topology", 0.0);
        NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
        CellGraph cells = cellGraphOfQuadTree(std::move(tree), std::move(topology));
        cells.applyTurnTime(TurnTimeModel::from(run.parameters()));
        return cells;
    });
}

} // namespace mcpp
