#pragma once

#include "core/decomposition/QuadCell.hpp"
#include "core/model/RoundedFieldOfView.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// The hierarchical quadtree of spec section 2. Cells are stored flat; active cells tile the task area.
struct QuadTree {
    int levels = 0;           // l
    double fovMin = 0.0;      // smallest rounded FOV: the bottom level's sub-cell side
    double topCellSize = 0.0; // Cs_1 = 2 * fovMin * 2^(l - 1)
    double originX = 0.0;     // western edge of the top grid: the raster origin, or a top cell of the
                              // raster's own grid of them where the land is in part of it
    double originY = 0.0;     // northern edge of the top grid
    int topColumns = 0;
    int topRows = 0;
    double passableAreaSquareMetres = 0.0; // all passable pixels, in any cell
    // The top level's cells come first, row-major; children follow their parents.
    std::vector<QuadCell> cells;
    std::vector<int> activeCells; // indices into cells, in a fixed order; activeIndex points back here
    std::vector<RoundedFieldOfView> roundedFieldsOfView;

    [[nodiscard]] double cellSize(int level) const {
        return topCellSize / static_cast<double>(1 << (level - 1));
    }
    [[nodiscard]] int columnsAt(int level) const { return topColumns << (level - 1); }
    [[nodiscard]] int rowsAt(int level) const { return topRows << (level - 1); }
    [[nodiscard]] const QuadCell& active(int activeIndex) const {
        return cells[static_cast<std::size_t>(activeCells[static_cast<std::size_t>(activeIndex)])];
    }
    [[nodiscard]] std::size_t activeCount() const { return activeCells.size(); }
    // The leaf holding the point, or -1 outside the top grid.
    [[nodiscard]] int leafAt(double x, double y) const;
};

} // namespace mcpp
