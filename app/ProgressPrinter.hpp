#pragma once

#include <mutex>
#include <ostream>
#include <string>
#include <string_view>

namespace mcpp::app {

// Prints "mcpp: <stage> <percent>%" lines: one when a stage begins and one per step of progress, so a
// long run shows it is alive without flooding the terminal.
class ProgressPrinter {
public:
    explicit ProgressPrinter(std::ostream& stream, bool enabled, int percentStep = 25);

    void report(std::string_view stage, double fraction);

private:
    std::ostream& stream_;
    bool enabled_;
    int percentStep_;
    std::mutex mutex_; // planners may report from worker threads
    std::string stage_;
    int lastPercent_ = -1;
};

} // namespace mcpp::app
