#include "core/planners/MlctPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/allocation/BorderStraightening.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathTimeBalancing.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TurnCalibration.hpp"
#include "core/decomposition/DecompositionOptions.hpp"
#include "core/planners/PlanningRun.hpp"
#include "core/planners/QuadTreeStage.hpp"

#include <algorithm>

namespace mcpp {
namespace {

// Whether turns take a share of some robot's time that a better estimate of them could rebalance: on slow
// land covers they are a rounding error (0.05 % of the time on the WorldCover crop) and a second
// allocation would only cost time.
bool turnsWeigh(const std::vector<CoveragePath>& paths) {
    constexpr double smallestShare = 0.005;
    return std::any_of(paths.begin(), paths.end(), [](const CoveragePath& path) {
        return path.turnSeconds > smallestShare * path.timeSeconds;
    });
}

} // namespace

PlannerDescription MlctPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "MCPP-MLCT";
    description.summary = "quadtree cells sized by field of view, azimuth-trend regions, improved STC";
    description.parameters = {
        DecompositionOptions::purityToleranceParameter(), DecompositionOptions::blockedThresholdParameter(),
        AzimuthTrendAllocator::rebalanceIterationsParameter(), BorderStraightening::slackParameter(),
        SpanningTreeCoverage::closedTourParameter()};
    return description;
}

void MlctPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    const ProgressReporter& progress = run.progress();
    Plan& plan = run.plan();
    plan.cells = quadTreeStage(run);
    const std::vector<int> startCells = run.locateStarts();
    const AzimuthTrendAllocator allocator(parameters.integer("rebalance_iterations"));
    const BorderStraightening straightening(plan.cells, parameters.real("fewer_turns_slack") / 100.0);
    plan.regions =
        run.stage("allocation", [&] { return allocator.allocate(plan.cells, startCells, progress); });
    run.stage("straight borders", [&] { return straightening.straighten(plan.regions); });
    const SpanningTreeCoverage coverage(parameters.boolean("closed_tour"));
    plan.paths =
        run.stage("paths", [&] { return coverage.plan(plan.cells, plan.regions, run.starts(), progress); });
    // Turns are not spread evenly: a second allocation with each region's measured turn rate balances real
    // time better. The faster plan is kept.
    run.stage("turn balance", [&] {
        if (!turnsWeigh(plan.paths) || !calibrateTurnRates(plan.cells, plan.regions, plan.paths))
            return 0;
        RegionAllocation regions =
            allocator.allocate(plan.cells, startCells, progress.within("turn balance", 0.0, 0.5));
        straightening.straighten(regions);
        std::vector<CoveragePath> paths =
            coverage.plan(plan.cells, regions, run.starts(), progress.within("turn balance", 0.5, 1.0));
        if (longestPathSeconds(paths) < longestPathSeconds(plan.paths)) {
            plan.regions = std::move(regions);
            plan.paths = std::move(paths);
        }
        return 0;
    });
    // Costs only estimate path times: border cells pass from the longest path to shorter neighbours, paths
    // replanned, while that shortens the longest. Bounded to about half a second of replanning.
    const PathTimeBalancing balancing(coverage, PathTimeBalancing::budgetFor(plan.cells));
    run.stage("path balance", [&] {
        return balancing.balance(plan.cells, plan.regions, plan.paths, run.starts(), progress);
    });
}

} // namespace mcpp
