#include "core/allocation/BorderStraightening.hpp"

#include "core/model/ParallelFor.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace mcpp {
namespace {

constexpr std::size_t east = 0;
constexpr std::size_t north = 1;
constexpr std::size_t west = 2;
constexpr std::size_t south = 3;

// Cells a connectivity check may visit: regions are checked near the moved cell only.
constexpr std::size_t searchLimit = 256;
// Passes over the border; later passes move few (on the benchmark grids the third moves under 5 %).
constexpr int passLimit = 8;

} // namespace

ParameterSpec BorderStraightening::slackParameter() {
    return realParameter("fewer_turns_slack", "Balance traded for turns", 0.2, 0.0, 10.0,
                         "How much longer than the most loaded robot's time (in percent) a region may grow "
                         "when a border cell changes hands so that borders cut fewer straight runs: more "
                         "means fewer turns and a less even split, 0 keeps the split as it was",
                         "%");
}

BorderStraightening::BorderStraightening(const CellGraph& graph, double slack, FirstPass firstPass)
    : graph_(graph), slack_(slack), firstPass_(firstPass) {}

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

// Tries the cell in each neighbouring region, restoring its owner after each trial.
int BorderStraightening::bestMove(int cell, std::vector<int>& owner, const std::vector<double>& cost,
                                  double ceiling, bool& refused) const {
    const int from = owner[static_cast<std::size_t>(cell)];
    const double cellCost = graph_.cell(static_cast<std::size_t>(cell)).coverSeconds();
    int before = -1; // counted when a first region could take the cell: most cells are inside theirs
    int best = -1;
    int bestChange = 0;
    for (int neighbour : graph_.neighbours(cell)) {
        const int to = owner[static_cast<std::size_t>(neighbour)];
        if (to < 0 || to == from || to == best)
            continue;
        if (cost[static_cast<std::size_t>(to)] + cellCost * pace(to) > ceiling) {
            refused = true;
            continue;
        }
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

// Blocked cells among the given ones and their neighbours, each counted once.
int BorderStraightening::blockedNear(const std::vector<int>& cells, const std::vector<int>& owner) const {
    std::vector<int> near(cells);
    for (int cell : cells)
        for (int neighbour : graph_.neighbours(cell))
            near.push_back(neighbour);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    int count = 0;
    for (int cell : near)
        if (blocksRuns(cell, owner))
            ++count;
    return count;
}

// A cell with the next one along a straight line in its region, both to a neighbouring region: a border
// step that no single move straightens.
int BorderStraightening::movePair(int cell, RegionAllocation& regions, double ceiling,
                                  LocalConnectivity& connectivity) const {
    std::vector<int>& owner = regions.robotOfCell;
    std::vector<double>& cost = regions.costSeconds;
    const int from = owner[static_cast<std::size_t>(cell)];
    for (std::size_t side = 0; side < 4; ++side) {
        const int partner = straightNeighbour(cell, side);
        if (partner < 0 || owner[static_cast<std::size_t>(partner)] != from || isStart(partner, regions))
            continue;
        const double pairCost = graph_.cell(static_cast<std::size_t>(cell)).coverSeconds() +
                                graph_.cell(static_cast<std::size_t>(partner)).coverSeconds();
        const std::vector<int> pair{cell, partner};
        int before = -1; // counted once a region could take the pair
        for (int neighbour : graph_.neighbours(cell)) {
            const int to = owner[static_cast<std::size_t>(neighbour)];
            if (to < 0 || to == from || cost[static_cast<std::size_t>(to)] + pairCost * pace(to) > ceiling)
                continue;
            if (before < 0)
                before = blockedNear(pair, owner);
            owner[static_cast<std::size_t>(cell)] = to;
            owner[static_cast<std::size_t>(partner)] = to;
            const int after = blockedNear(pair, owner);
            owner[static_cast<std::size_t>(cell)] = from;
            owner[static_cast<std::size_t>(partner)] = from;
            if (after >= before || !connectivity.canRemove(cell, owner, searchLimit))
                continue;
            owner[static_cast<std::size_t>(cell)] = to;
            const bool connected = connectivity.canRemove(partner, owner, searchLimit);
            owner[static_cast<std::size_t>(cell)] = from;
            if (!connected)
                continue;
            owner[static_cast<std::size_t>(cell)] = to;
            owner[static_cast<std::size_t>(partner)] = to;
            cost[static_cast<std::size_t>(from)] -= pairCost * pace(from);
            cost[static_cast<std::size_t>(to)] += pairCost * pace(to);
            return partner;
        }
    }
    return -1;
}

bool BorderStraightening::onBorder(int cell, const std::vector<int>& owner) const {
    const int region = owner[static_cast<std::size_t>(cell)];
    for (int neighbour : graph_.neighbours(cell)) {
        const int other = owner[static_cast<std::size_t>(neighbour)];
        if (other >= 0 && other != region)
            return true;
    }
    return false;
}

std::vector<std::uint8_t> BorderStraightening::bordersBeforeMoves(const std::vector<int>& owner) const {
    // A byte a cell (not bits), so that threads never write the same word.
    constexpr std::size_t cellsPerTask = std::size_t{1} << 16;
    std::vector<std::uint8_t> border(graph_.size(), 0);
    parallelForRanges(graph_.size(), cellsPerTask, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t cell = begin; cell < end; ++cell)
            border[cell] = owner[cell] >= 0 && onBorder(static_cast<int>(cell), owner) ? 1 : 0;
    });
    return border;
}

bool BorderStraightening::isStart(int cell, const RegionAllocation& regions) {
    return std::find(regions.startCell.begin(), regions.startCell.end(), cell) != regions.startCell.end();
}

int BorderStraightening::straighten(RegionAllocation& regions) const {
    std::vector<int>& owner = regions.robotOfCell;
    std::vector<double>& cost = regions.costSeconds;
    if (cost.empty())
        return 0;
    const double ceiling = *std::max_element(cost.begin(), cost.end()) * (1.0 + slack_);
    // The first pass looks at every cell, later ones at those near a move and those a region refused for
    // its cost: moves elsewhere may have made room under the ceiling since.
    std::vector<int> pending(graph_.size());
    std::iota(pending.begin(), pending.end(), 0);
    std::vector<int> queuedFor(graph_.size(), 0);
    // The first pass skips cells found off every border beforehand, unless a move changed them or a
    // neighbour since: the same cells are looked at as when each is asked in turn.
    const std::vector<std::uint8_t> onBorderAtFirst = firstPass_ == FirstPass::SkipsInsides
                                                          ? bordersBeforeMoves(owner)
                                                          : std::vector<std::uint8_t>(graph_.size(), 1);
    std::vector<bool> changedAround(graph_.size(), false);
    LocalConnectivity connectivity(graph_);
    int moved = 0;
    for (int pass = 1; pass <= passLimit && !pending.empty(); ++pass) {
        std::vector<int> next;
        const auto queue = [&](int cell) {
            if (queuedFor[static_cast<std::size_t>(cell)] != pass) {
                queuedFor[static_cast<std::size_t>(cell)] = pass;
                next.push_back(cell);
            }
        };
        for (int cell : pending) {
            const int from = owner[static_cast<std::size_t>(cell)];
            if (from < 0 || (pass == 1 && onBorderAtFirst[static_cast<std::size_t>(cell)] == 0 &&
                             !changedAround[static_cast<std::size_t>(cell)]))
                continue;
            if (!onBorder(cell, owner) || isStart(cell, regions))
                continue;
            bool refused = false;
            const int to = bestMove(cell, owner, cost, ceiling, refused);
            int partner = -1;
            if (to >= 0 && connectivity.canRemove(cell, owner, searchLimit)) {
                const double cellCost = graph_.cell(static_cast<std::size_t>(cell)).coverSeconds();
                owner[static_cast<std::size_t>(cell)] = to;
                cost[static_cast<std::size_t>(from)] -= cellCost * pace(from);
                cost[static_cast<std::size_t>(to)] += cellCost * pace(to);
                ++moved;
            } else if ((partner = movePair(cell, regions, ceiling, connectivity)) >= 0) {
                moved += 2;
            } else {
                if (refused)
                    queue(cell);
                continue;
            }
            for (int changed : {cell, partner}) {
                if (changed < 0)
                    continue;
                changedAround[static_cast<std::size_t>(changed)] = true;
                for (int neighbour : graph_.neighbours(changed)) {
                    changedAround[static_cast<std::size_t>(neighbour)] = true;
                    for (int around : graph_.neighbours(neighbour))
                        queue(around);
                }
            }
        }
        std::sort(next.begin(), next.end()); // cell order, as the first pass
        pending = std::move(next);
    }
    return moved;
}

} // namespace mcpp
