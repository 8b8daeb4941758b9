#pragma once

namespace mcpp {

// Where a decomposition's bottom grid lies: squares of `bottomCellSize` metres, row 0 at the northern edge,
// anchored at the north-west corner (the raster origin).
struct GridFrame {
    double originX = 0.0;
    double originY = 0.0;
    double bottomCellSize = 1.0;
    int columns = 0;
    int rows = 0;
    int levels = 1; // quadtree levels; 1 for a single-level grid

    [[nodiscard]] double x(int column) const { return originX + column * bottomCellSize; }
    [[nodiscard]] double y(int row) const { return originY - row * bottomCellSize; }
};

} // namespace mcpp
