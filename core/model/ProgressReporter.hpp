#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <string_view>

namespace mcpp {

// Reports stage progress to a caller and carries its request to stop. The planner checks
// the cancel flag between units of work and throws PlanningError(Kind::Cancelled).
class ProgressReporter {
  public:
    using Callback = std::function<void(std::string_view stage, double fraction)>;

    ProgressReporter() = default;
    explicit ProgressReporter(Callback callback, const std::atomic<bool>* cancelRequested = nullptr)
        : callback_(std::move(callback)), cancelRequested_(cancelRequested) {}

    void report(std::string_view stage, double fraction) const {
        if (callback_)
            callback_(stage, fraction);
    }
    [[nodiscard]] bool cancelRequested() const {
        return cancelRequested_ != nullptr && cancelRequested_->load(std::memory_order_relaxed);
    }
    // Throws PlanningError(Kind::Cancelled) when the caller asked to stop.
    void throwIfCancelled() const;
    // A reporter for work done again inside a later stage: whatever it reports shows as `stage`, its
    // fraction scaled into [from, to]; cancelling still stops it.
    [[nodiscard]] ProgressReporter within(std::string stage, double from, double to) const {
        Callback outer = callback_;
        return ProgressReporter(
            [outer, stage = std::move(stage), from, to](std::string_view, double fraction) {
                if (outer)
                    outer(stage, from + (to - from) * fraction);
            },
            cancelRequested_);
    }

    // A reporter for the first part of a longer job: its stages show under their own names, their
    // fractions scaled into [from, to].
    [[nodiscard]] ProgressReporter scaled(double from, double to) const {
        Callback outer = callback_;
        return ProgressReporter(
            [outer, from, to](std::string_view stage, double fraction) {
                if (outer)
                    outer(stage, from + (to - from) * fraction);
            },
            cancelRequested_);
    }

  private:
    Callback callback_;
    const std::atomic<bool>* cancelRequested_ = nullptr;
};

} // namespace mcpp
