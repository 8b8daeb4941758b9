#pragma once

#include <vector>

namespace mcpp {

// What a plan's passes see, cell by cell of the sub-cell lattice (half a grid cell): the chance a target
// there has been seen, and the chance the plan had to reach. NaN where no free sub-cell lies or no robot
// covers it.
struct DetectionGrid {
    double originX = 0.0; // western edge
    double originY = 0.0; // northern edge
    double cellSize = 1.0;
    int columns = 0;
    int rows = 0;
    std::vector<float> probability; // row-major from the north-west
    std::vector<float> required;    // the required probability, 0 where the land cover hides targets
};

} // namespace mcpp
