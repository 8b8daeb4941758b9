#pragma once

#include "core/coverage/DetectionLattice.hpp"

namespace mcpp {

// A straight pass a detection planner chose: from one lattice position to another in the same row
// (horizontal) or column, every position between them included.
struct DetectionSegment {
    LatticePosition from;
    LatticePosition to;
    bool horizontal = true;
};

} // namespace mcpp
