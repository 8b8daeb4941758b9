#pragma once

#include <vector>

namespace mcpp {

// Land on a raster's pixel grid, as runs of pixels along its rows: a few runs a row where the land is a few
// intervals, so a map of tens of millions of pixels typically holds it in kilobytes. Row 0 is the northern
// edge.
struct PixelRuns {
    struct Run {
        int row = 0;
        int firstColumn = 0;
        int endColumn = 0; // one past the last
    };
    double originX = 0.0; // the raster's frame, planning metres
    double originY = 0.0;
    double pixelWidth = 1.0;
    double pixelHeight = 1.0;
    std::vector<Run> runs; // by row, then column

    [[nodiscard]] bool empty() const { return runs.empty(); }
};

} // namespace mcpp
