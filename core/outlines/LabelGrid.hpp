#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace mcpp {

// A raster of integer labels on a square grid of the planning frame, row 0 at the north, anchored at its
// north-west corner. Pixels without a label hold noLabel. Labels are robots (and a few negative marks), so
// 16 bits hold them: a large plan's grid has tens of millions of pixels.
struct LabelGrid {
    using Label = std::int16_t;
    static constexpr Label noLabel = -1;
    static constexpr int largestLabel = std::numeric_limits<Label>::max();

    int columns = 0;
    int rows = 0;
    double originX = 0.0; // planning metres
    double originY = 0.0;
    double pixelSize = 1.0;
    std::vector<Label> labels; // row-major

    [[nodiscard]] std::size_t index(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
               static_cast<std::size_t>(column);
    }
    [[nodiscard]] bool contains(int column, int row) const {
        return column >= 0 && row >= 0 && column < columns && row < rows;
    }
    [[nodiscard]] Label at(int column, int row) const {
        return contains(column, row) ? labels[index(column, row)] : noLabel;
    }
    [[nodiscard]] double x(double column) const { return originX + column * pixelSize; }
    [[nodiscard]] double y(double row) const { return originY - row * pixelSize; }
};

} // namespace mcpp
