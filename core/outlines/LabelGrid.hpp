#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mcpp {

// A raster of integer labels on a square grid of the planning frame, row 0 at the north, anchored at its
// north-west corner. Pixels without a label hold noLabel.
struct LabelGrid {
    static constexpr std::int32_t noLabel = -1;

    int columns = 0;
    int rows = 0;
    double originX = 0.0; // planning metres
    double originY = 0.0;
    double pixelSize = 1.0;
    std::vector<std::int32_t> labels; // row-major

    [[nodiscard]] std::size_t index(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
               static_cast<std::size_t>(column);
    }
    [[nodiscard]] bool contains(int column, int row) const {
        return column >= 0 && row >= 0 && column < columns && row < rows;
    }
    [[nodiscard]] std::int32_t at(int column, int row) const {
        return contains(column, row) ? labels[index(column, row)] : noLabel;
    }
    [[nodiscard]] double x(double column) const { return originX + column * pixelSize; }
    [[nodiscard]] double y(double row) const { return originY - row * pixelSize; }
};

} // namespace mcpp
