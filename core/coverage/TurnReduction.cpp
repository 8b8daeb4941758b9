#include "core/coverage/TurnReduction.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <numeric>

namespace mcpp {
namespace {

int totalTurns(const std::vector<CoveragePath>& paths) {
    return std::accumulate(paths.begin(), paths.end(), 0,
                           [](int sum, const CoveragePath& path) { return sum + path.turns; });
}

// The regions a cell could join: those holding at least two of its neighbours, when its own region holds
// only one (a cell with none is its region's last and stays).
std::vector<int> takers(const CellGraph& graph, const std::vector<int>& owner, int cell) {
    const int own = owner[static_cast<std::size_t>(cell)];
    std::vector<int> counts;
    std::vector<int> regions;
    int ownCount = 0;
    for (int neighbour : graph.neighbours(cell)) {
        const int region = owner[static_cast<std::size_t>(neighbour)];
        if (region == own) {
            ++ownCount;
            continue;
        }
        if (region < 0)
            continue;
        const auto found = std::find(regions.begin(), regions.end(), region);
        if (found == regions.end()) {
            regions.push_back(region);
            counts.push_back(1);
        } else {
            ++counts[static_cast<std::size_t>(found - regions.begin())];
        }
    }
    std::vector<int> result;
    if (ownCount != 1)
        return result;
    for (std::size_t k = 0; k < regions.size(); ++k)
        if (counts[k] >= 2)
            result.push_back(regions[k]);
    return result;
}

} // namespace

TurnReduction::Outcome TurnReduction::improve(const CellGraph& graph, RegionAllocation& regions,
                                              std::vector<CoveragePath>& paths,
                                              const std::vector<MapPoint>& starts,
                                              const ProgressReporter& progress) const {
    Outcome outcome;
    outcome.turnsBefore = totalTurns(paths);
    std::vector<std::vector<int>> cells = cellsByRobot(regions);
    std::vector<int>& owner = regions.robotOfCell;
    std::vector<int> scratchIndex(graph.size(), -1);
    const auto pathOf = [&](int robot) {
        const auto r = static_cast<std::size_t>(robot);
        return coverage_.regionPath(graph, cells[r], regions.startCell[r], robot, starts[r], scratchIndex);
    };
    for (int round = 0; round < rounds_; ++round) {
        int moved = 0;
        const double makespan = longestPathSeconds(paths);
        for (int cell = 0; cell < static_cast<int>(graph.size()); ++cell) {
            const int donor = owner[static_cast<std::size_t>(cell)];
            if (donor < 0 || regions.startCell[static_cast<std::size_t>(donor)] == cell)
                continue;
            progress.throwIfCancelled();
            for (int taker : takers(graph, owner, cell)) {
                auto& donorCells = cells[static_cast<std::size_t>(donor)];
                auto& takerCells = cells[static_cast<std::size_t>(taker)];
                donorCells.erase(std::find(donorCells.begin(), donorCells.end(), cell));
                takerCells.insert(std::lower_bound(takerCells.begin(), takerCells.end(), cell), cell);
                CoveragePath donorPath = pathOf(donor);
                CoveragePath takerPath = pathOf(taker);
                const CoveragePath& oldDonor = paths[static_cast<std::size_t>(donor)];
                const CoveragePath& oldTaker = paths[static_cast<std::size_t>(taker)];
                const bool better = donorPath.turns <= oldDonor.turns && takerPath.turns <= oldTaker.turns &&
                                    donorPath.turns + takerPath.turns < oldDonor.turns + oldTaker.turns &&
                                    takerPath.timeSeconds <= makespan + 1e-9;
                if (better) {
                    owner[static_cast<std::size_t>(cell)] = taker;
                    paths[static_cast<std::size_t>(donor)] = std::move(donorPath);
                    paths[static_cast<std::size_t>(taker)] = std::move(takerPath);
                    ++moved;
                    break;
                }
                takerCells.erase(std::lower_bound(takerCells.begin(), takerCells.end(), cell));
                donorCells.insert(std::lower_bound(donorCells.begin(), donorCells.end(), cell), cell);
            }
        }
        outcome.cellsMoved += moved;
        if (moved == 0)
            break;
    }
    outcome.turnsAfter = totalTurns(paths);
    return outcome;
}

} // namespace mcpp
