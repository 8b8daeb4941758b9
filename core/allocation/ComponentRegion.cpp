#include "core/allocation/ComponentRegion.hpp"

namespace mcpp {

RegionAllocation componentRegion(const CellGraph& graph, int startCell) {
    RegionAllocation regions;
    regions.robotOfCell.assign(graph.size(), -1);
    regions.startCell = {startCell};
    std::vector<int> queue{startCell};
    regions.robotOfCell[static_cast<std::size_t>(startCell)] = 0;
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int neighbour : graph.neighbours(queue[head]))
            if (regions.robotOfCell[static_cast<std::size_t>(neighbour)] < 0) {
                regions.robotOfCell[static_cast<std::size_t>(neighbour)] = 0;
                queue.push_back(neighbour);
            }
    return regions;
}

} // namespace mcpp
