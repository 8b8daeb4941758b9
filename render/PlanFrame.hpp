#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/Plan.hpp"

#include <vector>

namespace mcpp::render {

// The part of the raster a picture of plans shows, as a grid of the raster's pixels holding no values (its
// extent alone): the whole raster, or, where the plans cover a small part of it (an area of interest), the
// pixels around their cells with a margin of a fifth of their extent on each side (at least a twentieth of
// the raster's). Null plans are skipped.
[[nodiscard]] ClassGrid planFrame(const ClassGrid& grid, const std::vector<const Plan*>& plans);

} // namespace mcpp::render
