#include "core/allocation/BatteryRange.hpp"

#include "core/coverage/OwnSpeeds.hpp"
#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>

namespace mcpp {

namespace {

struct Growth {
    std::vector<double> seconds; // by cell: travel from the charger that reached it (infinity: none)
    std::vector<int> reachedBy;  // by cell: that charger's robot, or -1
};

// Ways from the start cells of `robots`, all of one speed, at once through neighbouring cells (centre to
// centre), quickest first; a robot's way enters a cell only where mayEnter(robot, cell, seconds there)
// allows.
template <typename MayEnter>
Growth growFromChargers(const CellGraph& graph, const std::vector<int>& startCells,
                        const std::vector<int>& robots, const std::vector<double>& robotSpeeds,
                        MayEnter mayEnter) {
    Growth growth{std::vector<double>(graph.size(), std::numeric_limits<double>::infinity()),
                  std::vector<int>(graph.size(), -1)};
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (const int robot : robots) {
        const auto start = static_cast<std::size_t>(startCells[static_cast<std::size_t>(robot)]);
        growth.seconds[start] = 0.0;
        growth.reachedBy[start] = robot;
        queue.emplace(0.0, static_cast<int>(start));
    }
    while (!queue.empty()) {
        const auto [reached, id] = queue.top();
        queue.pop();
        if (reached != growth.seconds[static_cast<std::size_t>(id)])
            continue;
        const int robot = growth.reachedBy[static_cast<std::size_t>(id)];
        const double ownSpeed = ownSpeedOf(robotSpeeds, static_cast<std::size_t>(robot));
        const Cell& here = graph.cell(id);
        for (const int next : graph.neighbours(id)) {
            const Cell& there = graph.cell(next);
            const double seconds =
                reached +
                travelSeconds(std::hypot(there.centreX() - here.centreX(), there.centreY() - here.centreY()),
                              ownSpeed > 0.0 ? ownSpeed : here.speedMetresPerSecond,
                              ownSpeed > 0.0 ? ownSpeed : there.speedMetresPerSecond);
            const auto index = static_cast<std::size_t>(next);
            if (seconds < growth.seconds[index] && mayEnter(robot, index, seconds)) {
                growth.seconds[index] = seconds;
                growth.reachedBy[index] = robot;
                queue.emplace(seconds, next);
            }
        }
    }
    return growth;
}

// The quickest way from some charger to every cell, each robot at its own speed. Robots of one speed and
// one battery grow together; others apart, the quickest kept cell by cell: grown together, a slow robot's
// way would bar a fast one's from the land beyond it, and a short battery's a long one's.
template <typename MayEnter>
Growth growByKind(const CellGraph& graph, const std::vector<int>& startCells, const BatteryRange& range,
                  MayEnter mayEnter) {
    std::map<std::pair<double, double>, std::vector<int>> robotsByKind; // speed 0: the cells' speeds
    for (std::size_t robot = 0; robot < startCells.size(); ++robot)
        robotsByKind[{ownSpeedOf(range.robotSpeeds, robot), range.enduranceOf(robot)}].push_back(
            static_cast<int>(robot));
    Growth quickest{std::vector<double>(graph.size(), std::numeric_limits<double>::infinity()),
                    std::vector<int>(graph.size(), -1)};
    for (const auto& group : robotsByKind) {
        Growth growth = growFromChargers(graph, startCells, group.second, range.robotSpeeds, mayEnter);
        if (robotsByKind.size() == 1)
            return growth;
        for (std::size_t id = 0; id < graph.size(); ++id)
            if (growth.seconds[id] < quickest.seconds[id]) {
                quickest.seconds[id] = growth.seconds[id];
                quickest.reachedBy[id] = growth.reachedBy[id];
            }
    }
    return quickest;
}

} // namespace

std::vector<double> BatteryRange::secondsFromChargers(const CellGraph& graph,
                                                      const std::vector<int>& startCells) const {
    return growByKind(graph, startCells, *this, [](int, std::size_t, double) { return true; }).seconds;
}

BatteryRange::AllocationGraph BatteryRange::allocationGraph(const CellGraph& graph,
                                                            const std::vector<int>& startCells) const {
    const std::vector<double> seconds = secondsFromChargers(graph, startCells);
    // Ways that stop where their robot's battery runs out reach exactly the cells in range.
    const Growth inRange = growByKind(graph, startCells, *this, [&](int robot, std::size_t, double reached) {
        return withinRangeOf(static_cast<std::size_t>(robot), reached);
    });
    AllocationGraph result;
    std::vector<char> outOfRange(graph.size(), 0);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        outOfRange[id] = inRange.reachedBy[id] >= 0 ? 0 : 1;
        if (outOfRange[id] != 0 && std::isfinite(seconds[id]))
            result.outOfRange.push_back(static_cast<int>(id));
    }
    result.graph = cutOffCells(graph, outOfRange);
    return result;
}

std::vector<int> BatteryRange::handOver(const CellGraph& graph, std::vector<int>& robotOfCell,
                                        const std::vector<int>& startCells,
                                        const std::vector<int>& leftOutBy) const {
    // A robot's way keeps to its own region and the cells others left out, within its range.
    const Growth growth =
        growByKind(graph, startCells, *this, [&](int robot, std::size_t cell, double seconds) {
            const bool open = leftOutBy[cell] >= 0 && leftOutBy[cell] != robot;
            return open ? withinRangeOf(static_cast<std::size_t>(robot), seconds)
                        : robotOfCell[cell] == robot;
        });
    std::vector<int> gained;
    for (std::size_t id = 0; id < leftOutBy.size(); ++id) {
        if (leftOutBy[id] < 0 || growth.reachedBy[id] < 0)
            continue;
        robotOfCell[id] = growth.reachedBy[id];
        gained.push_back(growth.reachedBy[id]);
    }
    std::sort(gained.begin(), gained.end());
    gained.erase(std::unique(gained.begin(), gained.end()), gained.end());
    return gained;
}

CellGraph cutOffCells(const CellGraph& graph, const std::vector<char>& cutOff) {
    std::vector<int> offsets{0};
    std::vector<int> neighbours;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        if (cutOff[id] == 0)
            for (const int next : graph.neighbours(static_cast<int>(id)))
                if (cutOff[static_cast<std::size_t>(next)] == 0)
                    neighbours.push_back(next);
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    CellGraph result(graph.frame(), graph.records(),
                     NeighbourTopology(std::move(offsets), std::move(neighbours)));
    result.setTurnFigures(graph.turnFigures());
    result.fieldsOfView = graph.fieldsOfView;
    result.passableAreaSquareMetres = graph.passableAreaSquareMetres;
    return result;
}

} // namespace mcpp
