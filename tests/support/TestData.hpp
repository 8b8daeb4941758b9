#pragma once

#include <string>

namespace mcpp::test {

// Absolute path of a file under tests/data.
[[nodiscard]] std::string testDataPath(const std::string& relative);
// Absolute path of a file under the source tree's root (samples/, docs/, ...).
[[nodiscard]] std::string sourcePath(const std::string& relative);
// Absolute path under the build tree.
[[nodiscard]] std::string binaryPath(const std::string& relative);

} // namespace mcpp::test
