#include "io/PlanExport.hpp"

namespace mcpp::io {

const RegionOutlines& ExportContext::outlines() const {
    std::call_once(outlineCache->traced, [this] { outlineCache->outlines = regionOutlines(plan); });
    return outlineCache->outlines;
}

} // namespace mcpp::io
