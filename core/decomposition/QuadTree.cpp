#include "core/decomposition/QuadTree.hpp"

#include <cmath>

namespace mcpp {

int QuadTree::leafAt(double x, double y) const {
    if (topColumns == 0 || topRows == 0)
        return -1;
    const double column = std::floor((x - originX) / topCellSize);
    const double row = std::floor((originY - y) / topCellSize);
    if (column < 0 || row < 0 || column >= topColumns || row >= topRows)
        return -1;
    int index = static_cast<int>(row) * topColumns + static_cast<int>(column);
    while (cells[static_cast<std::size_t>(index)].state == CellState::Auxiliary) {
        const QuadCell& cell = cells[static_cast<std::size_t>(index)];
        const bool east = x >= cell.centreX();
        const bool north = y >= cell.centreY();
        // children: north-west, north-east, south-east, south-west
        const int child = north ? (east ? 1 : 0) : (east ? 2 : 3);
        index = cell.child(child);
    }
    return index;
}

} // namespace mcpp
