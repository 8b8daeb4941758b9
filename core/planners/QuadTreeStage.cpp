#include "core/planners/QuadTreeStage.hpp"

#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"

#include <utility>

namespace mcpp {

CellGraph quadTreeStage(PlanningRun& run) {
    std::optional<CellGraph>* kept = run.keptCells();
    if (kept && *kept)
        return run.stage("cells of the first round", [&] { return **kept; });
    QuadTreeLeaves leaves = run.stage("quadtree", [&] {
        return QuadTreeBuilder{}.buildLeaves(
            run.problem().grid, run.problem().classes,
            DecompositionOptions::from(run.parameters(), run.bytesPerBottomCell()), run.progress());
    });
    CellGraph cells = run.stage("topology", [&] {
        run.progress().report("topology", 0.0);
        CellGraph built = cellGraphOfLeaves(std::move(leaves));
        built.applyTurnTime(TurnTimeModel::from(run.parameters()));
        return built;
    });
    // Kept as built: a planner may price the plan's cells again (turn calibration).
    if (kept)
        *kept = cells;
    return cells;
}

} // namespace mcpp
