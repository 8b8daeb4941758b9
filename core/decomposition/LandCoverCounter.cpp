#include "core/decomposition/LandCoverCounter.hpp"

#include <algorithm>

namespace mcpp {

LandCoverCounter::Result LandCoverCounter::of(double minX, double maxX, double minY, double maxY) {
    const auto [firstColumn, lastColumn] =
        sampleRange(minX, maxX, samples_.originX, samples_.sampleWidth, samples_.columns);
    const auto [firstRow, lastRow] = sampleRange(samples_.originY - maxY, samples_.originY - minY, 0.0,
                                                 samples_.sampleHeight, samples_.rows);
    touched_.clear();
    for (int r = firstRow; r < lastRow; ++r)
        for (int c = firstColumn; c < lastColumn; ++c) {
            const std::uint16_t code = samples_.row(r)[c];
            if (code < PixelCodes::obstacle && counts_[code]++ == 0)
                touched_.push_back(code);
        }
    std::sort(touched_.begin(), touched_.end(),
              [&](std::uint16_t a, std::uint16_t b) { return classes_[a].value < classes_[b].value; });
    Result result;
    std::uint32_t best = 0;
    std::uint32_t passable = 0;
    double inverseSpeedSum = 0.0;
    for (auto code : touched_) {
        const std::uint32_t count = counts_[code];
        if (count > best) {
            best = count;
            result.classValue = classes_[code].value;
        }
        passable += count;
        inverseSpeedSum += count / classes_[code].speed;
        counts_[code] = 0;
    }
    result.speedMetresPerSecond = passable == 0 ? 0.0 : passable / inverseSpeedSum;
    return result;
}

} // namespace mcpp
