#pragma once

#include "core/outlines/LabelGrid.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// The 4-connected patches of equal labels in a label grid, numbered in the order of their first pixel (row
// by row from the north-west). Kept as runs of equal labels along rows rather than a number per pixel: a
// large plan's label grid holds tens of millions of pixels and far fewer runs.
class LabelPatches {
  public:
    explicit LabelPatches(const LabelGrid& grid);

    [[nodiscard]] int count() const { return static_cast<int>(labels_.size()); }
    [[nodiscard]] LabelGrid::Label label(int patch) const { return labels_[static_cast<std::size_t>(patch)]; }
    [[nodiscard]] std::int64_t pixels(int patch) const { return pixels_[static_cast<std::size_t>(patch)]; }
    // The patch of a pixel; -1 for a pixel with no label or outside the grid.
    [[nodiscard]] int patchAt(int column, int row) const;

  private:
    struct Run {
        int firstColumn = 0;
        int endColumn = 0; // one past the last
        int patch = 0;     // while building: the union-find parent, a run index
    };

    void findRuns(const LabelGrid& grid);
    void joinRowToTheOneAbove(const LabelGrid& grid, int row);
    int root(int run);
    void numberPatches(const LabelGrid& grid);

    std::vector<std::size_t> rowStart_; // runs of row r: rowStart_[r] .. rowStart_[r + 1] - 1
    std::vector<Run> runs_;
    std::vector<LabelGrid::Label> labels_;
    std::vector<std::int64_t> pixels_;
};

} // namespace mcpp
