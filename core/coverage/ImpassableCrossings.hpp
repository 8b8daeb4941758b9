#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/RegionAllocation.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

namespace mcpp {

// A cell a robot covers although some of its free sub-cells hold impassable pixels (obstacle classes, or
// pixels outside the task area): the blocked threshold kept it, so the path crosses that land.
struct ImpassableCrossing {
    int cell = -1;
    double impassableShare = 0.0; // of the pixels whose centres lie in its free sub-cells
};

// Key of impassableClassesIn for pixels outside the task area (nodata, outside the area of interest, no-go).
inline constexpr std::int32_t outsideTaskArea = std::numeric_limits<std::int32_t>::min();

// The covered cells that cross impassable land, by cell id; at most `most` of them.
[[nodiscard]] std::vector<ImpassableCrossing>
impassableCrossings(const CellGraph& cells, const RegionAllocation& regions, const ClassGrid& grid,
                    const ClassTable& classes, std::size_t most = std::numeric_limits<std::size_t>::max());

// The impassable pixels of one cell's free sub-cells by class (outsideTaskArea for pixels outside the task
// area), counted by their centres, and in `pixels` all the pixels counted there.
[[nodiscard]] std::map<std::int32_t, std::int64_t>
impassableClassesIn(const Cell& cell, const ClassGrid& grid, const ClassTable& classes, std::int64_t& pixels);

} // namespace mcpp
