#include "core/decomposition/DecompositionOptions.hpp"

namespace mcpp {

ParameterSpec DecompositionOptions::purityToleranceParameter() {
    return realParameter(
        "purity_tolerance", "Purity tolerance", 0.0, 0.0, 1.0,
        "A class covering at most this fraction of a cell's pixels does not force the cell to split "
        "(stray pixels of real rasters)",
        {}, false);
}

ParameterSpec DecompositionOptions::blockedThresholdParameter() {
    return realParameter(
        "blocked_threshold", "Blocked threshold", 0.5, 0.0, 1.0,
        "A smallest cell whose share of obstacle and outside pixels exceeds this is left out");
}

DecompositionOptions DecompositionOptions::from(const ParameterValues& values,
                                                std::int64_t bytesPerBottomCell) {
    DecompositionOptions options;
    options.bytesPerBottomCell = bytesPerBottomCell;
    if (values.has("purity_tolerance"))
        options.purityTolerance = values.real("purity_tolerance");
    if (values.has("blocked_threshold"))
        options.blockedThreshold = values.real("blocked_threshold");
    return options;
}

} // namespace mcpp
