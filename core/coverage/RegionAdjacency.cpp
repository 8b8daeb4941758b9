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
    edges_.push_back({a, b, side, from.span == to.span && sameLine});
}

void RegionAdjacency::index(std::size_t nodes) {
    offsets_.assign(nodes + 1, 0);
    for (const Edge& edge : edges_) {
        ++offsets_[static_cast<std::size_t>(edge.first) + 1];
        ++offsets_[static_cast<std::size_t>(edge.second) + 1];
    }
    for (std::size_t i = 0; i < nodes; ++i)
        offsets_[i + 1] += offsets_[i];
    incidences_.resize(2 * edges_.size());
    std::vector<int> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t e = 0; e < edges_.size(); ++e) {
        const Edge& edge = edges_[e];
        const int id = static_cast<int>(e);
        incidences_[static_cast<std::size_t>(fill[static_cast<std::size_t>(edge.first)]++)] = {
            id, edge.second, edge.sideOfFirst};
        incidences_[static_cast<std::size_t>(fill[static_cast<std::size_t>(edge.second)]++)] = {
            id, edge.first, oppositeSide(edge.sideOfFirst)};
    }
}

} // namespace mcpp
