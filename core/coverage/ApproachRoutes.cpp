#include "core/coverage/ApproachRoutes.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace mcpp {
namespace {

// 0 east, 1 north, 2 west, 3 south: the main direction of a step.
int headingOf(double dx, double dy) {
    if (std::abs(dx) >= std::abs(dy))
        return dx >= 0.0 ? 0 : 2;
    return dy >= 0.0 ? 1 : 3;
}

// Quarter turns between two headings: 0, 1 or 2.
int quarterTurns(int from, int to) {
    const int difference = std::abs(from - to) % 4;
    return difference == 3 ? 1 : difference;
}

} // namespace

ApproachRoutes::ApproachRoutes(const CellGraph& graph) : offsets_{0}, turnSeconds_(graph.size()) {
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell here = graph.cell(static_cast<int>(id));
        turnSeconds_[id] = graph.turnSeconds(static_cast<int>(id));
        for (const int neighbour : graph.neighbours(static_cast<int>(id))) {
            const Cell there = graph.cell(neighbour);
            const double dx = there.centreX() - here.centreX();
            const double dy = there.centreY() - here.centreY();
            steps_.push_back({neighbour, headingOf(dx, dy),
                              static_cast<float>(travelSeconds(std::hypot(dx, dy), here.speedMetresPerSecond,
                                                               there.speedMetresPerSecond))});
        }
        offsets_.push_back(static_cast<int>(steps_.size()));
    }
}

std::vector<float> ApproachRoutes::secondsFrom(int cell) const {
    return search(cell, -1, false).secondsToCell;
}

ApproachRoutes::Tree ApproachRoutes::search(int from, int stopAt, bool turnsCount) const {
    // A hair per quarter turn where turns cost nothing: straighter among equally quick ways.
    constexpr double tieBreakSeconds = 1e-6;
    // Without turns a cell is one state, entered with no heading that counts.
    const int statesPerCell = turnsCount ? headings : 1;
    const std::size_t cells = turnSeconds_.size();
    const std::size_t states = cells * static_cast<std::size_t>(statesPerCell);
    Tree tree{std::vector<float>(cells, std::numeric_limits<float>::infinity()),
              std::vector<int>(turnsCount ? states : 0, -1), std::vector<int>(cells, -1)};
    std::vector<double> seconds(states, std::numeric_limits<double>::infinity());
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    const int first = turnsCount ? from * headings + 4 : from;
    seconds[static_cast<std::size_t>(first)] = 0.0;
    queue.push({0.0, first});
    while (!queue.empty()) {
        const auto [reached, state] = queue.top();
        queue.pop();
        if (reached > seconds[static_cast<std::size_t>(state)])
            continue;
        const int here = state / statesPerCell;
        const int heading = turnsCount ? state % headings : 4;
        if (tree.bestState[static_cast<std::size_t>(here)] < 0) { // the first time out is the soonest
            tree.bestState[static_cast<std::size_t>(here)] = state;
            tree.secondsToCell[static_cast<std::size_t>(here)] = static_cast<float>(reached);
            if (here == stopAt)
                break;
        }
        const double turn = turnSeconds_[static_cast<std::size_t>(here)] + tieBreakSeconds;
        for (int k = offsets_[static_cast<std::size_t>(here)];
             k < offsets_[static_cast<std::size_t>(here) + 1]; ++k) {
            const Step& step = steps_[static_cast<std::size_t>(k)];
            const double next =
                reached + step.seconds + (heading == 4 ? 0.0 : quarterTurns(heading, step.heading) * turn);
            const int nextState = turnsCount ? step.to * headings + step.heading : step.to;
            if (next < seconds[static_cast<std::size_t>(nextState)]) {
                seconds[static_cast<std::size_t>(nextState)] = next;
                if (turnsCount)
                    tree.cameFrom[static_cast<std::size_t>(nextState)] = state;
                queue.push({next, nextState});
            }
        }
    }
    return tree;
}

std::vector<int> ApproachRoutes::cellsBetween(int from, int to) const {
    const Tree tree = search(from, to, true);
    const int cell = to;
    std::vector<int> cells;
    for (int state = tree.bestState[static_cast<std::size_t>(cell)]; state >= 0;
         state = tree.cameFrom[static_cast<std::size_t>(state)])
        cells.push_back(state / headings);
    std::reverse(cells.begin(), cells.end());
    return cells;
}

} // namespace mcpp
