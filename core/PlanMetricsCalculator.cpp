#include "core/PlanMetricsCalculator.hpp"

#include "core/RegionAllocator.hpp"

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
    std::size_t visits = 0;
    std::size_t distinct = 0;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        RobotMetrics& robotMetrics = metrics.robots[robot];
        robotMetrics.robot = static_cast<int>(robot);
        if (robot < plan.paths.size()) {
            const CoveragePath& path = plan.paths[robot];
            robotMetrics.lengthMetres = path.lengthMetres;
            robotMetrics.timeSeconds = path.timeSeconds;
            robotMetrics.turns = path.turns;
            std::vector<std::pair<long long, long long>> keys;
            const std::size_t last = path.closed && path.waypoints.size() > 1 ? path.waypoints.size() - 1 : path.waypoints.size();
            for (std::size_t i = 0; i < last; ++i) {
                const Waypoint& waypoint = path.waypoints[i];
                // Keys on a grid far finer than any sub-cell, so equal centres compare equal.
                const double step = waypoint.fieldOfViewMetres / 64.0;
                keys.emplace_back(std::llround(waypoint.x / step), std::llround(waypoint.y / step));
            }
            std::sort(keys.begin(), keys.end());
            visits += keys.size();
            distinct += static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
        }
        metrics.makespanSeconds = std::max(metrics.makespanSeconds, robotMetrics.timeSeconds);
    }
    metrics.lowerBoundSeconds = robots == 0 ? 0.0 : totalCost / static_cast<double>(robots);
    metrics.ratio = metrics.lowerBoundSeconds > 0.0 ? metrics.makespanSeconds / metrics.lowerBoundSeconds : 0.0;
    metrics.passableAreaSquareMetres = tree.passableAreaSquareMetres;
    metrics.coveredAreaSquareMetres = covered;
    metrics.coveredFraction = tree.passableAreaSquareMetres > 0.0 ? covered / tree.passableAreaSquareMetres : 0.0;
    metrics.unreachableAreaSquareMetres = unreachable;
    // A start point off the sub-cell grid adds one visit that is not a sub-cell: do not count it as repeated.
    metrics.repeatedFraction = subCells == 0 ? 0.0
                                             : static_cast<double>(visits - std::min(visits, distinct)) / static_cast<double>(subCells);
}

} // namespace mcpp
