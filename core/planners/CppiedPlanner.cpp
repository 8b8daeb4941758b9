#include "core/planners/CppiedPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/coverage/DetectionAccumulator.hpp"
#include "core/coverage/DetectionCoverage.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace mcpp {
namespace {

constexpr float notATarget = std::numeric_limits<float>::quiet_NaN();

// The required probability of each lattice cell a robot covers: 0 where its land cover hides targets.
std::vector<float> requiredByPosition(const Plan& plan, const DetectionLattice& lattice,
                                      const DetectionAccumulator& seen, double required) {
    const LatticeWindow whole = lattice.whole();
    std::vector<float> byPosition(whole.size(), notATarget);
    for (int row = 0; row < whole.rows; ++row)
        for (int column = 0; column < whole.columns; ++column) {
            const LatticePosition position{column, row};
            const int cell = lattice.cellAt(position);
            if (cell < 0 || plan.regions.robotOfCell[static_cast<std::size_t>(cell)] < 0)
                continue;
            const std::size_t index = whole.index(position);
            const bool visible = seen.model().nearProbability(seen.profileAt(index)) > 0.0;
            byPosition[index] = visible ? static_cast<float>(required) : 0.0F;
        }
    return byPosition;
}

DetectionSummary summarise(const DetectionGrid& grid, double required) {
    DetectionSummary summary;
    summary.requiredProbability = required;
    summary.minimum = 1.0;
    double sum = 0.0;
    double seenUpToRequired = 0.0; // for the lower bound
    for (std::size_t index = 0; index < grid.required.size(); ++index) {
        const float target = grid.required[index];
        if (std::isnan(target))
            continue;
        if (target == 0.0F) {
            summary.undetectableAreaSquareMetres += grid.cellSize * grid.cellSize;
            continue;
        }
        ++summary.targets;
        const double seen = grid.probability[index];
        summary.minimum = std::min(summary.minimum, seen);
        sum += seen;
        seenUpToRequired += std::min(seen, required);
        if (seen < target - 1e-6)
            ++summary.unmetTargets;
    }
    if (summary.targets == 0)
        summary.minimum = 0.0;
    summary.mean = summary.targets == 0 ? 0.0 : sum / static_cast<double>(summary.targets);
    summary.passesNoPlanBeats = seenUpToRequired; // divided by the strip's sum in boundPasses
    summary.shareMet = summary.targets == 0 ? 1.0
                                            : 1.0 - static_cast<double>(summary.unmetTargets) /
                                                        static_cast<double>(summary.targets);
    return summary;
}

// What every robot's path sees, on the whole lattice; NaN off the free sub-cells.
DetectionGrid detectionGrid(const Plan& plan, const DetectionLattice& lattice, const DetectionModel& model,
                            double required) {
    DetectionAccumulator seen(lattice, plan.cells, model, lattice.whole());
    for (const CoveragePath& path : plan.paths)
        seen.addPath(path);
    DetectionGrid grid;
    grid.originX = lattice.originX();
    grid.originY = lattice.originY();
    grid.cellSize = lattice.cellSize();
    grid.columns = lattice.whole().columns;
    grid.rows = lattice.whole().rows;
    grid.required = requiredByPosition(plan, lattice, seen, required);
    // Values only where a robot goes, as in the required band.
    grid.probability.assign(lattice.whole().size(), notATarget);
    for (std::size_t index = 0; index < grid.probability.size(); ++index)
        if (!std::isnan(grid.required[index]))
            grid.probability[index] = static_cast<float>(seen.probabilities()[index]);
    return grid;
}

// The land covers of covered cells that hide targets altogether (p0 = 0), by name.
std::string undetectableClasses(const Plan& plan, const ClassTable& classes, const DetectionModel& model) {
    std::set<std::string> names;
    for (std::size_t cell = 0; cell < plan.cells.size(); ++cell) {
        if (plan.regions.robotOfCell[cell] < 0)
            continue;
        const std::int32_t value = plan.cells.cell(static_cast<int>(cell)).classValue;
        if (model.nearProbability(model.profileOf(value)) > 0.0)
            continue;
        const LandCoverClass* landCover = classes.find(value);
        names.insert(landCover != nullptr && !landCover->name.empty() ? landCover->name
                                                                      : "class " + std::to_string(value));
    }
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : ", ") + name;
    return joined;
}

// See DetectionSummary::passesNoPlanBeats.
void boundPasses(DetectionSummary& summary, const DetectionModel& model, const Plan& plan, double cellSize) {
    double stripSum = 0.0;
    for (int offset = -model.reach(); offset <= model.reach(); ++offset) {
        double best = 0.0;
        for (int profile = 0; profile < model.profiles(); ++profile)
            best = std::max(best, model.probability(profile, offset));
        stripSum += best;
    }
    double fastest = 0.0;
    for (const Cell& cell : plan.cells.cells())
        fastest = std::max(fastest, double{cell.speedMetresPerSecond});
    if (stripSum <= 0.0 || fastest <= 0.0) {
        summary.passesNoPlanBeats = 0.0;
        return;
    }
    summary.passesNoPlanBeats /= stripSum;
    summary.secondsPerStep = cellSize / fastest;
}

// The grid priced for detection: a cell's travel time scaled by the passes its land cover needs per
// lattice cell (fewer where the sensor sees far, more where it often misses), so that the regions share
// the passes and not the area. Land whose targets cannot be seen is priced as crossed once in a while.
CellGraph priceForDetection(const CellGraph& cells, const DetectionModel& model, double required) {
    constexpr double crossedOnly = 0.25;
    std::vector<double> passesOfProfile(static_cast<std::size_t>(model.profiles()));
    for (int profile = 0; profile < model.profiles(); ++profile) {
        const double passes = model.passesPerCell(profile, required);
        passesOfProfile[static_cast<std::size_t>(profile)] = passes > 0.0 ? passes : crossedOnly;
    }
    std::vector<CellRecord> priced = cells.records();
    for (CellRecord& cell : priced) {
        const int profile = model.profileOf(cell.classValue);
        if (profile != DetectionModel::noProfile)
            cell.speedMetresPerSecond = static_cast<float>(
                cell.speedMetresPerSecond / passesOfProfile[static_cast<std::size_t>(profile)]);
    }
    return CellGraph(cells, std::move(priced));
}

void warnOfMisses(PlanningRun& run, const DetectionSummary& summary, const DetectionModel& model) {
    if (summary.undetectableAreaSquareMetres > 0.0)
        run.addIssue(IssueSeverity::Warning, "undetectable",
                     formatArea(summary.undetectableAreaSquareMetres) + " of " +
                         undetectableClasses(run.plan(), run.problem().classes, model) +
                         " cannot reach the required probability: targets there are never seen "
                         "(detection probability 0)");
    if (summary.unmetTargets > 0)
        run.addIssue(IssueSeverity::Warning, "below-required-probability",
                     std::to_string(summary.unmetTargets) +
                         " lattice cells stay below the required "
                         "probability " +
                         formatQuantity(summary.requiredProbability));
}

} // namespace

PlannerDescription CppiedPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "CPPIED";
    description.summary = "straight passes until every cell is seen with the required probability, by an "
                          "imperfect sensor";
    // Passes run a strip apart where the sensor sees farther than a sub-cell.
    description.promises.passesEverySubCell = false;
    description.parameters = {
        DecompositionOptions::blockedThresholdParameter(),
        AzimuthTrendAllocator::rebalanceIterationsParameter(),
        realParameter("required_probability", "Required detection", 0.95, 0.001, 1.0,
                      "Chance with which a target in every covered cell must be seen", {}, false),
        realParameter("detection_probability", "Sensor detection", 0.9, 0.0, 1.0,
                      "Chance one pass sees a target beside it, for classes whose table gives none; it "
                      "fades to 0 from half a field of view to a whole one"),
    };
    return description;
}

void CppiedPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::WholeCell);
    const std::vector<int> startCells = run.locateStarts();
    const double required = parameters.real("required_probability");
    const DetectionLattice lattice(plan.cells);
    const DetectionModel model(run.problem().classes, parameters.real("detection_probability"),
                               lattice.cellSize());
    plan.regions = run.stage("allocation", [&] {
        return AzimuthTrendAllocator(parameters.integer("rebalance_iterations"))
            .allocate(priceForDetection(plan.cells, model, required), startCells, run.progress());
    });
    run.stage("paths", [&] {
        const std::vector<std::vector<int>> cells = cellsByRobot(plan.regions);
        std::vector<CoveragePath> paths(startCells.size());
        const DetectionCoverage coverage(plan.cells, lattice, model, required);
        parallelFor(startCells.size(), [&](std::size_t robot, int) {
            paths[robot] = coverage.cover(static_cast<int>(robot), cells[robot], startCells[robot],
                                          run.starts()[robot], run.progress());
        });
        plan.paths = std::move(paths);
        return 0;
    });
    DetectionGrid grid =
        run.stage("detection", [&] { return detectionGrid(plan, lattice, model, required); });
    DetectionSummary summary = summarise(grid, required);
    boundPasses(summary, model, plan, lattice.cellSize());
    warnOfMisses(run, summary, model);
    plan.layers.push_back(std::make_shared<DetectionLayer>(std::move(grid), summary));
}

} // namespace mcpp
