#pragma once

#include <cstdint>

namespace mcpp {

enum class CellState : std::uint8_t {
    Auxiliary, // split into four children; no land cover of its own
    Active,    // a leaf that is part of the task area
    Blocked,   // a leaf of obstacles or of pixels outside the task area
};

// One square of the hierarchical quadtree. Level 1 is the top. 64 bytes: a large map's quadtree holds tens
// of millions of them, written and read once each while the cells are made.
struct QuadCell {
    std::uint8_t level = 1; // at most mostQuadTreeLevels (Cell.hpp)
    CellState state = CellState::Auxiliary;
    int row = 0;    // row in its level's grid, 0 at the northern edge
    int column = 0; // column in its level's grid, 0 at the western edge
    // A split cell's four children are the cells firstChild to firstChild + 3: north-west, north-east,
    // south-east, south-west. -1 for a leaf.
    int firstChild = -1;
    int activeIndex = -1;        // index among active cells, -1 otherwise
    std::int32_t classValue = 0; // majority passable class of an active cell
    double minX = 0.0;
    double minY = 0.0;
    double size = 0.0; // side in metres; the four sub-cells have side size / 2 (the level's FOV)
    double speedMetresPerSecond = 0.0;     // harmonic mean over its passable pixels
    double passableAreaSquareMetres = 0.0; // area of its passable pixels

    [[nodiscard]] int child(int which) const { return firstChild + which; }

    [[nodiscard]] double maxX() const { return minX + size; }
    [[nodiscard]] double maxY() const { return minY + size; }
    [[nodiscard]] double centreX() const { return minX + size / 2.0; }
    [[nodiscard]] double centreY() const { return minY + size / 2.0; }
    [[nodiscard]] double fieldOfView() const { return size / 2.0; }
};
static_assert(sizeof(QuadCell) == 64);

} // namespace mcpp
