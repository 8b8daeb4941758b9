#pragma once

#include "core/model/CellRecord.hpp"

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

    [[nodiscard]] bool empty() const { return words_.empty(); }
    // Whether a cell lies at the place (false off the grid).
    [[nodiscard]] bool holds(int column, int row) const {
        if (column < 0 || row < 0 || column >= columns_ || row >= rows_)
            return false;
        const std::uint64_t place = placeOf(column, row);
        return (words_[place / 64U] >> (place % 64U) & 1U) != 0;
    }
    // The cell at the place, or -1 where there is none or the place is off the grid.
    [[nodiscard]] int idAt(int column, int row) const {
        if (column < 0 || row < 0 || column >= columns_ || row >= rows_)
            return -1;
        const std::uint64_t place = placeOf(column, row);
        const std::uint64_t word = words_[place / 64U];
        const std::uint64_t bit = std::uint64_t{1} << (place % 64U);
        if ((word & bit) == 0)
            return -1;
        return static_cast<int>(heldBefore_[place / 64U] + bitsSet(word & (bit - 1)));
    }

    // Counted in a few arithmetic steps: the build targets every x86-64, whose first chips lack a
    // popcount instruction, and the library call that stands in for it took 5 % of a large map's run.
    [[nodiscard]] static std::uint32_t bitsSet(std::uint64_t word) {
        word -= (word >> 1U) & 0x5555555555555555ULL;
        word = (word & 0x3333333333333333ULL) + ((word >> 2U) & 0x3333333333333333ULL);
        word = (word + (word >> 4U)) & 0x0f0f0f0f0f0f0f0fULL;
        return static_cast<std::uint32_t>((word * 0x0101010101010101ULL) >> 56U);
    }

  private:
    [[nodiscard]] std::uint64_t placeOf(int column, int row) const {
        return static_cast<std::uint64_t>(row) * static_cast<std::uint64_t>(columns_) +
               static_cast<std::uint64_t>(column);
    }

    int columns_ = 0;
    int rows_ = 0;
    std::vector<std::uint64_t> words_;
    std::vector<std::uint32_t> heldBefore_; // held places in the words before each
};

} // namespace mcpp
