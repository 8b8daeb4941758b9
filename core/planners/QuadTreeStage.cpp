#include "core/planners/QuadTreeStage.hpp"

#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"

#include <utility>

namespace mcpp {

CellGraph quadTreeStage(PlanningRun& run) {
    QuadTreeLeaves leaves = run.stage("quadtree", [&] {
        return QuadTreeBuilder{}.buildLeaves(
            run.problem().grid, run.problem().classes,
            DecompositionOptions::from(run.parameters(), run.bytesPerBottomCell()), run.progress());
    });
    return run.stage("topology", [&] {
        run.progress().report("topology", 0.0);
        CellGraph cells = cellGraphOfLeaves(std::move(leaves));
        cells.applyTurnTime(TurnTimeModel::from(run.parameters()));
        return cells;
    });
}

} // namespace mcpp
