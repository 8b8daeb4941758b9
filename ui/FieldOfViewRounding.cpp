#include "ui/FieldOfViewRounding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp::ui {

std::map<std::int32_t, RoundedClassFieldOfView>
roundFieldsOfView(const ClassTable& classes, const std::map<std::int32_t, std::int64_t>& pixelCounts) {
    auto counts = [&](const LandCoverClass& landCoverClass) {
        if (!landCoverClass.isTraversable())
            return false;
        if (!std::isfinite(landCoverClass.fieldOfViewMetres) || landCoverClass.fieldOfViewMetres <= 0.0)
            return false;
        if (pixelCounts.empty())
            return true;
        const auto found = pixelCounts.find(landCoverClass.value);
        return found != pixelCounts.end() && found->second > 0;
    };

    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& landCoverClass : classes.classes())
        if (counts(landCoverClass))
            smallest = std::min(smallest, landCoverClass.fieldOfViewMetres);
    std::map<std::int32_t, RoundedClassFieldOfView> rounded;
    if (!std::isfinite(smallest))
        return rounded;

    int largestPower = 0;
    for (const auto& landCoverClass : classes.classes()) {
        if (!counts(landCoverClass))
            continue;
        // The small epsilon keeps an exact multiple (e.g. 20 / 10 = 2) from flooring to the level below.
        const int power = std::max(
            0, static_cast<int>(std::floor(std::log2(landCoverClass.fieldOfViewMetres / smallest) + 1e-9)));
        rounded[landCoverClass.value] = {smallest * std::ldexp(1.0, power), power};
        largestPower = std::max(largestPower, power);
    }
    for (auto& [value, entry] : rounded)
        entry.level = 1 + (largestPower - entry.level);
    return rounded;
}

} // namespace mcpp::ui
