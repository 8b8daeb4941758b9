#include "core/planners/MdstcPlanner.hpp"

#include "core/allocation/RegionCosts.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathTimeBalancing.hpp"
#include "core/coverage/ReallocationSimulation.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TurnCalibration.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/SpeedSchedule.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/model/TurnTimeModel.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlanningRun.hpp"
#include "core/planners/QuadTreeStage.hpp"

#include <algorithm>
#include <limits>

namespace mcpp {
namespace {

constexpr const char* compareKey = "compare_static";
constexpr const char* quadTreeKey = "quadtree_cells";

// The static plan's parameters: MCPP-MLCT's defaults, with this run's turn model and start snapping, and
// open paths like MDSTC's (a return to the start would make the static plan look slower than it is).
ParameterValues staticParameters(const ParameterValues& own) {
    ParameterValues given;
    given.set(SpanningTreeCoverage::closedTourParameter().key, false);
    for (const ParameterSpec& shared :
         {TurnTimeModel::turnSecondsParameter(), TurnTimeModel::accelerationParameter(),
          Planner::snapStartsParameter(), DecompositionOptions::purityToleranceParameter(),
          DecompositionOptions::blockedThresholdParameter()})
        if (const ParameterValue* value = own.find(shared.key))
            given.set(shared.key, *value);
    return given;
}

// When each robot of the static plan would be done under the events.
std::vector<double> staticCompletions(const Plan& plan, const std::vector<SpeedEvent>& events,
                                      std::size_t robots) {
    std::vector<double> completions(robots, 0.0);
    for (const CoveragePath& path : plan.paths)
        if (path.robot >= 0 && static_cast<std::size_t>(path.robot) < robots)
            completions[static_cast<std::size_t>(path.robot)] =
                SpeedSchedule(events, path.robot).finishTime(0.0, path.timeSeconds);
    return completions;
}

RegionAllocation regionsOf(const CellGraph& cells, const std::vector<int>& robotOfCell,
                           const std::vector<int>& startCells) {
    return {robotOfCell, startCells, regionCosts(cells, robotOfCell, startCells.size())};
}

void reportLeftUncovered(PlanningRun& run, const std::vector<int>& uncovered, bool gaveUp) {
    if (uncovered.empty())
        return;
    double area = 0.0;
    for (const int cell : uncovered)
        area += run.plan().cells.cell(cell).passableAreaSquareMetres;
    run.addIssue(IssueSeverity::Warning, "left-uncovered",
                 formatArea(area) +
                     (gaveUp ? " stays uncovered: the simulation stopped at its move limit"
                             : " stays uncovered: every robot that could reach it stopped first"));
}

// The regions the robots set out with: grown from the starts in turns (seed 003), then balanced on the
// paths the walks will follow (MCPP-MLCT trees), as MCPP-MLCT balances its own. Those trees turn less than
// the cost's default rate: the rate measured on the grown regions prices the cells for a second growth, kept
// when its longest path is shorter.
RegionAllocation balancedDivision(PlanningRun& run, CellGraph& cells, const std::vector<int>& startCells) {
    const ProgressReporter& progress = run.progress();
    const SpanningTreeCoverage coverage(false);
    RegionAllocation division = ReallocationSimulation::firstDivision(cells, startCells, progress);
    // Compared by their trees, the two divisions hold a quarter of their paths' memory; only the one kept
    // is walked.
    std::vector<SpanningTreeCoverage::RegionTree> trees =
        coverage.planTrees(cells, division, run.starts(), progress.within("first division", 0.0, 0.3), true);
    if (calibrateTurnRates(cells, division, turningSecondsOf(trees))) {
        RegionAllocation priced = ReallocationSimulation::firstDivision(cells, startCells, progress);
        std::vector<SpanningTreeCoverage::RegionTree> pricedTrees = coverage.planTrees(
            cells, priced, run.starts(), progress.within("first division", 0.3, 0.6), true);
        if (walksQuicker(pricedTrees, trees)) {
            division = std::move(priced);
            trees = std::move(pricedTrees);
        }
    }
    std::vector<CoveragePath> paths = coverage.walkTrees(cells, std::move(trees), run.starts(), progress);
    const PathTimeBalancing balancing(coverage, PathTimeBalancing::budgetFor(cells));
    balancing.balance(cells, division, paths, run.starts(), progress.within("first division", 0.6, 1.0));
    return division;
}

} // namespace

PlannerDescription MdstcPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "MDSTC";
    description.summary =
        "regions re-divided while robots drive, for missions where robots slow down or stop";
    description.simulatesEvents = true;
    description.quadTreeCells = true;
    description.quadTreeSwitch = quadTreeKey;
    // A region may gain cells it reaches only by a detour, through other regions.
    description.promises.regionsConnected = false;
    description.promises.pathsCoverOwnRegion = false;
    description.parameters = {
        booleanParameter(
            quadTreeKey, "Cells sized by field of view", true,
            "Drive on MCPP-MLCT's quadtree, whose cells grow with each land cover's field of view, "
            "as the static plan does; off: on the uniform grid of 2 x the smallest field of view, "
            "as the seed does (slower wherever fields of view differ)"),
        DecompositionOptions::purityToleranceParameter(), DecompositionOptions::blockedThresholdParameter(),
        booleanParameter(compareKey, "Compare with a static plan", true,
                         "Also plan MCPP-MLCT and run it through the same events without re-allocation, "
                         "so the report shows what re-allocation saved (takes about as long again)")};
    return description;
}

void MdstcPlanner::run(PlanningRun& run) const {
    Plan& plan = run.plan();
    const PlanningProblem& problem = run.problem();
    plan.cells =
        run.parameters().boolean(quadTreeKey) ? quadTreeStage(run) : gridStage(run, GridCellRule::WholeCell);
    const std::vector<int> startCells = run.locateStarts();
    const RegionAllocation division =
        run.stage("first division", [&] { return balancedDivision(run, plan.cells, startCells); });
    ReallocationSimulation simulation(plan.cells, problem.events);
    ReallocationSimulation::Result result =
        run.stage("simulation", [&] { return simulation.run(division, run.starts(), run.progress()); });
    plan.regions = regionsOf(plan.cells, result.finalRegions, startCells);
    plan.paths = std::move(result.paths);
    reportLeftUncovered(run, result.uncoveredCells, result.gaveUp);

    TimelineLayer::Summary summary;
    summary.events = problem.events;
    for (const RobotTimeline& robot : result.robots)
        summary.makespanSeconds = std::max(summary.makespanSeconds, robot.completionSeconds);
    if (run.parameters().boolean(compareKey)) {
        const Plan staticPlan = run.stage("static plan", [&] {
            // Compared path time to path time: the static plan is not evened out in the field.
            PlanningProblem onPaths = problem;
            onPaths.fieldSeconds = nullptr;
            onPaths.robotFlights.clear();
            return MlctPlanner{}.plan(onPaths, staticParameters(run.parameters()),
                                      run.progress().within("static plan", 0.0, 1.0));
        });
        const std::vector<double> completions =
            staticCompletions(staticPlan, problem.events, result.robots.size());
        for (std::size_t r = 0; r < result.robots.size(); ++r)
            result.robots[r].staticCompletionSeconds = completions[r];
        summary.staticPlanner = MlctPlanner::plannerName;
        for (const double completion : completions)
            summary.staticMakespanSeconds = std::max(summary.staticMakespanSeconds, completion);
        summary.staticPlanMakespanSeconds = staticPlan.metrics.makespanSeconds;
    }
    plan.layers.push_back(std::make_shared<TimelineLayer>(std::move(summary), std::move(result.robots),
                                                          std::move(result.firstRegions)));
}

} // namespace mcpp
