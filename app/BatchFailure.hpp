#pragma once

#include <stdexcept>
#include <string>

namespace mcpp::app {

// Ends a batch run early with a one-line message and the exit code of the batch contract.
class BatchFailure : public std::runtime_error {
  public:
    static constexpr int badInput = 2;
    static constexpr int internalError = 1;
    // --compare: every planner ran, but some failed on the mission (their rows say why).
    static constexpr int somePlannersFailed = 3;

    BatchFailure(int exitCode, const std::string& message)
        : std::runtime_error(message), exitCode_(exitCode) {}
    [[nodiscard]] int exitCode() const { return exitCode_; }

  private:
    int exitCode_;
};

} // namespace mcpp::app
