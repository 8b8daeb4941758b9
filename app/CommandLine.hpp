#pragma once

#include "app/CommandLineParseResult.hpp"

#include <string>
#include <vector>

namespace mcpp::app {

// Turns mcpp's arguments into options. Works on plain strings so tests can call it directly and main can
// decide which kind of QCoreApplication to build before any exists.
class CommandLine {
  public:
    // arguments excludes the program name.
    [[nodiscard]] static CommandLineParseResult parse(const std::vector<std::string>& arguments);
    [[nodiscard]] static std::string usage();
    // One planner's description and parameters, for --help-planner.
    [[nodiscard]] static std::string plannerHelp(const std::string& name);
    [[nodiscard]] static std::string versionText();
};

} // namespace mcpp::app
