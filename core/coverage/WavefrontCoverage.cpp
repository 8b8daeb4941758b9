#include "core/coverage/WavefrontCoverage.hpp"

#include "core/coverage/PathClock.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/ReturnTree.hpp"
#include "core/coverage/SubCellNodes.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <queue>
#include <set>

namespace mcpp {
namespace {

// A sortie is planned to end this share of the battery early: sums of many steps round differently in
// the planner and in the measurement.
constexpr double rangeMargin = 1e-9;
constexpr int sideStep = 3; // the modified wavefront's weights (Zelinsky et al., as seed 002 counts them)
constexpr int diagonalStep = 4;

// Wavefront numbers from the root over the usable nodes, diagonals through a usable side neighbour.
std::vector<int> wavefrontNumbers(const SubCellNodes& nodes, const std::vector<char>& usable, int root) {
    std::vector<int> number(static_cast<std::size_t>(nodes.size()), std::numeric_limits<int>::max());
    using Entry = std::pair<int, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    const auto offer = [&](int node, int value) {
        if (node == SubCellNodes::none || usable[static_cast<std::size_t>(node)] == 0 ||
            value >= number[static_cast<std::size_t>(node)])
            return;
        number[static_cast<std::size_t>(node)] = value;
        open.emplace(value, node);
    };
    offer(root, 0);
    while (!open.empty()) {
        const auto [value, node] = open.top();
        open.pop();
        if (value != number[static_cast<std::size_t>(node)])
            continue;
        for (int side = 0; side < 4; ++side) {
            const int next = nodes.neighbour(node, side);
            offer(next, value + sideStep);
            if (next == SubCellNodes::none || usable[static_cast<std::size_t>(next)] == 0)
                continue;
            // East or west first, then north or south: each diagonal is reached through either side node.
            offer(nodes.neighbour(next, (side + 1) % 4), value + diagonalStep);
            offer(nodes.neighbour(next, (side + 3) % 4), value + diagonalStep);
        }
    }
    return number;
}

// One robot's walk over its usable nodes, in sorties.
class Walk {
  public:
    Walk(const SubCellNodes& nodes, const CellGraph& graph, const ReturnTree& tree, std::vector<char> usable,
         double enduranceSeconds, const ProgressReporter& progress)
        : nodes_(nodes), tree_(tree), usable_(std::move(usable)), endurance_(enduranceSeconds),
          progress_(progress), clock_(graph), visited_(usable_.size(), 0),
          wave_(wavefrontNumbers(nodes, usable_, tree.root())), distance_(usable_.size(), unset),
          cameFrom_(usable_.size(), SubCellNodes::none) {
        remaining_ = static_cast<int>(std::count(usable_.begin(), usable_.end(), char(1)));
    }

    // transit: the points from the start to the charger when the robot starts elsewhere; they count
    // against the first charge.
    void run(const std::vector<Waypoint>& transit, std::vector<Sortie>& sorties) {
        for (std::size_t point = 0; point + 1 < transit.size(); ++point)
            clock_.append(transit[point]);
        clock_.append(tree_.charger());
        current_ = tree_.root();
        if (tree_.chargerApart())
            step(current_);
        else
            markVisited(current_);
        for (std::size_t steps = 0; remaining_ > 0; ++steps) {
            if (steps % 4096 == 0)
                progress_.throwIfCancelled();
            const std::vector<int> route = nextRoute();
            if (route.empty())
                break;
            for (const int next : route) {
                if (!canStep(next)) {
                    charge(sorties);
                    flyOutTo(route.back());
                    break;
                }
                step(next);
            }
        }
        goHome();
        sorties.push_back({sortieFirst_, clock_.lastIndex()});
    }

    [[nodiscard]] std::vector<Waypoint> takeWaypoints() { return clock_.take(); }

  private:
    static constexpr double unset = -1.0;

    void markVisited(int node) {
        if (visited_[static_cast<std::size_t>(node)] == 0) {
            visited_[static_cast<std::size_t>(node)] = 1;
            --remaining_;
        }
    }
    void step(int node) {
        for (int side = 0; side < 4; ++side)
            if (nodes_.neighbour(current_, side) == node)
                heading_ = side;
        clock_.append(nodes_.waypoint(node));
        markVisited(node);
        current_ = node;
    }
    [[nodiscard]] bool canStep(int next) const {
        if (!std::isfinite(endurance_))
            return true;
        const Waypoint& here = clock_.waypoints().back();
        const Waypoint& there = nodes_.waypoint(next);
        const Direction way = unitDirection(here.x, here.y, there.x, there.y);
        const double needed = clock_.elapsed() - sortieStartSeconds_ + clock_.secondsToAppend(there) +
                              tree_.secondsHomeArriving(next, way.x, way.y);
        return needed <= endurance_ * (1.0 - rangeMargin);
    }
    void goHome() {
        for (const int node : tree_.wayHome(current_))
            step(node);
        if (tree_.chargerApart()) {
            clock_.append(tree_.charger());
            current_ = tree_.root();
            heading_ = -1;
        }
    }
    void charge(std::vector<Sortie>& sorties) {
        goHome();
        sorties.push_back({sortieFirst_, clock_.lastIndex()});
        sortieFirst_ = clock_.lastIndex();
        sortieStartSeconds_ = clock_.elapsed();
    }
    // From the charger along the reverse of the target's way home.
    void flyOutTo(int target) {
        std::vector<int> way = tree_.wayHome(target);
        std::reverse(way.begin(), way.end());
        way.push_back(target);
        current_ = tree_.root();
        for (const int node : way)
            if (node != tree_.root() || tree_.chargerApart())
                step(node);
    }
    // The unvisited side neighbour farthest out by wavefront number (straight on when tied), else the
    // quickest way to the nearest unvisited node.
    [[nodiscard]] std::vector<int> nextRoute() {
        int best = SubCellNodes::none;
        for (int side = 0; side < 4; ++side) {
            const int next = nodes_.neighbour(current_, side);
            if (!isOpen(next))
                continue;
            const auto value = wave_[static_cast<std::size_t>(next)];
            const auto bestValue = best == SubCellNodes::none ? -1 : wave_[static_cast<std::size_t>(best)];
            if (value > bestValue || (value == bestValue && side == heading_))
                best = next;
        }
        if (best != SubCellNodes::none)
            return {best};
        return wayToNearestUnvisited();
    }
    [[nodiscard]] bool isOpen(int node) const {
        return node != SubCellNodes::none && usable_[static_cast<std::size_t>(node)] != 0 &&
               visited_[static_cast<std::size_t>(node)] == 0;
    }
    [[nodiscard]] std::vector<int> wayToNearestUnvisited() {
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
        std::vector<std::size_t> touched;
        const auto offer = [&](int node, int from, double seconds) {
            const auto index = static_cast<std::size_t>(node);
            if (distance_[index] != unset && distance_[index] <= seconds)
                return;
            if (distance_[index] == unset)
                touched.push_back(index);
            distance_[index] = seconds;
            cameFrom_[index] = from;
            open.emplace(seconds, node);
        };
        offer(current_, SubCellNodes::none, 0.0);
        int found = SubCellNodes::none;
        while (!open.empty() && found == SubCellNodes::none) {
            const auto [seconds, node] = open.top();
            open.pop();
            if (seconds != distance_[static_cast<std::size_t>(node)])
                continue;
            if (isOpen(node)) {
                found = node;
                break;
            }
            for (int side = 0; side < 4; ++side) {
                const int next = nodes_.neighbour(node, side);
                if (next != SubCellNodes::none && usable_[static_cast<std::size_t>(next)] != 0)
                    offer(next, node, seconds + nodes_.stepSeconds(node, next));
            }
        }
        std::vector<int> route;
        for (int at = found; at != SubCellNodes::none && at != current_;
             at = cameFrom_[static_cast<std::size_t>(at)])
            route.push_back(at);
        std::reverse(route.begin(), route.end());
        for (const std::size_t index : touched)
            distance_[index] = unset;
        return route;
    }

    const SubCellNodes& nodes_;
    const ReturnTree& tree_;
    std::vector<char> usable_;
    double endurance_;
    const ProgressReporter& progress_;
    PathClock clock_;
    std::vector<char> visited_;
    std::vector<int> wave_;
    std::vector<double> distance_; // scratch for wayToNearestUnvisited
    std::vector<int> cameFrom_;
    int remaining_ = 0;
    int current_ = SubCellNodes::none;
    int heading_ = -1; // side of the last step, -1 before any
    std::size_t sortieFirst_ = 0;
    double sortieStartSeconds_ = 0.0;
};

// Whether a robot can fly out to the node, turn any way there and come home on one charge.
bool withinRange(const ReturnTree& tree, int node, double enduranceSeconds) {
    const double roundTrip =
        tree.worstTurnAtCharger() + 2.0 * tree.secondsHome(node) + tree.worstTurnSeconds(node);
    return roundTrip <= enduranceSeconds * (1.0 - rangeMargin);
}

// The cells out of range with the tree over the usable nodes: unreached, or too far to fly out to, turn
// any way and come back on one charge.
std::set<int> cellsOutOfRange(const SubCellNodes& nodes, const ReturnTree& tree,
                              const std::vector<char>& usable, double enduranceSeconds) {
    std::set<int> outOfRange;
    for (int node = 0; node < nodes.size(); ++node)
        if (usable[static_cast<std::size_t>(node)] != 0 &&
            (!tree.reaches(node) || !withinRange(tree, node, enduranceSeconds)))
            outOfRange.insert(nodes.waypoint(node).cell);
    return outOfRange;
}

} // namespace

PlanningError WavefrontCoverage::batteryTooShort(int robot) const {
    const std::string detail = " to cover the cell of its charger and return to it";
    if (!battery_.ownBattery)
        return PlanningError::aboutParameter("battery_s", formatDuration(battery_.enduranceSeconds) +
                                                              " is too short for robot " +
                                                              std::to_string(robot + 1) + detail);
    return PlanningError(PlanningError::Kind::InvalidParameter,
                         "robot " + std::to_string(robot + 1) + "'s own battery (" +
                             formatDuration(battery_.enduranceSeconds) + ") is too short" + detail +
                             ": give it a longer battery_s, or its vehicle a longer flight time");
}

std::unique_ptr<ReturnTree> WavefrontCoverage::treeWithinRange(const SubCellNodes& nodes, int root, int robot,
                                                               int chargerCell, MapPoint charger,
                                                               std::vector<char>& usable,
                                                               RobotSorties& sorties,
                                                               const ProgressReporter& progress) const {
    // Leaving cells out lengthens other ways home, so repeat until every cell left is within range.
    while (true) {
        progress.throwIfCancelled();
        auto tree = std::make_unique<ReturnTree>(nodes, graph_, usable, root, charger);
        const std::set<int> outOfRange = cellsOutOfRange(nodes, *tree, usable, battery_.enduranceSeconds);
        if (outOfRange.empty())
            return tree;
        if (outOfRange.count(chargerCell) != 0)
            throw batteryTooShort(robot);
        for (const int cell : outOfRange) {
            for (const int node : nodes.ofCell(cell))
                usable[static_cast<std::size_t>(node)] = 0;
            sorties.outOfRangeCells.push_back(cell);
            sorties.outOfRangeAreaSquareMetres += graph_.cell(cell).passableAreaSquareMetres;
        }
    }
}

WavefrontCoverage::Result WavefrontCoverage::cover(int robot, const std::vector<int>& cells, int chargerCell,
                                                   MapPoint charger, const std::vector<Waypoint>& transit,
                                                   const ProgressReporter& progress) const {
    const SubCellNodes nodes(graph_, cells, ownSpeed_);
    const int root = nodes.startNode(robot, chargerCell, charger);
    Result result;
    result.sorties.robot = robot;
    result.sorties.charger = charger;
    result.sorties.enduranceSeconds = battery_.enduranceSeconds;
    result.sorties.rechargeSeconds = battery_.rechargeSeconds;
    std::vector<char> usable(static_cast<std::size_t>(nodes.size()), 1);
    const auto tree =
        treeWithinRange(nodes, root, robot, chargerCell, charger, usable, result.sorties, progress);
    std::sort(result.sorties.outOfRangeCells.begin(), result.sorties.outOfRangeCells.end());
    Walk walk(nodes, graph_, *tree, std::move(usable), battery_.enduranceSeconds, progress);
    walk.run(transit, result.sorties.sorties);
    result.path.robot = robot;
    result.path.closed = transit.empty(); // a robot that started elsewhere ends at its charger
    result.path.waypoints = walk.takeWaypoints();
    // A charge at the end of every sortie but the last.
    for (std::size_t sortie = 0; sortie + 1 < result.sorties.sorties.size(); ++sortie)
        result.path.pauses.push_back({result.sorties.sorties[sortie].lastWaypoint, battery_.rechargeSeconds});
    return result;
}

} // namespace mcpp
