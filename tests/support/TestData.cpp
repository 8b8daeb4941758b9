#include "tests/support/TestData.hpp"

namespace mcpp::test {

std::string testDataPath(const std::string& relative) {
    return std::string(MCPP_TEST_DATA_DIR) + "/" + relative;
}
std::string sourcePath(const std::string& relative) {
    return std::string(MCPP_SOURCE_DIR) + "/" + relative;
}
std::string binaryPath(const std::string& relative) {
    return std::string(MCPP_BINARY_DIR) + "/" + relative;
}

} // namespace mcpp::test
