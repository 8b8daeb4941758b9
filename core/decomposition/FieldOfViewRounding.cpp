#include "core/decomposition/FieldOfViewRounding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {
namespace {

const LandCoverClass* takingPart(const ClassTable& classes, std::int32_t value) {
    const LandCoverClass* landCoverClass = classes.find(value);
    if (landCoverClass == nullptr || !landCoverClass->isTraversable())
        return nullptr;
    const double fov = landCoverClass->fieldOfViewMetres;
    return std::isfinite(fov) && fov > 0.0 ? landCoverClass : nullptr;
}

} // namespace

std::optional<double> smallestFieldOfView(const ClassTable& classes,
                                          const std::vector<std::int32_t>& presentValues) {
    double fovMin = std::numeric_limits<double>::infinity();
    for (auto value : presentValues)
        if (const LandCoverClass* landCoverClass = takingPart(classes, value))
            fovMin = std::min(fovMin, landCoverClass->fieldOfViewMetres);
    if (!std::isfinite(fovMin))
        return std::nullopt;
    return fovMin;
}

std::vector<RoundedFieldOfView> roundFieldsOfView(const ClassTable& classes,
                                                  const std::vector<std::int32_t>& presentValues) {
    std::vector<RoundedFieldOfView> rounded;
    const std::optional<double> smallest = smallestFieldOfView(classes, presentValues);
    if (!smallest)
        return rounded;
    const double fovMin = *smallest;
    int deepest = 0;
    for (auto value : presentValues) {
        const LandCoverClass* landCoverClass = takingPart(classes, value);
        if (landCoverClass == nullptr)
            continue;
        // Round down to fovMin * 2^k; the small epsilon keeps exact powers of two from rounding a step lower.
        const int k =
            static_cast<int>(std::floor(std::log2(landCoverClass->fieldOfViewMetres / fovMin) + 1e-9));
        rounded.push_back({value, landCoverClass->fieldOfViewMetres, fovMin * std::ldexp(1.0, k), k});
        deepest = std::max(deepest, k);
    }
    const int levels = deepest + 1;
    for (auto& entry : rounded)
        entry.level = levels - entry.level; // sub-cell side at level i is fovMin * 2^(l - i)
    return rounded;
}

} // namespace mcpp
