#include "app/ProgressPrinter.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::app {

ProgressPrinter::ProgressPrinter(std::ostream& stream, bool enabled, int percentStep)
    : stream_(stream), enabled_(enabled), percentStep_(std::max(1, percentStep)) {}

void ProgressPrinter::report(std::string_view stage, double fraction) {
    if (!enabled_) return;
    const double clamped = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
    const int percent = static_cast<int>(std::floor(clamped * 100.0));
    const std::lock_guard lock(mutex_);
    const bool newStage = stage != stage_;
    if (!newStage && percent / percentStep_ <= lastPercent_ / percentStep_) return;
    if (newStage) stage_ = std::string(stage);
    lastPercent_ = percent;
    stream_ << "mcpp: " << stage_ << ' ' << percent << "%\n" << std::flush;
}

} // namespace mcpp::app
