#include "core/planners/DarpTurnsPlanner.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/TurnReduction.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/planners/PlanningRun.hpp"

#include <string>

namespace mcpp {

PlannerDescription DarpTurnsPlanner::describe() const {
    PlannerDescription description = DarpPlanner::describe();
    description.name = "darp-turns";
    description.label = "DARP with turn reduction";
    description.summary = "DARP, then cells at the ends of regions change hands where that saves turns";
    description.parameters.push_back(
        integerParameter("turn_reduction_rounds", "Turn reduction rounds", 3, 0, 100,
                         "Passes over the cells sticking out of a region; each moves those whose change of "
                         "hands lowers the turns of both regions without lengthening the longest path"));
    return description;
}

void DarpTurnsPlanner::run(PlanningRun& run) const {
    planRegionsAndPaths(run);
    Plan& plan = run.plan();
    const SpanningTreeCoverage coverage(run.parameters().boolean("closed_tour"));
    const TurnReduction reduction(coverage, run.parameters().integer("turn_reduction_rounds"));
    const TurnReduction::Outcome outcome = run.stage("turns", [&] {
        // DARP's paths are only timed; the reduction weighs their turns.
        parallelFor(plan.paths.size(),
                    [&](std::size_t path, int) { measurePath(plan.paths[path], plan.cells); });
        return reduction.improve(plan.cells, plan.regions, plan.paths, run.starts(), run.progress());
    });
    run.addIssue(IssueSeverity::Information, "turns-reduced",
                 "turn reduction moved " + std::to_string(outcome.cellsMoved) +
                     " cells: " + std::to_string(outcome.turnsBefore) + " turns before, " +
                     std::to_string(outcome.turnsAfter) + " after");
    // After the reduction, whose replans build trees without the search.
    searchTurns(run);
}

} // namespace mcpp
