#pragma once

#include "core/model/Plan.hpp"
#include "core/outlines/LabelGrid.hpp"

#include <cstdint>

namespace mcpp {

// The label of passable land no robot covers (cells the plan names with robot -1).
inline constexpr std::int32_t unreachableLabel = -2;

// The plan's regions on a grid of sub-cells (half the bottom cell): the robot covering each free sub-cell,
// unreachableLabel for a free sub-cell nobody covers and for sub-cells whose centres lie on the passable land
// left out beyond every flight's reach (Plan::landBeyondReach), LabelGrid::noLabel elsewhere (obstacles,
// outside the map, blocked sub-cells), on the box around the plan's cells, widened towards that land by at
// most 16 million sub-cells. Exports draw region polygons and regions.tif from this one grid, so they agree.
[[nodiscard]] LabelGrid regionLabels(const Plan& plan);

// Any labels of cells on the same sub-cell grid: each free sub-cell of a cell takes the cell's label; cells
// labelled LabelGrid::noLabel stay empty. `cropped` keeps only the box around the labelled cells (a few
// cells of a large map need not cost a grid of the whole map).
[[nodiscard]] LabelGrid cellLabels(const CellGraph& graph, const std::vector<std::int32_t>& labelOfCell,
                                   bool cropped);

// The cells each robot of a plan simulated over time took over from others, labelled by robot on a grid
// cropped to them: what exports and the map outline. An empty grid when no robot took any over.
[[nodiscard]] LabelGrid takenOverLabels(const Plan& plan);

} // namespace mcpp
