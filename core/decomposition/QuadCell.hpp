#pragma once

#include <array>
#include <cstdint>

namespace mcpp {

enum class CellState : std::uint8_t {
    Auxiliary, // split into four children; no land cover of its own
    Active,    // a leaf that is part of the task area
    Blocked,   // a leaf of obstacles or of pixels outside the task area
};

// One square of the hierarchical quadtree. Level 1 is the top.
struct QuadCell {
    int level = 1;
    int row = 0;    // row in its level's grid, 0 at the northern edge
    int column = 0; // column in its level's grid, 0 at the western edge
    double minX = 0.0;
    double minY = 0.0;
    double size = 0.0; // side in metres; the four sub-cells have side size / 2 (the level's FOV)
    CellState state = CellState::Auxiliary;
    int parent = -1;
    std::array<int, 4> children{-1, -1, -1, -1}; // north-west, north-east, south-east, south-west
    int activeIndex = -1;                        // index among active cells, -1 otherwise
    std::int32_t classValue = 0;                 // majority passable class of an active cell
    double speedMetresPerSecond = 0.0;           // harmonic mean over its passable pixels
    double obstacleFraction = 0.0;               // obstacle + outside share of its pixels
    double passableAreaSquareMetres = 0.0;       // area of its passable pixels

    [[nodiscard]] double maxX() const { return minX + size; }
    [[nodiscard]] double maxY() const { return minY + size; }
    [[nodiscard]] double centreX() const { return minX + size / 2.0; }
    [[nodiscard]] double centreY() const { return minY + size / 2.0; }
    [[nodiscard]] double fieldOfView() const { return size / 2.0; }
};

} // namespace mcpp
