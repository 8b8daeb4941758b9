#include "core/coverage/SubCellNodes.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {
namespace {

struct LatticeOffset {
    int east = 0;  // sub-cells
    int south = 0; // sub-cells
};

constexpr std::array<LatticeOffset, 4> offsets{{{1, 0}, {0, -1}, {-1, 0}, {0, 1}}}; // by Direction

bool isEast(SubCell subCell) {
    return subCell == SubCell::SouthEast || subCell == SubCell::NorthEast;
}
bool isSouth(SubCell subCell) {
    return subCell == SubCell::SouthWest || subCell == SubCell::SouthEast;
}

// The side neighbour of `cell` at (column, row) among the grid's neighbours, or -1.
int neighbourAt(const CellGraph& graph, int cell, int column, int row) {
    for (const int other : graph.neighbours(cell)) {
        const Cell& candidate = graph.cell(other);
        if (candidate.column == column && candidate.row == row)
            return other;
    }
    return -1;
}

} // namespace

SubCellNodes::SubCellNodes(const CellGraph& graph, const std::vector<int>& cells, double ownSpeed)
    : cells_(cells) {
    std::sort(cells_.begin(), cells_.end());
    nodeOfSubCell_.assign(cells_.size() * 4, none);
    for (std::size_t slot = 0; slot < cells_.size(); ++slot) {
        const Cell& cell = graph.cell(cells_[slot]);
        for (const SubCell subCell : subCellsCounterClockwise) {
            if (!cell.isFree(subCell))
                continue;
            Node node;
            const MapPoint centre = cell.subCellCentre(subCell);
            node.waypoint = {centre.x, centre.y, cells_[slot],
                             ownSpeed > 0.0 ? static_cast<float>(ownSpeed) : cell.speedMetresPerSecond};
            nodeOfSubCell_[slot * 4 + static_cast<std::size_t>(subCell)] = static_cast<int>(nodes_.size());
            nodes_.push_back(node);
        }
    }
    for (Node& node : nodes_) {
        const Cell& cell = graph.cell(node.waypoint.cell);
        const SubCell own = cell.subCellAt({node.waypoint.x, node.waypoint.y});
        const int x = 2 * cell.column + (isEast(own) ? 1 : 0);
        const int y = 2 * cell.row + (isSouth(own) ? 1 : 0);
        for (int direction = 0; direction < 4; ++direction) {
            const int nextX = x + offsets[static_cast<std::size_t>(direction)].east;
            const int nextY = y + offsets[static_cast<std::size_t>(direction)].south;
            const int column = nextX >= 0 ? nextX / 2 : -1;
            const int row = nextY >= 0 ? nextY / 2 : -1;
            const int other = column == cell.column && row == cell.row
                                  ? node.waypoint.cell
                                  : neighbourAt(graph, node.waypoint.cell, column, row);
            if (other >= 0)
                node.neighbour[static_cast<std::size_t>(direction)] =
                    at(other, subCellOf(nextX % 2 == 1, nextY % 2 == 1));
        }
    }
}

int SubCellNodes::slotOf(int cell) const {
    const auto found = std::lower_bound(cells_.begin(), cells_.end(), cell);
    return found != cells_.end() && *found == cell ? static_cast<int>(found - cells_.begin()) : none;
}

int SubCellNodes::at(int cell, SubCell subCell) const {
    const int slot = slotOf(cell);
    return slot == none
               ? none
               : nodeOfSubCell_[static_cast<std::size_t>(slot) * 4 + static_cast<std::size_t>(subCell)];
}

std::vector<int> SubCellNodes::ofCell(int cell) const {
    std::vector<int> found;
    for (const SubCell subCell : subCellsCounterClockwise)
        if (const int index = at(cell, subCell); index != none)
            found.push_back(index);
    return found;
}

int SubCellNodes::nearestIn(int cell, MapPoint point) const {
    int best = none;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const int index : ofCell(cell)) {
        const double distance = std::hypot(waypoint(index).x - point.x, waypoint(index).y - point.y);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = index;
        }
    }
    return best;
}

int SubCellNodes::startNode(int robot, int cell, MapPoint start) const {
    const int node = nearestIn(cell, start);
    if (node == none)
        throw PlanningError::aboutStart(PlanningError::Kind::StartOnObstacle, robot,
                                        "lies in a cell with no free sub-cell");
    return node;
}

double SubCellNodes::stepSeconds(int from, int to) const {
    const Waypoint& a = waypoint(from);
    const Waypoint& b = waypoint(to);
    return travelSeconds(std::hypot(b.x - a.x, b.y - a.y), a.speedMetresPerSecond, b.speedMetresPerSecond);
}

} // namespace mcpp
