#pragma once

#include "core/decomposition/DecompositionOptions.hpp"
#include "core/decomposition/FieldOfViewRounding.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/ProgressReporter.hpp"

#include <vector>

namespace mcpp {

// Builds the hierarchical quadtree of spec section 2 over a class grid.
class QuadTreeBuilder {
  public:
    [[nodiscard]] QuadTree build(const ClassGrid& grid, const ClassTable& classes,
                                 const DecompositionOptions& options,
                                 const ProgressReporter& progress = {}) const;
};

} // namespace mcpp
