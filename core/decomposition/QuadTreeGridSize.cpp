#include "core/decomposition/QuadTreeGridSize.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {

QuadTreeGridSize quadTreeGridSize(double width, double height, double fovMin, int levels) {
    QuadTreeGridSize size;
    size.topCellSize = 2.0 * fovMin * std::ldexp(1.0, levels - 1);
    // A map a hair over a whole number of top cells is that number: rounding noise adds no column.
    size.topColumns = std::max(1, static_cast<int>(std::ceil(width / size.topCellSize - 1e-9)));
    size.topRows = std::max(1, static_cast<int>(std::ceil(height / size.topCellSize - 1e-9)));
    size.bottomColumns = static_cast<std::int64_t>(size.topColumns) << (levels - 1);
    size.bottomRows = static_cast<std::int64_t>(size.topRows) << (levels - 1);
    return size;
}

} // namespace mcpp
