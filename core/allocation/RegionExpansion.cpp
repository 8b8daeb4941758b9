#include "core/allocation/RegionExpansion.hpp"

#include <deque>
#include <functional>
#include <queue>
#include <utility>

namespace mcpp {

std::vector<int> expandRegions(const CellGraph& graph, const std::vector<int>& startCells) {
    std::vector<int> owner(graph.size(), -1);
    std::vector<std::deque<int>> frontier(startCells.size());
    // (cover time so far, robot): the region with the least claims next.
    using Turn = std::pair<double, int>;
    std::priority_queue<Turn, std::vector<Turn>, std::greater<>> turns;
    for (std::size_t robot = 0; robot < startCells.size(); ++robot) {
        const int cell = startCells[robot];
        owner[static_cast<std::size_t>(cell)] = static_cast<int>(robot);
        const NeighbourList around = graph.neighbours(cell);
        frontier[robot].assign(around.begin(), around.end());
        turns.emplace(graph.cell(cell).coverSeconds(), static_cast<int>(robot));
    }
    while (!turns.empty()) {
        const auto [seconds, robot] = turns.top();
        turns.pop();
        std::deque<int>& next = frontier[static_cast<std::size_t>(robot)];
        while (!next.empty() && owner[static_cast<std::size_t>(next.front())] >= 0)
            next.pop_front();
        if (next.empty())
            continue; // hemmed in: its turn passes for good
        const int cell = next.front();
        next.pop_front();
        owner[static_cast<std::size_t>(cell)] = robot;
        for (const int neighbour : graph.neighbours(cell))
            if (owner[static_cast<std::size_t>(neighbour)] < 0)
                next.push_back(neighbour);
        turns.emplace(seconds + graph.cell(cell).coverSeconds(), robot);
    }
    return owner;
}

} // namespace mcpp
