#pragma once

#include "app/CommandLineOptions.hpp"

#include <string>

namespace mcpp::app {

// The options, or the one-line reason the command line is unusable and the exit code that goes with it.
struct CommandLineParseResult {
    CommandLineOptions options;
    std::string error; // without the "mcpp: " prefix; empty on success
    int exitCode = 0;  // 2 when error is set

    [[nodiscard]] bool ok() const { return error.empty(); }
};

} // namespace mcpp::app
