#include "core/allocation/OwnFlightReach.hpp"

#include "core/allocation/RegionCosts.hpp"
#include "core/allocation/RegionReconnection.hpp"
#include "core/model/LocalConnectivity.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <utility>

namespace mcpp {
namespace {

// The cells of regions beyond their robots' reach: by cell, whether it waits for another robot.
std::vector<char> beyondOwnReach(const OwnFlightReach& reach, const CellGraph& graph,
                                 const RegionAllocation& regions) {
    std::vector<char> waiting(graph.size(), 0);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const int robot = regions.robotOfCell[id];
        if (robot >= 0 && static_cast<int>(id) != regions.startCell[static_cast<std::size_t>(robot)] &&
            !reach.reaches(static_cast<std::size_t>(robot), graph.cell(static_cast<int>(id))))
            waiting[id] = 1;
    }
    return waiting;
}

} // namespace

OwnFlightReach::OwnFlightReach(std::vector<MapPoint> launchPoints, const std::vector<FlightLimits>& flights)
    : launchPoints_(std::move(launchPoints)) {
    for (std::size_t robot = 0; robot < launchPoints_.size(); ++robot) {
        const double reach = robot < flights.size() ? flights[robot].workingReachMetres()
                                                    : std::numeric_limits<double>::infinity();
        // A reach too short to work anywhere keeps the robot to its start cell.
        reachMetres_.push_back(std::isnan(reach) ? std::numeric_limits<double>::infinity()
                                                 : std::max(reach, 0.0));
        limits_ = limits_ || std::isfinite(reachMetres_.back());
    }
}

bool OwnFlightReach::reaches(std::size_t robot, const Cell& cell) const {
    if (robot >= reachMetres_.size() || !std::isfinite(reachMetres_[robot]))
        return true;
    const MapPoint& launch = launchPoints_[robot];
    const double reachSquared = reachMetres_[robot] * reachMetres_[robot];
    const auto within = [&](const MapPoint& point) {
        const double east = point.x - launch.x;
        const double north = point.y - launch.y;
        return east * east + north * north <= reachSquared;
    };
    if (cell.freeSubCellCount() == 0)
        return within({cell.centreX(), cell.centreY()});
    for (const SubCell subCell : subCellsCounterClockwise)
        if (cell.isFree(subCell) && !within(cell.subCellCentre(subCell)))
            return false;
    return true;
}

int OwnFlightReach::handOver(const CellGraph& graph, RegionAllocation& regions) const {
    if (!limits_ || regions.robotOfCell.size() != graph.size())
        return 0;
    // Pieces a region loses its way to join the neighbour that reaches them first, in reach or not: a few
    // rounds hand on what that leaves beyond its new robot's reach.
    constexpr int rounds = 3;
    int handed = 0;
    for (int round = 0; round < rounds; ++round) {
        const int handedInRound = handOverOnce(graph, regions);
        handed += handedInRound;
        if (handedInRound == 0)
            break;
    }
    if (handed > 0) {
        regions.costSeconds = regionCosts(graph, regions.robotOfCell, regions.startCell.size());
        topUp(graph, regions);
    }
    return handed;
}

int OwnFlightReach::handOverOnce(const CellGraph& graph, RegionAllocation& regions) const {
    const std::vector<char> waiting = beyondOwnReach(*this, graph, regions);
    std::vector<int> taker(graph.size(), -1);
    // Grown from the regions' own cells within reach into the waiting cells, one step at a time.
    std::deque<std::pair<int, int>> queue; // cell, robot
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const int robot = regions.robotOfCell[id];
        if (waiting[id] != 0 || robot < 0)
            continue;
        for (const int next : graph.neighbours(static_cast<int>(id)))
            if (waiting[static_cast<std::size_t>(next)] != 0 &&
                regions.robotOfCell[static_cast<std::size_t>(next)] != robot &&
                reaches(static_cast<std::size_t>(robot), graph.cell(next)))
                queue.emplace_back(next, robot);
    }
    int handed = 0;
    while (!queue.empty()) {
        const auto [cell, robot] = queue.front();
        queue.pop_front();
        if (taker[static_cast<std::size_t>(cell)] >= 0)
            continue;
        taker[static_cast<std::size_t>(cell)] = robot;
        ++handed;
        for (const int next : graph.neighbours(cell))
            if (waiting[static_cast<std::size_t>(next)] != 0 && taker[static_cast<std::size_t>(next)] < 0 &&
                reaches(static_cast<std::size_t>(robot), graph.cell(next)))
                queue.emplace_back(next, robot);
    }
    if (handed == 0)
        return 0;
    for (std::size_t id = 0; id < graph.size(); ++id)
        if (taker[id] >= 0)
            regions.robotOfCell[id] = taker[id];
    // A region whose far cells went may fall apart where they joined it: its pieces cut off from its start
    // join a neighbour.
    reconnectRegions(graph, regions.startCell, regions.robotOfCell);
    return handed;
}

int OwnFlightReach::topUp(const CellGraph& graph, RegionAllocation& regions) const {
    // A robot that cannot reach the fair share (its reach ends first) takes no part in the next: the others'
    // share rises, and the few passes it takes end when no cell moves.
    constexpr int passes = 4;
    const std::size_t robots = regions.startCell.size();
    std::vector<char> capped(robots, 0);
    LocalConnectivity connectivity(graph);
    int taken = 0;
    for (int pass = 0; pass < passes; ++pass) {
        double cost = 0.0;
        double inversePaces = 0.0;
        for (std::size_t robot = 0; robot < robots; ++robot)
            if (capped[robot] == 0) {
                cost += regions.costSeconds[robot];
                inversePaces += 1.0 / paceOf(robot);
            }
        // The paced cost every robot not capped would have were their cells shared evenly.
        const double fair = inversePaces > 0.0 ? cost / inversePaces : 0.0;
        std::vector<std::size_t> order(robots);
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return pacedCost(regions, a) < pacedCost(regions, b);
        });
        int takenInPass = 0;
        for (const std::size_t taker : order) {
            if (capped[taker] != 0 || !(pacedCost(regions, taker) < fair))
                continue;
            takenInPass += takeWithinReach(graph, regions, taker, fair, connectivity);
            capped[taker] = pacedCost(regions, taker) < fair ? 1 : 0;
        }
        taken += takenInPass;
        if (takenInPass == 0)
            break;
    }
    return taken;
}

int OwnFlightReach::takeWithinReach(const CellGraph& graph, RegionAllocation& regions, std::size_t taker,
                                    double fair, LocalConnectivity& connectivity) const {
    // Cells a connectivity check may visit: a giver's cell whose neighbours do not meet again nearby stays.
    constexpr std::size_t searchLimit = 256;
    std::vector<int>& owner = regions.robotOfCell;
    const int me = static_cast<int>(taker);
    std::deque<int> frontier; // its cells beside another robot's, then those it takes
    for (std::size_t id = 0; id < graph.size(); ++id)
        if (owner[id] == me) {
            const auto neighbours = graph.neighbours(static_cast<int>(id));
            if (std::any_of(neighbours.begin(), neighbours.end(), [&](int next) {
                    const int other = owner[static_cast<std::size_t>(next)];
                    return other >= 0 && other != me;
                }))
                frontier.push_back(static_cast<int>(id));
        }
    int taken = 0;
    while (!frontier.empty() && pacedCost(regions, taker) < fair) {
        const int from = frontier.front();
        frontier.pop_front();
        for (const int cell : graph.neighbours(from)) {
            const int giver = owner[static_cast<std::size_t>(cell)];
            if (giver < 0 || giver == me || cell == regions.startCell[static_cast<std::size_t>(giver)])
                continue;
            const auto donor = static_cast<std::size_t>(giver);
            const double cost = graph.cell(cell).coverSeconds();
            if (pacedCost(regions, donor) - cost * paceOf(donor) < fair ||
                !reaches(taker, graph.cell(cell)) || !connectivity.canRemove(cell, owner, searchLimit))
                continue;
            owner[static_cast<std::size_t>(cell)] = me;
            regions.costSeconds[donor] -= cost;
            regions.costSeconds[taker] += cost;
            frontier.push_back(cell);
            ++taken;
            if (!(pacedCost(regions, taker) < fair))
                break;
        }
    }
    return taken;
}

} // namespace mcpp
