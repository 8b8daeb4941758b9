#pragma once

#include "core/model/ClassTable.hpp"

#include <cstdint>
#include <map>
#include <optional>

namespace mcpp::ui {

// What the quadtree will make of one class's FOV, shown beside the table before any planning.
struct RoundedClassFieldOfView {
    double roundedMetres = 0.0;
    int level = 0; // 1 = top (largest cells)
};

// Spec section 2: Fd_min is the smallest FOV among traversable classes present in the raster; each FOV
// is rounded down to Fd_min * 2^k, and the level is 1 + log2(Fd_max / Fd). Classes that are obstacles
// or absent from the raster get no entry. With empty pixel counts every class counts as present.
[[nodiscard]] std::map<std::int32_t, RoundedClassFieldOfView>
roundFieldsOfView(const ClassTable& classes, const std::map<std::int32_t, std::int64_t>& pixelCounts);

} // namespace mcpp::ui
