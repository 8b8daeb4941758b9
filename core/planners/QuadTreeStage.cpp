#include "core/planners/QuadTreeStage.hpp"

#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"

namespace mcpp {

CellGraph quadTreeStage(PlanningRun& run) {
    const QuadTree tree = run.stage("quadtree", [&] {
        return QuadTreeBuilder{}.build(run.problem().grid, run.problem().classes,
                                       DecompositionOptions::from(run.parameters()), run.progress());
    });
    return run.stage("topology", [&] {
        run.progress().report("topology", 0.0);
        CellGraph cells = cellGraphOfQuadTree(tree, NeighbourTopologyBuilder{}.build(tree));
        cells.applyTurnTime(TurnTimeModel::from(run.parameters()));
        return cells;
    });
}

} // namespace mcpp
