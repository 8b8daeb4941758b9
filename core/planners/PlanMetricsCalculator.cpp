#include "core/planners/PlanMetricsCalculator.hpp"

#include "core/allocation/RegionAllocator.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {

void PlanMetricsCalculator::compute(Plan& plan) const {
    PlanMetrics& metrics = plan.metrics;
    const QuadTree& tree = plan.quadTree;
    const std::size_t robots = plan.allocation.startCell.size();
    metrics.robots.assign(robots, {});
    double totalCost = 0.0;
    double covered = 0.0;
    double unreachable = 0.0;
    std::size_t subCells = 0;
    for (std::size_t cell = 0; cell < tree.activeCount(); ++cell) {
        const QuadCell& quadCell = tree.active(static_cast<int>(cell));
        const int robot = plan.allocation.robotOfCell[cell];
        if (robot < 0) {
            unreachable += quadCell.passableAreaSquareMetres;
            continue;
        }
        RobotMetrics& robotMetrics = metrics.robots[static_cast<std::size_t>(robot)];
        ++robotMetrics.cells;
        robotMetrics.areaSquareMetres += quadCell.size * quadCell.size;
        robotMetrics.costSeconds += cellCostSeconds(quadCell);
        totalCost += cellCostSeconds(quadCell);
        covered += quadCell.passableAreaSquareMetres;
        subCells += 4;
    }
    // Repeated coverage: sub-cell visits beyond the first, over the number of sub-cells.
    std::size_t repeats = 0;
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
    metrics.ratio = metrics.lowerBoundSeconds > 0.0 ? metrics.makespanSeconds / metrics.lowerBoundSeconds : 0.0;
    metrics.passableAreaSquareMetres = tree.passableAreaSquareMetres;
    metrics.coveredAreaSquareMetres = covered;
    metrics.coveredFraction = tree.passableAreaSquareMetres > 0.0 ? covered / tree.passableAreaSquareMetres : 0.0;
    metrics.unreachableAreaSquareMetres = unreachable;
    metrics.repeatedFraction = subCells == 0 ? 0.0 : static_cast<double>(repeats) / static_cast<double>(subCells);
}

} // namespace mcpp
