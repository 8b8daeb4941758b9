#include "core/allocation/StartComponents.hpp"

namespace mcpp {

std::vector<StartComponent> componentsWithStarts(const CellGraph& graph, const std::vector<int>& startCells) {
    std::vector<int> componentOf(graph.size(), -1);
    std::vector<StartComponent> components;
    for (std::size_t robot = 0; robot < startCells.size(); ++robot) {
        const auto start = static_cast<std::size_t>(startCells[robot]);
        if (componentOf[start] < 0) {
            const int index = static_cast<int>(components.size());
            StartComponent component;
            component.cells.push_back(startCells[robot]);
            componentOf[start] = index;
            for (std::size_t head = 0; head < component.cells.size(); ++head)
                for (int neighbour : graph.neighbours(component.cells[head]))
                    if (componentOf[static_cast<std::size_t>(neighbour)] < 0) {
                        componentOf[static_cast<std::size_t>(neighbour)] = index;
                        component.cells.push_back(neighbour);
                    }
            components.push_back(std::move(component));
        }
        components[static_cast<std::size_t>(componentOf[start])].robots.push_back(static_cast<int>(robot));
    }
    return components;
}

} // namespace mcpp
