#pragma once

#include "core/model/Cell.hpp"
#include "core/model/GridFrame.hpp"
#include "core/model/NeighbourTopology.hpp"

#include <vector>

namespace mcpp {

// Neighbours on a single-level grid (every cell of span 1): cells side by side whose free sub-cells face
// each other across the shared side, so a robot can pass from one to the other.
[[nodiscard]] NeighbourTopology gridNeighbours(const GridFrame& frame, const std::vector<Cell>& cells);

} // namespace mcpp
