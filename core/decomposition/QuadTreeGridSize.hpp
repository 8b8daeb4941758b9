#pragma once

#include <cstdint>

namespace mcpp {

// The quadtree's grid over a map: whole top cells of 2^(levels - 1) smallest cells (2 x fovMin) across it.
// One rule for the decomposition and for estimates made before planning (the window's size warning).
// levels: 1 to mostSizedLevels.
struct QuadTreeGridSize {
    double topCellSize = 0.0;
    int topColumns = 1;
    int topRows = 1;
    std::int64_t bottomColumns = 1;
    std::int64_t bottomRows = 1;
};

// Past this many levels the grid's size in bottom cells would overflow.
inline constexpr int mostSizedLevels = 20;

[[nodiscard]] QuadTreeGridSize quadTreeGridSize(double width, double height, double fovMin, int levels);

} // namespace mcpp
