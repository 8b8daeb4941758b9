#include "core/coverage/SizeChangeConnectors.hpp"

#include <algorithm>
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
    const double dx = to.x - from.x;
    const double dy = to.y - from.y;
    return std::sqrt(dx * dx + dy * dy) - (fromCellSize + toCellSize) / 4.0;
}

} // namespace

SizeChangeConnectors::SizeChangeConnectors(const CellGraph& graph, const std::vector<int>& cells,
                                           const RegionAdjacency& adjacency)
    : graph_(graph), cells_(cells), adjacency_(adjacency) {
    largerEnd_.reserve(adjacency.edges().size());
    for (const auto& edge : adjacency.edges()) {
        const int firstSpan = cellOf(edge.first).span;
        const int secondSpan = cellOf(edge.second).span;
        largerEnd_.push_back(firstSpan == secondSpan ? -1
                                                     : (firstSpan > secondSpan ? edge.first : edge.second));
    }
    // A small floor, so that turns still break ties where they are free.
    constexpr double floorSeconds = 1e-3;
    turnSeconds_.reserve(cells.size());
    for (const int cell : cells)
        turnSeconds_.push_back(
            std::max(static_cast<double>(graph.cell(cell).turnSecondsPer90Degrees), floorSeconds));
}

int SizeChangeConnectors::largerEnd(int edge) const {
    return largerEnd_[static_cast<std::size_t>(edge)];
}

std::size_t SizeChangeConnectors::smallerNeighbours(int node, CellSide side, const std::vector<char>& inTree,
                                                    int alsoEdge, Neighbours& out) const {
    const int span = cellOf(node).span;
    const SidePassage passage = passageOf(side);
    std::size_t count = 0;
    for (const auto& incidence : adjacency_.incident(node)) {
        if (incidence.side != side ||
            (inTree[static_cast<std::size_t>(incidence.edge)] == 0 && incidence.edge != alsoEdge))
            continue;
        const Cell& other = cellOf(incidence.other);
        if (other.span >= span || count == out.size())
            continue;
        const double along = (passage.alongX ? other.centreX() : other.centreY()) * passage.sign;
        // Insertion in the walk's order: a side holds a few neighbours at most.
        std::size_t at = count++;
        for (; at > 0 && out[at - 1].along > along; --at)
            out[at] = out[at - 1];
        out[at] = {along, incidence.other, incidence.edge};
    }
    return count;
}

double SizeChangeConnectors::passSeconds(int node, CellSide side, const Neighbours& neighbours,
                                         std::size_t count, int leftOutEdge) const {
    const Cell& self = cellOf(node);
    const SidePassage passage = passageOf(side);
    double excess = 0.0;
    MapPoint from = self.subCellCentre(passage.first);
    double fromSize = self.size;
    bool any = false;
    for (std::size_t i = 0; i < count; ++i) {
        if (neighbours[i].edge == leftOutEdge)
            continue;
        const Cell& other = cellOf(neighbours[i].node);
        excess += excessMetres(from, fromSize, other.subCellCentre(passage.entry), other.size);
        from = other.subCellCentre(passage.exit);
        fromSize = other.size;
        any = true;
    }
    if (!any)
        return 0.0;
    excess += excessMetres(from, fromSize, self.subCellCentre(passage.last), self.size);
    const double speed = self.speedMetresPerSecond > 0.0 ? self.speedMetresPerSecond : 1.0;
    return excess / speed;
}

double SizeChangeConnectors::sideSeconds(int node, CellSide side, const std::vector<char>& inTree) const {
    Neighbours neighbours;
    const std::size_t count = smallerNeighbours(node, side, inTree, -1, neighbours);
    return passSeconds(node, side, neighbours, count, -1);
}

double SizeChangeConnectors::changeOnToggle(int edge, const std::vector<char>& inTree) const {
    const int larger = largerEnd(edge);
    if (larger < 0)
        return 0.0;
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    const CellSide side = larger == e.first ? e.sideOfFirst : oppositeSide(e.sideOfFirst);
    // The side's joined neighbours and this edge's, costed with and without it, from one look round.
    Neighbours neighbours;
    const std::size_t count = smallerNeighbours(larger, side, inTree, edge, neighbours);
    const double with = passSeconds(larger, side, neighbours, count, -1);
    const double without = passSeconds(larger, side, neighbours, count, edge);
    return inTree[static_cast<std::size_t>(edge)] != 0 ? without - with : with - without;
}

double SizeChangeConnectors::turnSeconds(int node) const {
    return turnSeconds_[static_cast<std::size_t>(node)];
}

} // namespace mcpp
