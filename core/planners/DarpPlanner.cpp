#include "core/planners/DarpPlanner.hpp"

#include "core/allocation/DarpAllocator.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TurnSearch.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

#include <sstream>

namespace mcpp {

PlannerDescription DarpPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "DARP";
    description.summary =
        "grid cells divided by DARP into regions of equal cover time, fewest-turn STC per region";
    description.parameters = {DecompositionOptions::blockedThresholdParameter()};
    for (ParameterSpec& spec : DarpAllocator::Options::parameters())
        description.parameters.push_back(std::move(spec));
    description.parameters.push_back(SpanningTreeCoverage::closedTourParameter());
    description.parameters.push_back(TurnSearch::roundsParameter());
    return description;
}

void DarpPlanner::run(PlanningRun& run) const {
    planRegionsAndPaths(run);
    searchTurns(run);
}

void DarpPlanner::searchTurns(PlanningRun& run) const {
    Plan& plan = run.plan();
    const TurnSearch search = TurnSearch::forPlan(plan.cells, run.parameters());
    run.stage("turn search", [&] {
        return search.improve(plan.cells, plan.regions, plan.paths, run.starts(), run.progress());
    });
}

void DarpPlanner::planRegionsAndPaths(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::WholeCell);
    const std::vector<int> startCells = run.locateStarts();
    const DarpAllocator allocator(DarpAllocator::Options::from(parameters));
    plan.regions =
        run.stage("allocation", [&] { return allocator.allocate(plan.cells, startCells, run.progress()); });
    if (!allocator.outcome().converged) {
        std::ostringstream text;
        text.precision(3);
        text << "DARP stopped after " << allocator.outcome().iterations << " rounds with a region "
             << allocator.outcome().largestShareError * 100.0 << "% off its fair share";
        run.addIssue(IssueSeverity::Warning, "not-converged", text.str());
    }
    plan.paths = run.stage("paths", [&] {
        const SpanningTreeCoverage coverage(parameters.boolean("closed_tour"));
        // The metrics stage measures the paths.
        return coverage.timedPlan(plan.cells, plan.regions, run.starts(), run.progress());
    });
}

} // namespace mcpp
