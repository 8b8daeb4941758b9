#include "core/model/GridOccupancy.hpp"

#include <stdexcept>

namespace mcpp {

GridOccupancy::GridOccupancy(int columns, int rows, const std::vector<CellRecord>& cells)
    : columns_(columns), rows_(rows) {
    const std::uint64_t places = static_cast<std::uint64_t>(columns) * static_cast<std::uint64_t>(rows);
    places_ = RankedIdSet(0, places);
    std::uint64_t previous = 0;
    for (std::size_t id = 0; id < cells.size(); ++id) {
        const CellRecord& cell = cells[id];
        if (cell.span != 1 || cell.column < 0 || cell.row < 0 || cell.column >= columns || cell.row >= rows)
            throw std::invalid_argument("a grid occupancy of a cell that is not one place of the grid");
        const std::uint64_t place =
            static_cast<std::uint64_t>(cell.row) * static_cast<std::uint64_t>(columns) +
            static_cast<std::uint64_t>(cell.column);
        if (id > 0 && place <= previous)
            throw std::invalid_argument("a grid occupancy of cells not listed row by row");
        previous = place;
        places_.insert(place);
    }
    places_.countRanks();
}

} // namespace mcpp
