#pragma once

#include "core/model/Plan.hpp"
#include "core/outlines/LabelGrid.hpp"
#include "core/outlines/OutlinePolygon.hpp"

#include <vector>

namespace mcpp {

// A plan's regions on the sub-cell grid (regionLabels) and their traced outlines (traceOutlines): what
// the vector exports, regions.tif and the map drawing all start from, so it is made once per plan.
struct RegionOutlines {
    LabelGrid labels;
    std::vector<OutlinePolygon> polygons;
};

[[nodiscard]] RegionOutlines regionOutlines(const Plan& plan);

} // namespace mcpp
