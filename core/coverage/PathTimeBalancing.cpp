#include "core/coverage/PathTimeBalancing.hpp"

#include <algorithm>

namespace mcpp {
namespace {

// Whether the region stays in one piece without the cell (a full search: regions here are small).
bool connectedWithout(const CellGraph& graph, const std::vector<int>& owner, int cell, std::size_t size) {
    const int region = owner[static_cast<std::size_t>(cell)];
    int first = -1;
    for (int neighbour : graph.neighbours(cell))
        if (owner[static_cast<std::size_t>(neighbour)] == region) {
            first = neighbour;
            break;
        }
    if (first < 0)
        return false;
    std::vector<int> queue{first};
    std::vector<char> seen(owner.size(), 0);
    seen[static_cast<std::size_t>(first)] = 1;
    seen[static_cast<std::size_t>(cell)] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int next : graph.neighbours(queue[head]))
            if (owner[static_cast<std::size_t>(next)] == region &&
                seen[static_cast<std::size_t>(next)] == 0) {
                seen[static_cast<std::size_t>(next)] = 1;
                queue.push_back(next);
            }
    return queue.size() + 1 == size;
}

// Moves tried for one longest path before giving up: when the likeliest fail, the rest seldom help.
constexpr int trialsPerStep = 32;

// Within 0.2 % of the mean path time: what is left would cost more planning than it saves.
bool balanced(const std::vector<CoveragePath>& paths) {
    double longest = 0.0;
    double total = 0.0;
    for (const CoveragePath& path : paths) {
        longest = std::max(longest, path.timeSeconds);
        total += path.timeSeconds;
    }
    return paths.empty() || longest <= 1.002 * total / static_cast<double>(paths.size());
}

} // namespace

int PathTimeBalancing::balance(const CellGraph& graph, RegionAllocation& regions,
                               std::vector<CoveragePath>& paths, const std::vector<MapPoint>& starts,
                               const ProgressReporter& progress) const {
    std::vector<std::vector<int>> cells = cellsByRobot(regions);
    std::vector<int>& owner = regions.robotOfCell;
    std::vector<int> scratchIndex(graph.size(), -1);
    const auto replan = [&](std::size_t robot) {
        return coverage_.regionPath(graph, cells[robot], regions.startCell[robot], static_cast<int>(robot),
                                    starts[robot], scratchIndex);
    };
    std::size_t spent = 0;
    int moved = 0;
    while (spent < cellBudget_ && !balanced(paths)) {
        progress.throwIfCancelled();
        const auto longest =
            static_cast<std::size_t>(std::max_element(paths.begin(), paths.end(),
                                                      [](const CoveragePath& a, const CoveragePath& b) {
                                                          return a.timeSeconds < b.timeSeconds;
                                                      }) -
                                     paths.begin());
        const double makespan = paths[longest].timeSeconds;
        // Border cells of the longest region, with the neighbouring region each could go to, shortest first.
        std::vector<std::pair<double, std::pair<int, int>>> offers;
        for (int cell : cells[longest]) {
            if (cell == regions.startCell[longest])
                continue;
            for (int neighbour : graph.neighbours(cell)) {
                const int other = owner[static_cast<std::size_t>(neighbour)];
                if (other >= 0 && static_cast<std::size_t>(other) != longest &&
                    paths[static_cast<std::size_t>(other)].timeSeconds < makespan)
                    offers.push_back({paths[static_cast<std::size_t>(other)].timeSeconds, {cell, other}});
            }
        }
        std::sort(offers.begin(), offers.end());
        offers.erase(std::unique(offers.begin(), offers.end()), offers.end());
        bool improved = false;
        int trials = 0;
        for (const auto& [time, offer] : offers) {
            const auto [cell, other] = offer;
            const auto receiver = static_cast<std::size_t>(other);
            if (spent >= cellBudget_ || trials == trialsPerStep)
                break;
            if (!connectedWithout(graph, owner, cell, cells[longest].size()))
                continue;
            auto& giverCells = cells[longest];
            auto& takerCells = cells[receiver];
            giverCells.erase(std::find(giverCells.begin(), giverCells.end(), cell));
            takerCells.insert(std::lower_bound(takerCells.begin(), takerCells.end(), cell), cell);
            owner[static_cast<std::size_t>(cell)] = other;
            ++trials;
            CoveragePath giverPath = replan(longest);
            CoveragePath takerPath = replan(receiver);
            spent += giverCells.size() + takerCells.size();
            if (std::max(giverPath.timeSeconds, takerPath.timeSeconds) < makespan - 1e-9) {
                const double cellCost = graph.cell(cell).coverSeconds();
                regions.costSeconds[longest] -= cellCost;
                regions.costSeconds[receiver] += cellCost;
                paths[longest] = std::move(giverPath);
                paths[receiver] = std::move(takerPath);
                ++moved;
                improved = true;
                break;
            }
            owner[static_cast<std::size_t>(cell)] = static_cast<int>(longest);
            takerCells.erase(std::lower_bound(takerCells.begin(), takerCells.end(), cell));
            giverCells.insert(std::lower_bound(giverCells.begin(), giverCells.end(), cell), cell);
        }
        if (!improved)
            break;
    }
    return moved;
}

} // namespace mcpp
