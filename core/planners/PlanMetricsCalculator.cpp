#include "core/planners/PlanMetricsCalculator.hpp"

#include <algorithm>

namespace mcpp {

void PlanMetricsCalculator::compute(Plan& plan) const {
    PlanMetrics& metrics = plan.metrics;
    const CellGraph& graph = plan.cells;
    const std::size_t robots = plan.regions.startCell.size();
    metrics.robots.assign(robots, {});
    plan.regions.costSeconds.assign(robots, 0.0);
    double totalCost = 0.0;
    double covered = 0.0;
    double unreachable = 0.0;
    std::size_t subCells = 0;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        const int robot = id < plan.regions.robotOfCell.size() ? plan.regions.robotOfCell[id] : -1;
        if (robot < 0 || static_cast<std::size_t>(robot) >= robots) {
            unreachable += cell.passableAreaSquareMetres;
            continue;
        }
        RobotMetrics& robotMetrics = metrics.robots[static_cast<std::size_t>(robot)];
        ++robotMetrics.cells;
        robotMetrics.areaSquareMetres += cell.size * cell.size * cell.freeSubCellCount() / 4.0;
        robotMetrics.costSeconds += cell.coverSeconds();
        plan.regions.costSeconds[static_cast<std::size_t>(robot)] += cell.coverSeconds();
        totalCost += cell.coverSeconds();
        covered += cell.passableAreaSquareMetres;
        subCells += static_cast<std::size_t>(cell.freeSubCellCount());
    }
    std::size_t repeats = 0;
    metrics.makespanSeconds = 0.0;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        RobotMetrics& robotMetrics = metrics.robots[robot];
        robotMetrics.robot = static_cast<int>(robot);
        if (robot < plan.paths.size()) {
            const CoveragePath& path = plan.paths[robot];
            robotMetrics.lengthMetres = path.lengthMetres;
            robotMetrics.timeSeconds = path.timeSeconds;
            robotMetrics.turns = path.turns;
            repeats += static_cast<std::size_t>(path.repeatedSubCellVisits);
        }
        metrics.makespanSeconds = std::max(metrics.makespanSeconds, robotMetrics.timeSeconds);
    }
    metrics.lowerBoundSeconds = robots == 0 ? 0.0 : totalCost / static_cast<double>(robots);
    metrics.ratio =
        metrics.lowerBoundSeconds > 0.0 ? metrics.makespanSeconds / metrics.lowerBoundSeconds : 0.0;
    metrics.passableAreaSquareMetres = graph.passableAreaSquareMetres;
    metrics.coveredAreaSquareMetres = covered;
    metrics.coveredFraction =
        graph.passableAreaSquareMetres > 0.0 ? covered / graph.passableAreaSquareMetres : 0.0;
    metrics.unreachableAreaSquareMetres = unreachable;
    metrics.repeatedFraction =
        subCells == 0 ? 0.0 : static_cast<double>(repeats) / static_cast<double>(subCells);
}

} // namespace mcpp
