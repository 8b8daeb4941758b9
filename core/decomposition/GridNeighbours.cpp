#include "core/decomposition/GridNeighbours.hpp"

#include <algorithm>

namespace mcpp {
namespace {

bool facing(const Cell& a, SubCell first, const Cell& b, SubCell second) {
    return a.isFree(first) && b.isFree(second);
}

bool passableEastward(const Cell& west, const Cell& east) {
    return facing(west, SubCell::NorthEast, east, SubCell::NorthWest) ||
           facing(west, SubCell::SouthEast, east, SubCell::SouthWest);
}

bool passableSouthward(const Cell& north, const Cell& south) {
    return facing(north, SubCell::SouthWest, south, SubCell::NorthWest) ||
           facing(north, SubCell::SouthEast, south, SubCell::NorthEast);
}

} // namespace

NeighbourTopology gridNeighbours(const GridFrame& frame, const std::vector<Cell>& cells) {
    const auto columns = static_cast<std::size_t>(frame.columns);
    std::vector<int> idAt(columns * static_cast<std::size_t>(frame.rows), -1);
    for (std::size_t id = 0; id < cells.size(); ++id)
        idAt[static_cast<std::size_t>(cells[id].row) * columns + static_cast<std::size_t>(cells[id].column)] =
            static_cast<int>(id);
    const auto at = [&](int column, int row) {
        if (column >= frame.columns || row >= frame.rows)
            return -1;
        return idAt[static_cast<std::size_t>(row) * columns + static_cast<std::size_t>(column)];
    };
    std::vector<std::vector<int>> lists(cells.size());
    const auto link = [&](std::size_t a, int b) {
        lists[a].push_back(b);
        lists[static_cast<std::size_t>(b)].push_back(static_cast<int>(a));
    };
    for (std::size_t id = 0; id < cells.size(); ++id) {
        const Cell& cell = cells[id];
        const int east = at(cell.column + 1, cell.row);
        if (east >= 0 && passableEastward(cell, cells[static_cast<std::size_t>(east)]))
            link(id, east);
        const int south = at(cell.column, cell.row + 1);
        if (south >= 0 && passableSouthward(cell, cells[static_cast<std::size_t>(south)]))
            link(id, south);
    }
    std::vector<int> offsets{0};
    std::vector<int> neighbours;
    for (auto& list : lists) {
        std::sort(list.begin(), list.end());
        neighbours.insert(neighbours.end(), list.begin(), list.end());
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    return NeighbourTopology(std::move(offsets), std::move(neighbours));
}

} // namespace mcpp
