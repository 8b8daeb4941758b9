#include "core/decomposition/QuadTreeGridSize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {

QuadTreeGridSize quadTreeGridSize(double width, double height, double fovMin, int levels) {
    QuadTreeGridSize size;
    size.topCellSize = 2.0 * fovMin * std::ldexp(1.0, levels - 1);
    // A map a hair over a whole number of top cells is that number: rounding noise adds no column.
    // Counts past what an int holds (a field of view of micrometres) stop there: such a grid is refused
    // anyway.
    const auto topCells = [&](double length) {
        const double count = std::ceil(length / size.topCellSize - 1e-9);
        return static_cast<int>(std::clamp(count, 1.0, static_cast<double>(std::numeric_limits<int>::max())));
    };
    size.topColumns = topCells(width);
    size.topRows = topCells(height);
    size.bottomColumns = static_cast<std::int64_t>(size.topColumns) << (levels - 1);
    size.bottomRows = static_cast<std::int64_t>(size.topRows) << (levels - 1);
    return size;
}

} // namespace mcpp
