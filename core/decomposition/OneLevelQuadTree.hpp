#pragma once

#include "core/model/CellRecord.hpp"
#include "core/model/GridFrame.hpp"
#include "core/model/RoundedFieldOfView.hpp"

#include <vector>

namespace mcpp {

// A quadtree of a single level, where every class present needs the same cell size: a grid of its bottom
// cells. Made straight from the sample counts, listed as the tree lists its leaves (row by row), it spares
// the tree's 64-byte nodes (4.4 GB on a map of 69 million cells) and their topology search.
struct OneLevelQuadTree {
    GridFrame frame;
    std::vector<CellRecord> cells; // the active leaves, row by row
    std::vector<RoundedFieldOfView> roundedFieldsOfView;
    double passableAreaSquareMetres = 0.0; // all passable pixels, in any cell
    // What storing the cells' areas as floats changed, added to the total as the tree's graph adds it.
    double areaRounding = 0.0;
};

} // namespace mcpp
