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
    // Each link found twice, once to count and once to place: lists of their own per cell would cost a
    // vector and a heap block a cell (several gigabytes on a map of tens of millions of cells).
    const auto forEachLink = [&](auto&& visit) {
        for (std::size_t id = 0; id < cells.size(); ++id) {
            const Cell& cell = cells[id];
            const int east = at(cell.column + 1, cell.row);
            if (east >= 0 && passableEastward(cell, cells[static_cast<std::size_t>(east)]))
                visit(id, static_cast<std::size_t>(east));
            const int south = at(cell.column, cell.row + 1);
            if (south >= 0 && passableSouthward(cell, cells[static_cast<std::size_t>(south)]))
                visit(id, static_cast<std::size_t>(south));
        }
    };
    // Counted at each cell's place, summed to each cell's end, then filled backwards to each one's start.
    std::vector<int> offsets(cells.size() + 1, 0);
    forEachLink([&](std::size_t a, std::size_t b) {
        ++offsets[a];
        ++offsets[b];
    });
    for (std::size_t i = 1; i < offsets.size(); ++i)
        offsets[i] += offsets[i - 1];
    std::vector<int> neighbours(static_cast<std::size_t>(offsets.back()));
    forEachLink([&](std::size_t a, std::size_t b) {
        neighbours[static_cast<std::size_t>(--offsets[a])] = static_cast<int>(b);
        neighbours[static_cast<std::size_t>(--offsets[b])] = static_cast<int>(a);
    });
    for (std::size_t id = 0; id < cells.size(); ++id)
        std::sort(neighbours.begin() + offsets[id], neighbours.begin() + offsets[id + 1]);
    return NeighbourTopology(std::move(offsets), std::move(neighbours));
}

} // namespace mcpp
