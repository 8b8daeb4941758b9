#include "core/coverage/SizeChangeConnectors.hpp"

#include "core/coverage/PathMeasurement.hpp"

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

double speedOf(const Cell& cell) {
    return cell.speedMetresPerSecond > 0.0 ? cell.speedMetresPerSecond : 1.0;
}

// A step from a sub-cell centre of one cell to one of another, timed as paths are beyond the cells' travel.
double stepSeconds(MapPoint from, const Cell& fromCell, MapPoint to, const Cell& toCell) {
    const double dx = to.x - from.x;
    const double dy = to.y - from.y;
    return secondsBeyondCellTravel(std::sqrt(dx * dx + dy * dy), fromCell.size, speedOf(fromCell),
                                   toCell.size, speedOf(toCell));
}

} // namespace

SizeChangeConnectors::SizeChangeConnectors(const CellGraph& graph, const std::vector<int>& cells,
                                           const RegionAdjacency& adjacency)
    : graph_(graph), cells_(cells), adjacency_(adjacency) {
    largerEnd_.reserve(adjacency.edges().size());
    for (const auto& edge : adjacency.edges()) {
        const int firstSpan = recordOf(edge.first).span;
        const int secondSpan = recordOf(edge.second).span;
        largerEnd_.push_back(firstSpan == secondSpan ? -1
                                                     : (firstSpan > secondSpan ? edge.first : edge.second));
    }
    // A small floor, so that turns still break ties where they are free.
    constexpr double floorSeconds = 1e-3;
    turnSeconds_.reserve(cells.size());
    for (const int cell : cells)
        turnSeconds_.push_back(std::max(static_cast<double>(graph.turnSeconds(cell)), floorSeconds));
}

int SizeChangeConnectors::largerEnd(int edge) const {
    return largerEnd_[static_cast<std::size_t>(edge)];
}

const std::vector<SizeChangeConnectors::Neighbour>&
SizeChangeConnectors::smallerNeighbours(int node, CellSide side, const std::vector<char>& inTree,
                                        int alsoEdge) const {
    const int span = recordOf(node).span;
    const SidePassage passage = passageOf(side);
    std::vector<Neighbour>& found = neighbours_;
    found.clear();
    for (const auto& incidence : adjacency_.incident(node)) {
        if (incidence.side != side ||
            (inTree[static_cast<std::size_t>(incidence.edge)] == 0 && incidence.edge != alsoEdge))
            continue;
        if (recordOf(incidence.other).span >= span)
            continue;
        const Cell other = cellOf(incidence.other);
        const double along = (passage.alongX ? other.centreX() : other.centreY()) * passage.sign;
        // Insertion in the walk's order: a side holds a few neighbours, as many as its size over theirs.
        found.push_back({along, incidence.other, incidence.edge});
        for (std::size_t at = found.size() - 1; at > 0 && found[at - 1].along > along; --at)
            std::swap(found[at], found[at - 1]);
    }
    return found;
}

double SizeChangeConnectors::passSeconds(int node, CellSide side, const std::vector<Neighbour>& neighbours,
                                         int leftOutEdge) const {
    const Cell self = cellOf(node);
    const SidePassage passage = passageOf(side);
    double seconds = 0.0;
    MapPoint from = self.subCellCentre(passage.first);
    Cell fromCell = self;
    bool passedAny = false;
    for (const Neighbour& neighbour : neighbours) {
        if (neighbour.edge == leftOutEdge)
            continue;
        const Cell other = cellOf(neighbour.node);
        seconds += stepSeconds(from, fromCell, other.subCellCentre(passage.entry), other);
        from = other.subCellCentre(passage.exit);
        fromCell = other;
        passedAny = true;
    }
    if (!passedAny)
        return 0.0;
    return seconds + stepSeconds(from, fromCell, self.subCellCentre(passage.last), self);
}

double SizeChangeConnectors::sideSeconds(int node, CellSide side, const std::vector<char>& inTree) const {
    return passSeconds(node, side, smallerNeighbours(node, side, inTree, -1), -1);
}

double SizeChangeConnectors::changeOnToggle(int edge, const std::vector<char>& inTree) const {
    const int larger = largerEnd(edge);
    if (larger < 0)
        return 0.0;
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    const CellSide side = larger == e.first ? e.sideOfFirst : oppositeSide(e.sideOfFirst);
    // The side's joined neighbours and this edge's, costed with and without it, from one look round.
    const std::vector<Neighbour>& neighbours = smallerNeighbours(larger, side, inTree, edge);
    const double with = passSeconds(larger, side, neighbours, -1);
    const double without = passSeconds(larger, side, neighbours, edge);
    return inTree[static_cast<std::size_t>(edge)] != 0 ? without - with : with - without;
}

double SizeChangeConnectors::turnSeconds(int node) const {
    return turnSeconds_[static_cast<std::size_t>(node)];
}

} // namespace mcpp
