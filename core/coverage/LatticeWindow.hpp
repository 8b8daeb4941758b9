#pragma once

#include "core/coverage/LatticePosition.hpp"

#include <cstddef>

namespace mcpp {

// A rectangle of lattice positions, with row-major indices inside it.
struct LatticeWindow {
    int column = 0;
    int row = 0;
    int columns = 0;
    int rows = 0;

    [[nodiscard]] bool contains(LatticePosition position) const {
        return position.column >= column && position.row >= row && position.column < column + columns &&
               position.row < row + rows;
    }
    [[nodiscard]] std::size_t index(LatticePosition position) const {
        return static_cast<std::size_t>(position.row - row) * static_cast<std::size_t>(columns) +
               static_cast<std::size_t>(position.column - column);
    }
    [[nodiscard]] std::size_t size() const {
        return static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
    }
};

} // namespace mcpp
