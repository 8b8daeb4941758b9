#include "core/planners/MlctPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "core/planners/PlanningRun.hpp"

namespace mcpp {

PlannerDescription MlctPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "MCPP-MLCT";
    description.summary = "quadtree cells sized by field of view, azimuth-trend regions, improved STC";
    description.parameters = {
        DecompositionOptions::purityToleranceParameter(), DecompositionOptions::blockedThresholdParameter(),
        AzimuthTrendAllocator::rebalanceIterationsParameter(), SpanningTreeCoverage::closedTourParameter()};
    return description;
}

void MlctPlanner::run(PlanningRun& run) const {
    const PlanningProblem& problem = run.problem();
    const ParameterValues& parameters = run.parameters();
    const ProgressReporter& progress = run.progress();
    Plan& plan = run.plan();
    // The quadtree holds every node of the hierarchy: freed once the cell graph is built, it leaves room for
    // the paths on large maps.
    plan.cells = [&] {
        const QuadTree tree = run.stage("quadtree", [&] {
            return QuadTreeBuilder{}.build(problem.grid, problem.classes,
                                           DecompositionOptions::from(parameters), progress);
        });
        return run.stage("topology", [&] {
            progress.report("topology", 0.0);
            CellGraph cells = cellGraphOfQuadTree(tree, NeighbourTopologyBuilder{}.build(tree));
            cells.applyTurnTime(TurnTimeModel::from(parameters));
            return cells;
        });
    }();
    const std::vector<int> startCells = run.locateStarts();
    plan.regions = run.stage("allocation", [&] {
        const AzimuthTrendAllocator allocator(parameters.integer("rebalance_iterations"));
        return allocator.allocate(plan.cells, startCells, progress);
    });
    plan.paths = run.stage("paths", [&] {
        const SpanningTreeCoverage coverage(parameters.boolean("closed_tour"));
        return coverage.plan(plan.cells, plan.regions, run.starts(), progress);
    });
}

} // namespace mcpp
