#pragma once

#include "core/coverage/DetectionLattice.hpp"

#include <cstdlib>

namespace mcpp {

// A straight pass a detection planner chose: from one lattice position to another in the same row
// (horizontal) or column, every position between them included.
struct DetectionSegment {
    LatticePosition from;
    LatticePosition to;
    bool horizontal = true;

    [[nodiscard]] int length() const {
        return horizontal ? std::abs(to.column - from.column) + 1 : std::abs(to.row - from.row) + 1;
    }
};

} // namespace mcpp
