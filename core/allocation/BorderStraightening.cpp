#include "core/allocation/BorderStraightening.hpp"

#include <algorithm>

namespace mcpp {
namespace {

constexpr std::size_t east = 0;
constexpr std::size_t north = 1;
constexpr std::size_t west = 2;
constexpr std::size_t south = 3;

// Cells a connectivity check may visit: regions are checked near the moved cell only.
constexpr std::size_t searchLimit = 256;
// Passes over the cells; later passes move few (on the benchmark grids the third moves under 5 %).
constexpr int passLimit = 8;

} // namespace

ParameterSpec BorderStraightening::slackParameter() {
    return realParameter("fewer_turns_slack", "Balance traded for turns", 0.2, 0.0, 10.0,
                         "How much longer than the most loaded robot's time (in percent) a region may grow "
                         "when a border cell changes hands so that borders cut fewer straight runs: more "
                         "means fewer turns and a less even split, 0 keeps the split as it was",
                         "%");
}

BorderStraightening::BorderStraightening(const CellGraph& graph, double slack)
    : graph_(graph), slack_(slack) {}

// The neighbour of equal size in line with the cell on that side, -1 if there is none.
int BorderStraightening::straightNeighbour(int cell, std::size_t side) const {
    const Cell& self = graph_.cell(static_cast<std::size_t>(cell));
    for (int neighbour : graph_.neighbours(cell)) {
        const Cell& other = graph_.cell(static_cast<std::size_t>(neighbour));
        if (other.span != self.span)
            continue;
        if (other.row == self.row && (side == east || side == west) &&
            (other.column > self.column) == (side == east))
            return neighbour;
        if (other.column == self.column && (side == north || side == south) &&
            (other.row < self.row) == (side == north))
            return neighbour;
    }
    return -1;
}

bool BorderStraightening::blocksRuns(int cell, const std::vector<int>& owner) const {
    const int region = owner[static_cast<std::size_t>(cell)];
    if (region < 0)
        return false;
    auto inRegion = [&](std::size_t side) {
        const int neighbour = straightNeighbour(cell, side);
        return neighbour >= 0 && owner[static_cast<std::size_t>(neighbour)] == region;
    };
    return !((inRegion(east) && inRegion(west)) || (inRegion(north) && inRegion(south)));
}

int BorderStraightening::blockedAround(int cell, const std::vector<int>& owner) const {
    int count = blocksRuns(cell, owner) ? 1 : 0;
    for (int neighbour : graph_.neighbours(cell))
        if (blocksRuns(neighbour, owner))
            ++count;
    return count;
}

// Whether the cell's region neighbours still reach each other without it, searching near it only.
bool BorderStraightening::staysConnectedWithout(int cell, const std::vector<int>& owner) const {
    const int region = owner[static_cast<std::size_t>(cell)];
    std::vector<int> targets;
    for (int neighbour : graph_.neighbours(cell))
        if (owner[static_cast<std::size_t>(neighbour)] == region)
            targets.push_back(neighbour);
    if (targets.size() <= 1)
        return !targets.empty();
    std::vector<int> seen{cell, targets.front()};
    std::size_t found = 1;
    for (std::size_t head = 1; head < seen.size() && seen.size() < searchLimit; ++head)
        for (int next : graph_.neighbours(seen[head])) {
            if (owner[static_cast<std::size_t>(next)] != region ||
                std::find(seen.begin(), seen.end(), next) != seen.end())
                continue;
            seen.push_back(next);
            if (std::find(targets.begin(), targets.end(), next) != targets.end() && ++found == targets.size())
                return true;
        }
    return false;
}

// Tries the cell in each neighbouring region, restoring its owner after each trial.
int BorderStraightening::bestMove(int cell, std::vector<int>& owner, const std::vector<double>& cost,
                                  double ceiling) const {
    const int from = owner[static_cast<std::size_t>(cell)];
    const double cellCost = graph_.cell(static_cast<std::size_t>(cell)).coverSeconds();
    int before = -1; // counted when a first region could take the cell: most cells are inside theirs
    int best = -1;
    int bestChange = 0;
    for (int neighbour : graph_.neighbours(cell)) {
        const int to = owner[static_cast<std::size_t>(neighbour)];
        if (to < 0 || to == from || to == best || cost[static_cast<std::size_t>(to)] + cellCost > ceiling)
            continue;
        if (before < 0)
            before = blockedAround(cell, owner);
        owner[static_cast<std::size_t>(cell)] = to;
        const int change = blockedAround(cell, owner) - before;
        owner[static_cast<std::size_t>(cell)] = from;
        if (change < bestChange) {
            bestChange = change;
            best = to;
        }
    }
    return best;
}

int BorderStraightening::straighten(RegionAllocation& regions) const {
    std::vector<int>& owner = regions.robotOfCell;
    std::vector<double>& cost = regions.costSeconds;
    if (cost.empty())
        return 0;
    const double ceiling = *std::max_element(cost.begin(), cost.end()) * (1.0 + slack_);
    auto isStart = [&](int cell) {
        return std::find(regions.startCell.begin(), regions.startCell.end(), cell) != regions.startCell.end();
    };
    // Every pass looks at every cell: a move elsewhere may have made room under the ceiling.
    int moved = 0;
    for (int pass = 0; pass < passLimit; ++pass) {
        int movedThisPass = 0;
        for (std::size_t id = 0; id < graph_.size(); ++id) {
            const int cell = static_cast<int>(id);
            const int from = owner[id];
            if (from < 0)
                continue;
            const int to = bestMove(cell, owner, cost, ceiling);
            if (to < 0 || isStart(cell) || !staysConnectedWithout(cell, owner))
                continue;
            const double cellCost = graph_.cell(id).coverSeconds();
            owner[id] = to;
            cost[static_cast<std::size_t>(from)] -= cellCost;
            cost[static_cast<std::size_t>(to)] += cellCost;
            ++movedThisPass;
        }
        moved += movedThisPass;
        if (movedThisPass == 0)
            break;
    }
    return moved;
}

} // namespace mcpp
