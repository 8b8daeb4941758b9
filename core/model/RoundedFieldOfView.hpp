#pragma once

#include <cstdint>

namespace mcpp {

// A class's FOV rounded down to fovMin * 2^k (spec 2) and the quadtree level whose sub-cells have that side.
struct RoundedFieldOfView {
    std::int32_t classValue = 0;
    double originalMetres = 0.0;
    double roundedMetres = 0.0;
    int level = 0;
};

} // namespace mcpp
