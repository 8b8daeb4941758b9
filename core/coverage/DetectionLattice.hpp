#pragma once

#include "core/coverage/LatticePosition.hpp"
#include "core/coverage/LatticeWindow.hpp"
#include "core/model/Cell.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/MapPoint.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace mcpp {

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
