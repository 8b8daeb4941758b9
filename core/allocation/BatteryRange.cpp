#include "core/allocation/BatteryRange.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace mcpp {

std::vector<double> BatteryRange::secondsFromChargers(const CellGraph& graph,
                                                      const std::vector<int>& startCells) {
    std::vector<double> seconds(graph.size(), std::numeric_limits<double>::infinity());
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    for (const int start : startCells) {
        seconds[static_cast<std::size_t>(start)] = 0.0;
        open.emplace(0.0, start);
    }
    while (!open.empty()) {
        const auto [reached, id] = open.top();
        open.pop();
        if (reached != seconds[static_cast<std::size_t>(id)])
            continue;
        const Cell& here = graph.cell(id);
        for (const int next : graph.neighbours(id)) {
            const Cell& there = graph.cell(next);
            const double step =
                travelSeconds(std::hypot(there.centreX() - here.centreX(), there.centreY() - here.centreY()),
                              here.speedMetresPerSecond, there.speedMetresPerSecond);
            if (reached + step < seconds[static_cast<std::size_t>(next)]) {
                seconds[static_cast<std::size_t>(next)] = reached + step;
                open.emplace(reached + step, next);
            }
        }
    }
    return seconds;
}

BatteryRange::AllocationGraph BatteryRange::allocationGraph(const CellGraph& graph,
                                                            const std::vector<int>& startCells) const {
    const std::vector<double> seconds = secondsFromChargers(graph, startCells);
    AllocationGraph result;
    std::vector<char> inRange(graph.size(), 0);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        inRange[id] = withinRange(seconds[id]) ? 1 : 0;
        if (inRange[id] == 0 && std::isfinite(seconds[id]))
            result.outOfRange.push_back(static_cast<int>(id));
    }
    std::vector<int> offsets{0};
    std::vector<int> neighbours;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        if (inRange[id] != 0)
            for (const int next : graph.neighbours(static_cast<int>(id)))
                if (inRange[static_cast<std::size_t>(next)] != 0)
                    neighbours.push_back(next);
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    result.graph =
        CellGraph(graph.frame(), graph.cells(), NeighbourTopology(std::move(offsets), std::move(neighbours)));
    result.graph.fieldsOfView = graph.fieldsOfView;
    result.graph.passableAreaSquareMetres = graph.passableAreaSquareMetres;
    return result;
}

std::vector<int> BatteryRange::handOver(const CellGraph& graph, std::vector<int>& robotOfCell,
                                        const std::vector<int>& startCells,
                                        const std::vector<int>& leftOutBy) const {
    std::vector<double> seconds(graph.size(), std::numeric_limits<double>::infinity());
    std::vector<int> reachedBy(graph.size(), -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t robot = 0; robot < startCells.size(); ++robot) {
        seconds[static_cast<std::size_t>(startCells[robot])] = 0.0;
        reachedBy[static_cast<std::size_t>(startCells[robot])] = static_cast<int>(robot);
        queue.emplace(0.0, startCells[robot]);
    }
    while (!queue.empty()) {
        const auto [reached, id] = queue.top();
        queue.pop();
        if (reached != seconds[static_cast<std::size_t>(id)])
            continue;
        const int robot = reachedBy[static_cast<std::size_t>(id)];
        const Cell& here = graph.cell(id);
        for (const int next : graph.neighbours(id)) {
            const auto index = static_cast<std::size_t>(next);
            const bool open = leftOutBy[index] >= 0 && leftOutBy[index] != robot;
            if (robotOfCell[index] != robot && !open)
                continue; // another robot's region, a cell nobody may take, or one this robot cannot reach
            const Cell& there = graph.cell(next);
            const double step =
                travelSeconds(std::hypot(there.centreX() - here.centreX(), there.centreY() - here.centreY()),
                              here.speedMetresPerSecond, there.speedMetresPerSecond);
            if (reached + step < seconds[index] && (!open || withinRange(reached + step))) {
                seconds[index] = reached + step;
                reachedBy[index] = robot;
                queue.emplace(reached + step, next);
            }
        }
    }
    std::vector<int> gained;
    for (std::size_t id = 0; id < leftOutBy.size(); ++id) {
        if (leftOutBy[id] < 0 || reachedBy[id] < 0)
            continue;
        robotOfCell[id] = reachedBy[id];
        gained.push_back(reachedBy[id]);
    }
    std::sort(gained.begin(), gained.end());
    gained.erase(std::unique(gained.begin(), gained.end()), gained.end());
    return gained;
}

} // namespace mcpp
