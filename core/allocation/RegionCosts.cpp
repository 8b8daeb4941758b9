#include "core/allocation/RegionCosts.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {

std::vector<double> regionCosts(const CellGraph& graph, const std::vector<int>& robotOfCell,
                                std::size_t robots) {
    std::vector<double> costs(robots, 0.0);
    for (std::size_t cell = 0; cell < robotOfCell.size(); ++cell)
        if (robotOfCell[cell] >= 0)
            costs[static_cast<std::size_t>(robotOfCell[cell])] +=
                graph.cell(static_cast<int>(cell)).coverSeconds();
    return costs;
}

bool withinOfTheMean(const std::vector<double>& costs, double slack) {
    double total = 0.0;
    for (double cost : costs)
        total += cost;
    const double mean = total / static_cast<double>(costs.size());
    return std::all_of(costs.begin(), costs.end(),
                       [&](double cost) { return std::abs(cost - mean) <= slack; });
}

} // namespace mcpp
