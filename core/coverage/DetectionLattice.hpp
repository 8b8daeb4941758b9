#pragma once

#include "core/model/Cell.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/MapPoint.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace mcpp {

// A place on the sub-cell lattice: column east, row south, from the grid's north-west corner.
struct LatticePosition {
    int column = 0;
    int row = 0;
};

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

// The free sub-cells of a single-level grid as a lattice of squares of half a cell: where a detection
// planner's passes run and what they see.
class DetectionLattice {
  public:
    explicit DetectionLattice(const CellGraph& graph);

    [[nodiscard]] LatticeWindow whole() const { return {0, 0, columns_, rows_}; }
    [[nodiscard]] double cellSize() const { return cellSize_; }
    [[nodiscard]] double originX() const { return originX_; }
    [[nodiscard]] double originY() const { return originY_; }
    // The cell whose free sub-cell lies at the position, or -1 (blocked, no cell, off the lattice).
    [[nodiscard]] int cellAt(LatticePosition position) const;
    [[nodiscard]] MapPoint centre(LatticePosition position) const;
    // The position whose centre the point is, or nothing for a point off every centre.
    [[nodiscard]] std::optional<LatticePosition> centreAt(MapPoint point) const;
    [[nodiscard]] static SubCell subCellAt(LatticePosition position);

  private:
    double originX_ = 0.0;
    double originY_ = 0.0;
    double cellSize_ = 1.0;
    int columns_ = 0;
    int rows_ = 0;
    std::vector<int> cellOfPosition_; // whole() order: the cell holding the free sub-cell there, or -1
};

} // namespace mcpp
