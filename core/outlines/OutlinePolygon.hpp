#pragma once

#include <cstdint>
#include <vector>

namespace mcpp {

// A corner of the label grid: column and row of the pixel whose north-west corner it is.
struct GridVertex {
    int column = 0;
    int row = 0;

    friend bool operator==(const GridVertex&, const GridVertex&) = default;
};

// A closed ring of grid vertices at its corners only (the first vertex is not repeated at the end).
// Exteriors run counter-clockwise on the map (north up), holes clockwise; no ring passes a vertex twice.
using OutlineRing = std::vector<GridVertex>;

// One 4-connected patch of pixels of the same label: its outline and the outlines of its holes.
struct OutlinePolygon {
    std::int32_t label = 0;
    OutlineRing exterior;
    std::vector<OutlineRing> holes;
    std::int64_t pixels = 0; // pixels in the patch, so area = pixels x pixel size squared
};

// Twice the signed area of a ring in pixel units, positive when counter-clockwise on the map.
[[nodiscard]] std::int64_t doubledSignedArea(const OutlineRing& ring);

} // namespace mcpp
