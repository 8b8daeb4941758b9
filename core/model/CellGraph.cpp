#include "core/model/CellGraph.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
    : CellGraph(frame, recordsOf(cells), std::move(adjacency)) {
    std::vector<float> seconds;
    std::vector<float> turns;
    seconds.reserve(cells.size());
    turns.reserve(cells.size());
    for (const Cell& cell : cells) {
        seconds.push_back(cell.turnSecondsPer90Degrees);
        turns.push_back(cell.expectedTurnsPerSubCell);
    }
    turns_.setTurnSeconds(std::move(seconds));
    turns_.setExpectedTurns(std::move(turns));
}

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

CellGraph CellGraph::ofGrid(GridFrame frame, std::vector<CellRecord> records) {
    CellGraph graph;
    graph.frame_ = frame;
    if (frame.levels != 1)
        throw std::invalid_argument("a grid's cell graph of " + std::to_string(frame.levels) + " levels");
    graph.occupancy_ = GridOccupancy(frame.columns, frame.rows, records);
    graph.records_ = std::move(records);
    return graph;
}

CellGraph::CellGraph(const CellGraph& sameCells, std::vector<CellRecord> records)
    : frame_(sameCells.frame_), records_(std::move(records)), turns_(sameCells.turns_),
      adjacency_(sameCells.adjacency_), occupancy_(sameCells.occupancy_), locator_(sameCells.locator_) {
    if (records_.size() != sameCells.records_.size())
        throw std::invalid_argument("a cell graph's figures for " + std::to_string(records_.size()) +
                                    " cells where it has " + std::to_string(sameCells.records_.size()));
    // Turn times worked out from the speeds stay those of the speeds they were worked out from, as a
    // planner pricing cells by other speeds expects.
    const bool speedsChanged = !std::equal(records_.begin(), records_.end(), sameCells.records_.begin(),
                                           [](const CellRecord& now, const CellRecord& before) {
                                               return now.speedMetresPerSecond == before.speedMetresPerSecond;
                                           });
    if (turns_.followSpeeds() && speedsChanged) {
        std::vector<float> seconds(records_.size());
        for (std::size_t id = 0; id < seconds.size(); ++id)
            seconds[id] = sameCells.turnSeconds(static_cast<int>(id));
        turns_.setTurnSeconds(std::move(seconds));
    }
}

bool CellGraph::areNeighbours(int a, int b) const {
    if (!occupancy_.empty()) { // grid cells of one size: side by side in a row or a column
        const CellRecord& first = record(a);
        const CellRecord& second = record(b);
        return std::abs(first.column - second.column) + std::abs(first.row - second.row) == 1;
    }
    const NeighbourList list = neighbours(a);
    return std::find(list.begin(), list.end(), b) != list.end();
}

NeighbourTopology CellGraph::neighbourLists() const {
    if (occupancy_.empty())
        return adjacency_;
    std::vector<int> offsets;
    std::vector<int> neighbours;
    offsets.reserve(records_.size() + 1);
    neighbours.reserve(records_.size() * NeighbourList::mostWorkedOut);
    offsets.push_back(0);
    for (std::size_t id = 0; id < records_.size(); ++id) {
        for (const int neighbour : neighboursOnGrid(static_cast<int>(id)))
            neighbours.push_back(neighbour);
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    return {std::move(offsets), std::move(neighbours)};
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
    if (!occupancy_.empty())
        return occupancy_.idAt(static_cast<int>(column), static_cast<int>(row));
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
    turns_.applyModel(model);
}

void CellGraph::setExpectedTurns(const std::vector<float>& turnsPerSubCell) {
    std::vector<float> turns(records_.size());
    for (std::size_t id = 0; id < turns.size(); ++id)
        turns[id] = id < turnsPerSubCell.size() ? turnsPerSubCell[id] : turns_.expectedTurns(id);
    turns_.setExpectedTurns(std::move(turns));
}

void CellGraph::setTurnSeconds(std::vector<float> secondsPerCell) {
    secondsPerCell.resize(records_.size(), 0.0F);
    turns_.setTurnSeconds(std::move(secondsPerCell));
}

void CellGraph::setTurnFigures(CellTurnFigures figures) {
    turns_ = std::move(figures);
}

} // namespace mcpp
