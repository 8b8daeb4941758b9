#pragma once

#include "core/model/CellRecord.hpp"
#include "core/model/RankedIdSet.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// Which places of a grid hold a cell, for a graph whose cells are that grid's places listed row by row:
// a cell's id is the number of held places before it. A bit a place and a count every 64 places, about
// 0.19 bytes a place, where neighbour lists take 20 bytes a cell (1.4 GB on a map of 69 million cells).
class GridOccupancy {
  public:
    GridOccupancy() = default;
    // cells: span-1 cells on a columns x rows grid, listed row by row, each place at most once.
    GridOccupancy(int columns, int rows, const std::vector<CellRecord>& cells);

    [[nodiscard]] bool empty() const { return !places_.hasRoom(); }
    // Whether a cell lies at the place (false off the grid).
    [[nodiscard]] bool holds(int column, int row) const {
        return onGrid(column, row) && places_.holds(placeOf(column, row));
    }
    // The cell at the place, or -1 where there is none or the place is off the grid.
    [[nodiscard]] int idAt(int column, int row) const {
        return onGrid(column, row) ? places_.rankOf(placeOf(column, row)) : -1;
    }

  private:
    [[nodiscard]] std::uint64_t placeOf(int column, int row) const {
        return static_cast<std::uint64_t>(row) * static_cast<std::uint64_t>(columns_) +
               static_cast<std::uint64_t>(column);
    }

    [[nodiscard]] bool onGrid(int column, int row) const {
        return column >= 0 && row >= 0 && column < columns_ && row < rows_;
    }

    int columns_ = 0;
    int rows_ = 0;
    RankedIdSet places_; // a cell's id is its place's rank
};

} // namespace mcpp
