#include "core/planners/SpiralStcPlanner.hpp"

#include "core/allocation/ComponentRegion.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

namespace mcpp {

PlannerDescription SpiralStcPlanner::describe() const {
    PlannerDescription description;
    description.name = "spiral-stc";
    description.label = "Spiral-STC";
    description.summary = "mega-cells touching an obstacle dropped, spiral spanning tree from the start";
    description.singleRobot = true;
    description.parameters = {DecompositionOptions::blockedThresholdParameter(),
                              SpanningTreeCoverage::closedTourParameter()};
    return description;
}

void SpiralStcPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::AllSubCellsFree);
    const int startCell =
        run.locateStarts("touches an obstacle or the edge of the area (Spiral-STC leaves such "
                         "mega-cells out; full-spiral-stc keeps them)")
            .front();
    plan.regions = run.stage("allocation", [&] { return componentRegion(plan.cells, startCell); });
    plan.paths = run.stage("paths", [&] {
        std::vector<int> scratchIndex(plan.cells.size(), -1);
        const SpanningTree tree = SpanningTreeBuilder(plan.cells, scratchIndex)
                                      .spiral(cellsByRobot(plan.regions).front(), startCell);
        TreeCircumnavigation walker(plan.cells);
        const bool closed = parameters.boolean("closed_tour");
        const MapPoint start = run.starts().front();
        return std::vector<CoveragePath>{pathFromWalk(0, start, walker.walk(tree, start, closed), closed)};
    });
}

} // namespace mcpp
