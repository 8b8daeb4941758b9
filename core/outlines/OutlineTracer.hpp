#pragma once

#include "core/outlines/LabelGrid.hpp"
#include "core/outlines/OutlinePolygon.hpp"

#include <vector>

namespace mcpp {

// The outlines of every patch of equal labels (pixels joined through their sides), found by walking the
// boundary between pixels: time linear in the pixels and the boundary's length, no polygon unions.
// Where two pixels of a label meet only at a corner they belong to different patches, so rings never cross;
// a ring that would touch itself at such a corner is split there into a ring and a hole, as the simple
// features rules want. Patches come in the order of their first pixel (row by row from the north-west),
// and each walk begins at the first pixel side of it met in that order, its ring at the first corner it
// turns at (a ring split off at a pinched corner, at that corner): the same rings, vertex for vertex, from
// one run to the next.
[[nodiscard]] std::vector<OutlinePolygon> traceOutlines(const LabelGrid& grid);

} // namespace mcpp
