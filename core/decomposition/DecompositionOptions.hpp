#pragma once

#include "core/model/MemoryBudget.hpp"
#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

namespace mcpp {

// How a decomposition judges mixed cells (spec 2). Each field's parameter is declared beside it.
struct DecompositionOptions {
    // A class covering at most this fraction of a cell's pixels does not force a split (quadtree only).
    double purityTolerance = 0.0;
    // A smallest cell (or sub-cell, for the grid planners) whose obstacle + outside fraction exceeds this
    // is blocked.
    double blockedThreshold = 0.5;
    // The planner's peak memory per smallest cell: a grid needing more than the machine allows is refused
    // before it is built.
    std::int64_t bytesPerBottomCell = unmeasuredBytesPerBottomCell;

    [[nodiscard]] static ParameterSpec purityToleranceParameter();
    [[nodiscard]] static ParameterSpec blockedThresholdParameter();
    // The options from resolved parameter values; keys a planner does not declare keep their defaults.
    [[nodiscard]] static DecompositionOptions
    from(const ParameterValues& values, std::int64_t bytesPerBottomCell = unmeasuredBytesPerBottomCell);
};

} // namespace mcpp
