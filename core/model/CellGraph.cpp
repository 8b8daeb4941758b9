#include "core/model/CellGraph.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace mcpp {
namespace {

std::uint64_t placementKey(long long row, long long column) {
    return (static_cast<std::uint64_t>(row) << 32U) | static_cast<std::uint64_t>(column);
}

std::uint64_t keyOf(const CellRecord& cell) {
    return placementKey(cell.row / cell.span, cell.column / cell.span);
}

std::vector<CellRecord> recordsOf(const std::vector<Cell>& cells) {
    std::vector<CellRecord> records;
    records.reserve(cells.size());
    for (const Cell& cell : cells)
        records.push_back(recordOf(cell));
    return records;
}

} // namespace

CellGraph::CellGraph(GridFrame frame, const std::vector<Cell>& cells, NeighbourTopology adjacency)
    : CellGraph(frame, recordsOf(cells), std::move(adjacency)) {}

CellGraph::CellGraph(GridFrame frame, std::vector<CellRecord> records, NeighbourTopology adjacency)
    : frame_(frame), records_(std::move(records)), adjacency_(std::move(adjacency)) {
    // Squares are worked out level by level from the top cells: a frame must have the levels a quadtree
    // can.
    if (frame_.levels > mostQuadTreeLevels || (frame_.levels < 1 && !records_.empty()))
        throw std::invalid_argument("a cell graph of " + std::to_string(frame_.levels) +
                                    " levels; a quadtree has 1 to " + std::to_string(mostQuadTreeLevels));
    std::map<int, std::size_t> cellsOfSpan;
    for (const CellRecord& cell : records_)
        ++cellsOfSpan[cell.span];
    for (const auto& [span, count] : cellsOfSpan)
        locator_.emplace_back(span, idsInPlacementOrder(span, count));
}

// The cells of one span ordered by placement. Decompositions mostly list cells in that order already (a
// uniform grid or a one-level quadtree row by row): then the ids are taken as they are, without sorting
// tens of millions of keys.
std::vector<int> CellGraph::idsInPlacementOrder(int span, std::size_t count) const {
    std::vector<int> ids;
    ids.reserve(count);
    bool ordered = true;
    std::uint64_t previousKey = 0;
    for (std::size_t id = 0; id < records_.size(); ++id) {
        if (records_[id].span != span)
            continue;
        const std::uint64_t key = keyOf(records_[id]);
        ordered = ordered && (ids.empty() || previousKey < key);
        previousKey = key;
        ids.push_back(static_cast<int>(id));
    }
    if (ordered)
        return ids;
    // Sorted by a key computed once per cell; the keys are dropped when the ids are in order.
    std::vector<std::pair<std::uint64_t, int>> keys;
    keys.reserve(count);
    for (int id : ids)
        keys.emplace_back(keyOf(records_[static_cast<std::size_t>(id)]), id);
    std::sort(keys.begin(), keys.end());
    std::transform(keys.begin(), keys.end(), ids.begin(), [](const auto& key) { return key.second; });
    return ids;
}

int CellGraph::cellAt(MapPoint point) const {
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
        return -1;
    const double column = std::floor((point.x - frame_.originX) / frame_.bottomCellSize);
    const double row = std::floor((frame_.originY - point.y) / frame_.bottomCellSize);
    if (!(column >= 0 && row >= 0 && column < frame_.columns && row < frame_.rows)) // false for NaN too
        return -1;
    for (const auto& [span, ids] : locator_) {
        const std::uint64_t key =
            placementKey(static_cast<long long>(row) / span, static_cast<long long>(column) / span);
        const auto found = std::lower_bound(ids.begin(), ids.end(), key, [&](int id, std::uint64_t wanted) {
            return keyOf(record(id)) < wanted;
        });
        if (found != ids.end() && keyOf(record(*found)) == key)
            return *found;
    }
    return -1;
}

void CellGraph::applyTurnTime(const TurnTimeModel& model) {
    for (CellRecord& cell : records_)
        cell.turnSecondsPer90Degrees =
            static_cast<float>(model.secondsPer90Degrees(cell.speedMetresPerSecond));
}

void CellGraph::setExpectedTurns(const std::vector<float>& turnsPerSubCell) {
    for (std::size_t id = 0; id < records_.size() && id < turnsPerSubCell.size(); ++id)
        records_[id].expectedTurnsPerSubCell = turnsPerSubCell[id];
}

} // namespace mcpp
