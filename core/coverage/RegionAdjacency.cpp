#include "core/coverage/RegionAdjacency.hpp"

namespace mcpp {
namespace {

// From the cells' placement on the bottom grid (row 0 at the north): exact, and no square to work out.
CellSide sideOf(const CellRecord& from, const CellRecord& to) {
    if (to.column >= from.column + from.span)
        return CellSide::East;
    if (to.column + to.span <= from.column)
        return CellSide::West;
    return to.row + to.span <= from.row ? CellSide::North : CellSide::South;
}

} // namespace

void RegionAdjacency::add(const CellRecord& from, const CellRecord& to, int a, int b) {
    const CellSide side = sideOf(from, to);
    const bool horizontal = side == CellSide::East || side == CellSide::West;
    const bool sameLine = horizontal ? from.row == to.row : from.column == to.column;
    Edge& edge = edges_.emplace_back();
    edge.first = a;
    edge.second = b;
    edge.sideOfFirst = side;
    edge.straight = from.span == to.span && sameLine;
}

void RegionAdjacency::index(std::size_t nodes) {
    // Counted, summed to each node's end, then filled from the back with the edges in reverse: each node's
    // edges come out in increasing order and its start is left behind, with no second array of offsets.
    secondOffsets_.assign(nodes + 1, 0);
    for (const Edge& edge : edges_)
        ++secondOffsets_[static_cast<std::size_t>(edge.second)];
    for (std::size_t i = 1; i <= nodes; ++i)
        secondOffsets_[i] += secondOffsets_[i - 1];
    secondEnds_.resize(edges_.size());
    for (std::size_t e = edges_.size(); e-- > 0;)
        secondEnds_[static_cast<std::size_t>(--secondOffsets_[static_cast<std::size_t>(edges_[e].second)])] =
            static_cast<int>(e);
}

} // namespace mcpp
