#include "core/coverage/ReturnTree.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <cmath>
#include <functional>
#include <queue>

namespace mcpp {
ReturnTree::ReturnTree(const SubCellNodes& nodes, const CellGraph& graph, const std::vector<char>& usable,
                       int root, MapPoint charger)
    : nodes_(nodes), graph_(graph), root_(root), parent_(static_cast<std::size_t>(nodes.size()), unreached),
      secondsHome_(static_cast<std::size_t>(nodes.size()), 0.0) {
    charger_ = nodes.waypoint(root);
    charger_.x = charger.x;
    charger_.y = charger.y;
    const Waypoint& rootPoint = nodes.waypoint(root);
    const double apart = std::hypot(rootPoint.x - charger.x, rootPoint.y - charger.y);
    chargerApart_ = apart > 1e-9;
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    std::vector<char> settled(parent_.size(), 0);
    parent_[static_cast<std::size_t>(root)] = atRoot;
    secondsHome_[static_cast<std::size_t>(root)] =
        chargerApart_ ? travelSeconds(apart, rootPoint.speedMetresPerSecond, rootPoint.speedMetresPerSecond)
                      : 0.0;
    open.emplace(secondsHome_[static_cast<std::size_t>(root)], root);
    while (!open.empty()) {
        const auto [seconds, node] = open.top();
        open.pop();
        if (settled[static_cast<std::size_t>(node)] != 0)
            continue;
        settled[static_cast<std::size_t>(node)] = 1;
        const Waypoint& here = nodes.waypoint(node);
        for (int side = 0; side < 4; ++side) {
            const int next = nodes.neighbour(node, side);
            if (next == SubCellNodes::none || usable[static_cast<std::size_t>(next)] == 0 ||
                settled[static_cast<std::size_t>(next)] != 0)
                continue;
            const Waypoint& there = nodes.waypoint(next);
            // The way from `next` enters `node` and turns there onto node's own way home.
            const Direction in = unitDirection(there.x, there.y, here.x, here.y);
            const double candidate = nodes.stepSeconds(next, node) + secondsHomeArriving(node, in.x, in.y);
            const auto index = static_cast<std::size_t>(next);
            if (parent_[index] == unreached || candidate < secondsHome_[index]) {
                parent_[index] = node;
                secondsHome_[index] = candidate;
                open.emplace(candidate, next);
            }
        }
    }
}

bool ReturnTree::nextPoint(int node, double& x, double& y) const {
    const int parent = parent_[static_cast<std::size_t>(node)];
    if (parent >= 0) {
        x = nodes_.waypoint(parent).x;
        y = nodes_.waypoint(parent).y;
        return true;
    }
    if (parent == atRoot && chargerApart_) {
        x = charger_.x;
        y = charger_.y;
        return true;
    }
    return false;
}

double ReturnTree::secondsHomeArriving(int node, double inX, double inY) const {
    double nextX = 0.0;
    double nextY = 0.0;
    const double home = secondsHome(node);
    if ((inX == 0.0 && inY == 0.0) || !nextPoint(node, nextX, nextY))
        return home;
    const Waypoint& here = nodes_.waypoint(node);
    const Direction out = unitDirection(here.x, here.y, nextX, nextY);
    return turnSecondsAt(here, inX, inY, out.x, out.y, graph_) + home;
}

double ReturnTree::worstTurnSeconds(int node) const {
    // At the node's speed, as the path is timed: a robot of its own speed turns at its price, not the cell's.
    const Waypoint& point = nodes_.waypoint(node);
    return 2.0 * double(graph_.turnSeconds(point.cell, point.speedMetresPerSecond));
}

double ReturnTree::worstTurnAtCharger() const {
    return charger_.cell < 0 ? 0.0
                             : 2.0 * double(graph_.turnSeconds(charger_.cell, charger_.speedMetresPerSecond));
}

std::vector<int> ReturnTree::wayHome(int node) const {
    std::vector<int> way;
    for (int at = parent_[static_cast<std::size_t>(node)]; at >= 0;
         at = parent_[static_cast<std::size_t>(at)])
        way.push_back(at);
    return way;
}

} // namespace mcpp
