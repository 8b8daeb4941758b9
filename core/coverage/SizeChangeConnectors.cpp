#include "core/coverage/SizeChangeConnectors.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mcpp {
namespace {

// How a counter-clockwise walk passes a side of a cell: from corner sub-cell `first` to `last`; a
// neighbour there is entered at its sub-cell `entry` and left from `exit`; neighbours come in the order of
// `along` (their centre's coordinate, x or y, times `sign`).
struct SidePassage {
    SubCell first;
    SubCell last;
    SubCell entry;
    SubCell exit;
    bool alongX;
    double sign;
};

SidePassage passageOf(CellSide side) {
    switch (side) {
    case CellSide::East:
        return {SubCell::SouthEast, SubCell::NorthEast, SubCell::SouthWest, SubCell::NorthWest, false, 1.0};
    case CellSide::North:
        return {SubCell::NorthEast, SubCell::NorthWest, SubCell::SouthEast, SubCell::SouthWest, true, -1.0};
    case CellSide::West:
        return {SubCell::NorthWest, SubCell::SouthWest, SubCell::NorthEast, SubCell::SouthEast, false, -1.0};
    case CellSide::South:
        break;
    }
    return {SubCell::SouthWest, SubCell::SouthEast, SubCell::NorthWest, SubCell::NorthEast, true, 1.0};
}

// A step's length beyond one sub-cell's half side at each end: what a straight step between sub-cells
// of these cells would be.
double excessMetres(MapPoint from, double fromCellSize, MapPoint to, double toCellSize) {
    return std::hypot(to.x - from.x, to.y - from.y) - (fromCellSize + toCellSize) / 4.0;
}

} // namespace

int SizeChangeConnectors::largerEnd(int edge) const {
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    const int firstSpan = cellOf(e.first).span;
    const int secondSpan = cellOf(e.second).span;
    if (firstSpan == secondSpan)
        return -1;
    return firstSpan > secondSpan ? e.first : e.second;
}

double SizeChangeConnectors::sideSeconds(int node, CellSide side, const std::vector<char>& inTree) const {
    const Cell& self = cellOf(node);
    const SidePassage passage = passageOf(side);
    // The joined smaller neighbours on this side, in the walk's order (a side holds a few at most).
    std::array<std::pair<double, int>, 16> joined{};
    std::size_t count = 0;
    for (const auto& incidence : adjacency_.incident(node)) {
        if (incidence.side != side || inTree[static_cast<std::size_t>(incidence.edge)] == 0)
            continue;
        const Cell& other = cellOf(incidence.other);
        if (other.span >= self.span || count == joined.size())
            continue;
        const double along = passage.alongX ? other.centreX() : other.centreY();
        joined[count++] = {along * passage.sign, incidence.other};
    }
    if (count == 0)
        return 0.0;
    std::sort(joined.begin(), joined.begin() + static_cast<std::ptrdiff_t>(count));
    double excess = 0.0;
    MapPoint from = self.subCellCentre(passage.first);
    double fromSize = self.size;
    for (std::size_t i = 0; i < count; ++i) {
        const Cell& other = cellOf(joined[i].second);
        excess += excessMetres(from, fromSize, other.subCellCentre(passage.entry), other.size);
        from = other.subCellCentre(passage.exit);
        fromSize = other.size;
    }
    excess += excessMetres(from, fromSize, self.subCellCentre(passage.last), self.size);
    const double speed = self.speedMetresPerSecond > 0.0 ? self.speedMetresPerSecond : 1.0;
    return excess / speed;
}

double SizeChangeConnectors::changeOnToggle(int edge, std::vector<char>& inTree) const {
    const int larger = largerEnd(edge);
    if (larger < 0)
        return 0.0;
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    const CellSide side = larger == e.first ? e.sideOfFirst : oppositeSide(e.sideOfFirst);
    const double before = sideSeconds(larger, side, inTree);
    char& mark = inTree[static_cast<std::size_t>(edge)];
    mark = mark == 0 ? 1 : 0;
    const double after = sideSeconds(larger, side, inTree);
    mark = mark == 0 ? 1 : 0;
    return after - before;
}

double SizeChangeConnectors::turnSeconds(int node) const {
    constexpr double floorSeconds = 1e-3;
    return std::max(static_cast<double>(cellOf(node).turnSecondsPer90Degrees), floorSeconds);
}

} // namespace mcpp
