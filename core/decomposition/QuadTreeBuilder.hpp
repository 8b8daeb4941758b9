#pragma once

#include "core/decomposition/DecompositionOptions.hpp"
#include "core/decomposition/FieldOfViewRounding.hpp"
#include "core/decomposition/OneLevelQuadTree.hpp"
#include "core/decomposition/QuadTree.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/ProgressReporter.hpp"

#include <variant>
#include <vector>

namespace mcpp {

// The leaves a decomposition plans on: the quadtree, or the grid of a quadtree of one level.
using QuadTreeLeaves = std::variant<QuadTree, OneLevelQuadTree>;

// Builds the hierarchical quadtree of spec section 2 over a class grid.
class QuadTreeBuilder {
  public:
    [[nodiscard]] QuadTree build(const ClassGrid& grid, const ClassTable& classes,
                                 const DecompositionOptions& options,
                                 const ProgressReporter& progress = {}) const;
    // The same leaves; where the tree has one level, as the grid of its cells without the tree's nodes.
    [[nodiscard]] QuadTreeLeaves buildLeaves(const ClassGrid& grid, const ClassTable& classes,
                                             const DecompositionOptions& options,
                                             const ProgressReporter& progress = {}) const;
};

} // namespace mcpp
