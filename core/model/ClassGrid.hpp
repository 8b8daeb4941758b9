#pragma once

#include "core/model/MapPoint.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace mcpp {

// A pixel position in a ClassGrid.
struct PixelIndex {
    int column = 0;
    int row = 0;
};

// A land-cover raster in a metric frame. Row 0 is the northern edge; y decreases as rows increase.
struct ClassGrid {
    int columns = 0;
    int rows = 0;
    double originX = 0.0;     // x of the western edge of column 0
    double originY = 0.0;     // y of the northern edge of row 0
    double pixelWidth = 1.0;  // metres, > 0
    double pixelHeight = 1.0; // metres, > 0
    // How far true north lies counter-clockwise from the grid's north (+y) at the map's centre, in radians:
    // a conic or transverse projection far from its central meridian turns the grid (NRCan's Lambert grid
    // at 118 W: about -21 degrees). 0 where unknown. For directions in messages.
    double trueNorthRadians = 0.0;
    std::vector<std::int32_t> values; // row-major, columns * rows
    // Why a pixel is not part of the task area (0 where it is); may be empty.
    std::vector<std::uint8_t> outside;
    static constexpr std::uint8_t outsideNodata = 1;   // the raster's nodata
    static constexpr std::uint8_t outsideArea = 2;     // outside the area of interest
    static constexpr std::uint8_t outsideUnlisted = 3; // a class the table has no row for, left out
    static constexpr std::uint8_t inNoGoZone = 4;      // inside the area of interest, in a no-go zone
    // Farther from every aircraft's start than one flight reaches (set by the planner, never by io).
    static constexpr std::uint8_t beyondFlightReach = 5;
    // Whether the flag is the task area's edge a user drew (an area of interest or a no-go zone).
    [[nodiscard]] static constexpr bool isDrawnEdge(std::uint8_t flag) {
        return flag == outsideArea || flag == inNoGoZone;
    }

    [[nodiscard]] std::size_t index(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
               static_cast<std::size_t>(column);
    }
    [[nodiscard]] bool isOutside(int column, int row) const {
        return !outside.empty() && outside[index(column, row)] != 0;
    }
    [[nodiscard]] std::int32_t valueAt(int column, int row) const { return values[index(column, row)]; }
    [[nodiscard]] double width() const { return columns * pixelWidth; }
    [[nodiscard]] double height() const { return rows * pixelHeight; }
    [[nodiscard]] double minY() const { return originY - height(); }
    [[nodiscard]] double maxX() const { return originX + width(); }
    // The pixel a point lies in, or nothing off the raster (and for NaN).
    [[nodiscard]] std::optional<PixelIndex> pixelAt(MapPoint point) const {
        const double column = std::floor((point.x - originX) / pixelWidth);
        const double row = std::floor((originY - point.y) / pixelHeight);
        if (!(column >= 0.0 && row >= 0.0 && column < columns && row < rows))
            return std::nullopt;
        return PixelIndex{static_cast<int>(column), static_cast<int>(row)};
    }
};

} // namespace mcpp
