#pragma once

namespace mcpp {

// A place on the sub-cell lattice: column east, row south, from the grid's north-west corner.
struct LatticePosition {
    int column = 0;
    int row = 0;
};

} // namespace mcpp
