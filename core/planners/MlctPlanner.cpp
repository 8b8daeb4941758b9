#include "core/planners/MlctPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/decomposition/QuadTreeDecomposition.hpp"
#include "core/planners/PlanningRun.hpp"

namespace mcpp {

PlannerDescription MlctPlanner::description() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "MCPP-MLCT";
    description.summary =
        "quadtree cells sized by each land cover's field of view, balanced regions grown by "
        "azimuth trend, improved spanning-tree coverage";
    return description;
}

void MlctPlanner::run(PlanningRun& run) const {
    const PlanningProblem& problem = run.problem();
    const ProgressReporter& progress = run.progress();
    Plan& plan = run.plan();
    const QuadTree tree = run.stage("quadtree", [&] {
        return QuadTreeBuilder{}.build(problem.grid, problem.classes, problem.settings, progress);
    });
    plan.cells = run.stage("topology", [&] {
        progress.report("topology", 0.0);
        return cellGraphOfQuadTree(tree, NeighbourTopologyBuilder{}.build(tree));
    });
    const std::vector<int> startCells = run.locateStarts();
    plan.regions = run.stage("allocation", [&] {
        return AzimuthTrendAllocator{}.allocate(plan.cells, startCells, problem.settings, progress);
    });
    plan.paths = run.stage("paths", [&] {
        return SpanningTreeCoverage{}.plan(plan.cells, plan.regions, run.starts(), problem.settings,
                                           progress);
    });
}

} // namespace mcpp
