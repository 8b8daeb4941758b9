#pragma once

#include "core/decomposition/LandCoverSamples.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// The land cover of a square of samples, as every decomposition gives it to a cell: the majority passable
// class (a tie goes to the lower class value) and the harmonic mean of the speeds over its passable samples.
class LandCoverCounter {
  public:
    struct Result {
        std::int32_t classValue = 0;
        double speedMetresPerSecond = 0.0; // 0 when no sample is passable
    };

    LandCoverCounter(const SampleGrid& samples, const std::vector<PixelCodes::DenseClass>& classes)
        : samples_(samples), classes_(classes), counts_(classes.size(), 0U) {}

    [[nodiscard]] Result of(double minX, double maxX, double minY, double maxY);

  private:
    const SampleGrid& samples_;
    const std::vector<PixelCodes::DenseClass>& classes_;
    std::vector<std::uint32_t> counts_; // by class code, zero between calls
    std::vector<std::uint16_t> touched_;
};

} // namespace mcpp
