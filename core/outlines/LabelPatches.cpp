#include "core/outlines/LabelPatches.hpp"

#include <algorithm>

namespace mcpp {

LabelPatches::LabelPatches(const LabelGrid& grid) {
    findRuns(grid);
    for (int row = 1; row < grid.rows; ++row)
        joinRowToTheOneAbove(grid, row);
    numberPatches(grid);
}

void LabelPatches::findRuns(const LabelGrid& grid) {
    rowStart_.reserve(static_cast<std::size_t>(grid.rows) + 1);
    for (int row = 0; row < grid.rows; ++row) {
        rowStart_.push_back(runs_.size());
        int column = 0;
        while (column < grid.columns) {
            const LabelGrid::Label label = grid.labels[grid.index(column, row)];
            const int first = column;
            while (column < grid.columns && grid.labels[grid.index(column, row)] == label)
                ++column;
            if (label != LabelGrid::noLabel)
                runs_.push_back(Run{first, column, static_cast<int>(runs_.size())});
        }
    }
    rowStart_.push_back(runs_.size());
}

// Runs of one label that share a stretch of columns in neighbouring rows touch through a side.
void LabelPatches::joinRowToTheOneAbove(const LabelGrid& grid, int row) {
    std::size_t above = rowStart_[static_cast<std::size_t>(row) - 1];
    const std::size_t aboveEnd = rowStart_[static_cast<std::size_t>(row)];
    for (std::size_t here = aboveEnd; here < rowStart_[static_cast<std::size_t>(row) + 1]; ++here) {
        while (above < aboveEnd && runs_[above].endColumn <= runs_[here].firstColumn)
            ++above;
        const LabelGrid::Label label = grid.labels[grid.index(runs_[here].firstColumn, row)];
        for (std::size_t other = above; other < aboveEnd && runs_[other].firstColumn < runs_[here].endColumn;
             ++other) {
            if (grid.labels[grid.index(runs_[other].firstColumn, row - 1)] != label)
                continue;
            const int a = root(static_cast<int>(here));
            const int b = root(static_cast<int>(other));
            // The earlier run stays the root, so a patch's root is its first run.
            runs_[static_cast<std::size_t>(std::max(a, b))].patch = std::min(a, b);
        }
    }
}

int LabelPatches::root(int run) {
    int top = run;
    while (runs_[static_cast<std::size_t>(top)].patch != top)
        top = runs_[static_cast<std::size_t>(top)].patch;
    while (runs_[static_cast<std::size_t>(run)].patch != top) { // shorten the way for the next look-up
        const int next = runs_[static_cast<std::size_t>(run)].patch;
        runs_[static_cast<std::size_t>(run)].patch = top;
        run = next;
    }
    return top;
}

// A patch's root is its smallest run, the first in row order, which holds its first pixel: numbering roots
// as they come numbers patches in the order of their first pixel.
void LabelPatches::numberPatches(const LabelGrid& grid) {
    for (std::size_t run = 0; run < runs_.size(); ++run)
        runs_[run].patch = root(static_cast<int>(run)); // every run now points at its root
    std::size_t row = 0;
    for (std::size_t run = 0; run < runs_.size(); ++run) {
        while (rowStart_[row + 1] <= run)
            ++row;
        Run& current = runs_[run];
        if (current.patch == static_cast<int>(run)) {
            current.patch = static_cast<int>(labels_.size());
            labels_.push_back(grid.labels[grid.index(current.firstColumn, static_cast<int>(row))]);
            pixels_.push_back(0);
        } else {
            current.patch = runs_[static_cast<std::size_t>(current.patch)].patch; // the root, numbered before
        }
        pixels_[static_cast<std::size_t>(current.patch)] += current.endColumn - current.firstColumn;
    }
}

int LabelPatches::patchAt(int column, int row) const {
    if (row < 0 || static_cast<std::size_t>(row) + 1 >= rowStart_.size())
        return -1;
    const auto begin = runs_.begin() + static_cast<std::ptrdiff_t>(rowStart_[static_cast<std::size_t>(row)]);
    const auto end =
        runs_.begin() + static_cast<std::ptrdiff_t>(rowStart_[static_cast<std::size_t>(row) + 1]);
    const auto after = std::upper_bound(begin, end, column,
                                        [](int value, const Run& run) { return value < run.firstColumn; });
    if (after == begin)
        return -1;
    const Run& run = *(after - 1);
    return column < run.endColumn ? run.patch : -1;
}

} // namespace mcpp
