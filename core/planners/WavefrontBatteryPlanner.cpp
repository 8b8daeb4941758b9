#include "core/planners/WavefrontBatteryPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/allocation/BatteryRange.hpp"
#include "core/coverage/WavefrontCoverage.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

namespace mcpp {
namespace {

std::vector<std::vector<int>> regionCells(const RegionAllocation& regions) {
    std::vector<std::vector<int>> cells(regions.startCell.size());
    for (std::size_t id = 0; id < regions.robotOfCell.size(); ++id)
        if (const int robot = regions.robotOfCell[id]; robot >= 0)
            cells[static_cast<std::size_t>(robot)].push_back(static_cast<int>(id));
    return cells;
}

std::string outOfRangeMessage(const RobotSorties& robot) {
    return formatArea(robot.outOfRangeAreaSquareMetres) + " of robot " + std::to_string(robot.robot + 1) +
           "'s region lies beyond half its battery (" + formatDuration(robot.enduranceSeconds) +
           ") from its charger and is not covered";
}

std::string beyondEveryChargerMessage(const CellGraph& cells, const std::vector<int>& ids,
                                      const BatteryRange& range) {
    double area = 0.0;
    for (const int id : ids)
        area += cells.cell(id).passableAreaSquareMetres;
    return formatArea(area) + " lies beyond half the battery (" + formatDuration(range.enduranceSeconds) +
           ") from every charger and is not covered";
}

} // namespace

PlannerDescription WavefrontBatteryPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "Wavefront with battery";
    description.summary = "wavefront coverage from far to near, in sorties from each robot's charger";
    // Cells beyond a battery's reach are left to no robot.
    description.promises.everyReachableCellCovered = false;
    description.parameters = {
        DecompositionOptions::blockedThresholdParameter(),
        AzimuthTrendAllocator::rebalanceIterationsParameter(),
        realParameter("battery_s", "Battery endurance", 1200.0, 1.0, 1e7,
                      "Seconds of travel and turning on one charge; each sortie starts and ends at the "
                      "robot's charger (its start) within it",
                      "s"),
        realParameter("recharge_s", "Recharge time", 600.0, 0.0, 1e7,
                      "Seconds at the charger between two sorties", "s"),
    };
    return description;
}

void WavefrontBatteryPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::WholeCell);
    const std::vector<int> startCells = run.locateStarts();
    const AzimuthTrendAllocator allocator(parameters.integer("rebalance_iterations"));
    const BatteryRange range{parameters.real("battery_s")};
    std::vector<int> beyondEveryCharger;
    plan.regions = run.stage("allocation", [&] {
        auto allocation = range.allocationGraph(plan.cells, startCells);
        beyondEveryCharger = std::move(allocation.outOfRange);
        return allocator.allocate(allocation.graph, startCells, run.progress());
    });
    if (!beyondEveryCharger.empty())
        run.addIssue(IssueSeverity::Warning, "beyond-every-charger",
                     beyondEveryChargerMessage(plan.cells, beyondEveryCharger, range));
    const WavefrontCoverage coverage(plan.cells,
                                     {parameters.real("battery_s"), parameters.real("recharge_s")});
    const std::vector<std::vector<int>> cells = regionCells(plan.regions);
    std::vector<WavefrontCoverage::Result> results(startCells.size());
    run.stage("paths", [&] {
        parallelFor(results.size(), [&](std::size_t robot, int) {
            results[robot] = coverage.cover(static_cast<int>(robot), cells[robot], startCells[robot],
                                            run.starts()[robot], run.progress());
        });
        return 0;
    });
    std::vector<RobotSorties> sorties;
    for (WavefrontCoverage::Result& result : results) {
        for (const int cell : result.sorties.outOfRangeCells)
            plan.regions.robotOfCell[static_cast<std::size_t>(cell)] = -1;
        if (result.sorties.outOfRangeAreaSquareMetres > 0.0)
            run.addIssue(IssueSeverity::Warning, "beyond-battery", outOfRangeMessage(result.sorties));
        plan.paths.push_back(std::move(result.path));
        sorties.push_back(std::move(result.sorties));
    }
    plan.layers.push_back(std::make_shared<SortieLayer>(std::move(sorties)));
}

} // namespace mcpp
