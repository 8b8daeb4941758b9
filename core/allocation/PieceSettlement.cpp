#include "core/allocation/PieceSettlement.hpp"

#include "core/allocation/BorderExchange.hpp"
#include "core/allocation/RegionCosts.hpp"
#include "core/allocation/StartComponents.hpp"
#include "core/coverage/CellIndexScope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace mcpp {
namespace {

// Whether every region is within `slack` of the mean of `robots`' costs.
bool within(const RegionAllocation& regions, const std::vector<int>& robots, double slack) {
    std::vector<double> costs;
    costs.reserve(robots.size());
    for (int robot : robots)
        costs.push_back(regions.costSeconds[static_cast<std::size_t>(robot)]);
    return withinOfTheMean(costs, slack);
}

} // namespace

void settleRegionsWithPieces(const CellGraph& graph, RegionAllocation& regions,
                             const ProgressReporter& progress) {
    // Most allocations are settled already: then the parts of the map need not be found.
    double largestCell = 0.0;
    for (std::size_t cell = 0; cell < graph.size(); ++cell)
        largestCell = std::max(largestCell, graph.cell(static_cast<int>(cell)).coverSeconds());
    std::vector<int> everyRobot(regions.startCell.size());
    std::iota(everyRobot.begin(), everyRobot.end(), 0);
    if (everyRobot.size() < 2 || within(regions, everyRobot, largestCell))
        return;
    std::vector<int> scratch(graph.size(), -1);
    for (const StartComponent& part : componentsWithStarts(graph, regions.startCell)) {
        if (part.robots.size() < 2)
            continue;
        if (within(regions, part.robots, largestCell))
            continue;
        const CellIndexScope local(scratch, part.cells);
        std::vector<int> regionOfRobot(regions.startCell.size(), -1);
        std::vector<int> starts;
        for (std::size_t index = 0; index < part.robots.size(); ++index) {
            regionOfRobot[static_cast<std::size_t>(part.robots[index])] = static_cast<int>(index);
            starts.push_back(local[regions.startCell[static_cast<std::size_t>(part.robots[index])]]);
        }
        std::vector<double> weights;
        std::vector<int> owner;
        for (int cell : part.cells) {
            weights.push_back(graph.cell(cell).coverSeconds());
            owner.push_back(
                regionOfRobot[static_cast<std::size_t>(regions.robotOfCell[static_cast<std::size_t>(cell)])]);
        }
        BorderExchange exchange(graph, part.cells, local, std::move(weights), starts,
                                [](int, int, int) { return std::int64_t{0}; });
        exchange.balance(owner, largestCell, progress);
        for (std::size_t i = 0; i < part.cells.size(); ++i) {
            const int robot = part.robots[static_cast<std::size_t>(owner[i])];
            regions.robotOfCell[static_cast<std::size_t>(part.cells[i])] = robot;
        }
    }
    regions.costSeconds = regionCosts(graph, regions.robotOfCell, regions.costSeconds.size());
}

} // namespace mcpp
