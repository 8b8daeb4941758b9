#pragma once

#include <string>

namespace mcpp::app {

// Starts the window (QApplication) and opens a mission or raster given on the command line.
class GuiLauncher {
  public:
    // argv[0] is handed to Qt; the rest of the command line was already parsed by CommandLine.
    [[nodiscard]] static int run(char* programName, const std::string& fileToOpen);
};

} // namespace mcpp::app
