#pragma once

#include "core/decomposition/QuadTree.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/planners/PlannerSettings.hpp"

#include <vector>

namespace mcpp {

// Rounds every passable class FOV down to fovMin * 2^k and gives each its quadtree level (spec 2).
// Only classes present in `presentValues` count. Throws PlanningError when no passable class is present.
[[nodiscard]] std::vector<RoundedFieldOfView>
roundFieldsOfView(const ClassTable& classes, const std::vector<std::int32_t>& presentValues);

// Builds the hierarchical quadtree of spec section 2 over a class grid.
class QuadTreeBuilder {
  public:
    [[nodiscard]] QuadTree build(const ClassGrid& grid, const ClassTable& classes,
                                 const PlannerSettings& settings,
                                 const ProgressReporter& progress = {}) const;
};

} // namespace mcpp
