#pragma once

#include <chrono>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace mcpp::app {

// Prints "mcpp: <stage> <percent>%" lines: one when a stage begins and one per step of progress, so a
// long run shows it is alive without flooding the terminal.
//
// Lines can be held back for a while: the planner checks the starts only after its first stages, and a
// bad start must still come out as one error line, not as progress followed by the error.
class ProgressPrinter {
  public:
    using Clock = std::chrono::steady_clock;

    explicit ProgressPrinter(std::ostream& stream, bool enabled, int percentStep = 25);

    void report(std::string_view stage, double fraction);

    // Buffers lines until `delay` has passed (they are then printed at the next report) or until
    // release() or discardHeld().
    void holdFor(Clock::duration delay);
    void release();     // print what is held and stop holding
    void discardHeld(); // drop what is held and stop holding

  private:
    void emit(const std::string& line);

    std::ostream& stream_;
    bool enabled_;
    int percentStep_;
    std::mutex mutex_; // planners may report from worker threads
    std::string stage_;
    int lastPercent_ = -1;
    bool holding_ = false;
    Clock::time_point holdUntil_;
    std::vector<std::string> held_;
};

} // namespace mcpp::app
