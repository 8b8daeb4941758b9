#include "core/allocation/StartComponents.hpp"

#include <algorithm>

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

bool regionsLinkEveryRobot(const CellGraph& graph, const RegionAllocation& regions) {
    const std::vector<int>& owner = regions.robotOfCell;
    const std::size_t robots = regions.startCell.size();
    if (owner.size() != graph.size())
        return false;
    std::vector<std::size_t> group(robots); // union-find over robots
    for (std::size_t robot = 0; robot < robots; ++robot)
        group[robot] = robot;
    const auto root = [&](std::size_t robot) {
        while (group[robot] != robot)
            robot = group[robot] = group[group[robot]];
        return robot;
    };
    std::size_t groups = robots;
    for (std::size_t cell = 0; cell < owner.size() && groups > 1; ++cell) {
        const int here = owner[cell];
        if (here < 0 || static_cast<std::size_t>(here) >= robots)
            continue;
        for (const int neighbour : graph.neighbours(static_cast<int>(cell))) {
            const int there = owner[static_cast<std::size_t>(neighbour)];
            if (there < 0 || there == here || static_cast<std::size_t>(there) >= robots)
                continue;
            const std::size_t a = root(static_cast<std::size_t>(here));
            const std::size_t b = root(static_cast<std::size_t>(there));
            if (a != b) {
                group[std::max(a, b)] = std::min(a, b);
                --groups;
            }
        }
    }
    return groups <= 1;
}

} // namespace mcpp
