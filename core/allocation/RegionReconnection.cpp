#include "core/allocation/RegionReconnection.hpp"

#include <cstdint>

namespace mcpp {

namespace {

// Marks the cells of `robot`'s region its start reaches through the region.
void markReached(const CellGraph& graph, int robot, int start, const std::vector<int>& robotOfCell,
                 std::vector<std::uint8_t>& reached, std::vector<int>& queue) {
    queue.assign(1, start);
    reached[static_cast<std::size_t>(start)] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int neighbour : graph.neighbours(queue[head])) {
            const auto at = static_cast<std::size_t>(neighbour);
            if (reached[at] == 0 && robotOfCell[at] == robot) {
                reached[at] = 1;
                queue.push_back(neighbour);
            }
        }
}

} // namespace

void reconnectRegions(const CellGraph& graph, const std::vector<int>& startCells,
                      std::vector<int>& robotOfCell) {
    std::vector<std::uint8_t> reached(graph.size(), 0);
    std::vector<int> queue;
    // Every start is its robot's before any region is searched: a start inside another region cuts it.
    for (std::size_t robot = 0; robot < startCells.size(); ++robot)
        robotOfCell[static_cast<std::size_t>(startCells[robot])] = static_cast<int>(robot);
    for (std::size_t robot = 0; robot < startCells.size(); ++robot)
        markReached(graph, static_cast<int>(robot), startCells[robot], robotOfCell, reached, queue);
    // Cells cut off from their region's start are nobody's until a region reaches them.
    queue.clear();
    for (std::size_t cell = 0; cell < graph.size(); ++cell) {
        if (reached[cell] != 0)
            continue;
        robotOfCell[cell] = -1;
        for (int neighbour : graph.neighbours(static_cast<int>(cell)))
            if (reached[static_cast<std::size_t>(neighbour)] != 0) {
                robotOfCell[cell] = robotOfCell[static_cast<std::size_t>(neighbour)];
                reached[cell] = 1;
                queue.push_back(static_cast<int>(cell));
                break;
            }
    }
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int robot = robotOfCell[static_cast<std::size_t>(queue[head])];
        for (int neighbour : graph.neighbours(queue[head])) {
            const auto at = static_cast<std::size_t>(neighbour);
            if (reached[at] == 0) {
                robotOfCell[at] = robot;
                reached[at] = 1;
                queue.push_back(neighbour);
            }
        }
    }
}

} // namespace mcpp
