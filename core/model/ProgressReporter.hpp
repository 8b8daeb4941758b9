#pragma once

#include <atomic>
#include <functional>
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

  private:
    Callback callback_;
    const std::atomic<bool>* cancelRequested_ = nullptr;
};

} // namespace mcpp
