#include "core/planners/GridStage.hpp"

namespace mcpp {

CellGraph gridStage(PlanningRun& run, GridCellRule rule) {
    return run.stage("grid", [&] {
        const UniformGridDecomposition grid(
            DecompositionOptions::from(run.parameters(), run.bytesPerBottomCell()), rule);
        CellGraph cells = grid.decompose(run.problem().grid, run.problem().classes, run.progress());
        cells.applyTurnTime(TurnTimeModel::from(run.parameters()));
        return cells;
    });
}

} // namespace mcpp
