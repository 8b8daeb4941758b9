#include "app/ProgressPrinter.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::app {

ProgressPrinter::ProgressPrinter(std::ostream& stream, bool enabled, int percentStep)
    : stream_(stream), enabled_(enabled), percentStep_(std::max(1, percentStep)) {}

void ProgressPrinter::report(std::string_view stage, double fraction) {
    if (!enabled_)
        return;
    const double clamped = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
    const int percent = static_cast<int>(std::floor(clamped * 100.0));
    const std::lock_guard lock(mutex_);
    const bool newStage = stage != stage_;
    if (!newStage && percent / percentStep_ <= lastPercent_ / percentStep_)
        return;
    if (newStage)
        stage_ = std::string(stage);
    lastPercent_ = percent;
    emit("mcpp: " + stage_ + ' ' + std::to_string(percent) + "%\n");
}

void ProgressPrinter::holdFor(Clock::duration delay) {
    const std::lock_guard lock(mutex_);
    holding_ = true;
    holdUntil_ = Clock::now() + delay;
}

void ProgressPrinter::release() {
    const std::lock_guard lock(mutex_);
    holding_ = false;
    for (const auto& line : held_)
        stream_ << line;
    held_.clear();
    stream_ << std::flush;
}

void ProgressPrinter::discardHeld() {
    const std::lock_guard lock(mutex_);
    holding_ = false;
    held_.clear();
}

void ProgressPrinter::emit(const std::string& line) {
    if (holding_ && Clock::now() < holdUntil_) {
        held_.push_back(line);
        return;
    }
    if (holding_) {
        holding_ = false;
        for (const auto& earlier : held_)
            stream_ << earlier;
        held_.clear();
    }
    stream_ << line << std::flush;
}

} // namespace mcpp::app
