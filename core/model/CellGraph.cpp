#include "core/model/CellGraph.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace mcpp {
namespace {

std::uint64_t placementKey(long long row, long long column) {
    return (static_cast<std::uint64_t>(row) << 32U) | static_cast<std::uint64_t>(column);
}

} // namespace

CellGraph::CellGraph(GridFrame frame, std::vector<Cell> cells, NeighbourTopology adjacency)
    : frame_(frame), cells_(std::move(cells)), adjacency_(std::move(adjacency)) {
    // Reserved exactly: grown by doubling, the keys of an 18 M-cell map held 0.8 GB instead of 0.3 GB.
    std::map<int, std::size_t> cellsOfSpan;
    for (const Cell& cell : cells_)
        ++cellsOfSpan[cell.span];
    std::map<int, std::vector<std::pair<std::uint64_t, int>>> bySpan;
    for (const auto& [span, count] : cellsOfSpan)
        bySpan[span].reserve(count);
    for (std::size_t id = 0; id < cells_.size(); ++id) {
        const Cell& cell = cells_[id];
        bySpan[cell.span].emplace_back(placementKey(cell.row / cell.span, cell.column / cell.span),
                                       static_cast<int>(id));
    }
    for (auto& [span, keys] : bySpan) {
        std::sort(keys.begin(), keys.end());
        locator_.emplace_back(span, std::move(keys));
    }
}

int CellGraph::cellAt(MapPoint point) const {
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
        return -1;
    const double column = std::floor((point.x - frame_.originX) / frame_.bottomCellSize);
    const double row = std::floor((frame_.originY - point.y) / frame_.bottomCellSize);
    if (!(column >= 0 && row >= 0 && column < frame_.columns && row < frame_.rows)) // false for NaN too
        return -1;
    for (const auto& [span, keys] : locator_) {
        const std::uint64_t key =
            placementKey(static_cast<long long>(row) / span, static_cast<long long>(column) / span);
        const auto found = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, -1));
        if (found != keys.end() && found->first == key)
            return found->second;
    }
    return -1;
}

void CellGraph::applyTurnTime(const TurnTimeModel& model) {
    for (Cell& cell : cells_)
        cell.turnSecondsPer90Degrees =
            static_cast<float>(model.secondsPer90Degrees(cell.speedMetresPerSecond));
}

void CellGraph::setExpectedTurns(const std::vector<float>& turnsPerSubCell) {
    for (std::size_t id = 0; id < cells_.size() && id < turnsPerSubCell.size(); ++id)
        cells_[id].expectedTurnsPerSubCell = turnsPerSubCell[id];
}

} // namespace mcpp
