#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace mcpp {

// The robots a message names by number ("robot 3", or a list: "robots 1, 2 and 5"; counted from 1 as every
// message counts them), each once, in increasing order: callers that know the robots by name say which is
// which.
[[nodiscard]] std::vector<std::size_t> robotNumbersIn(const std::string& message);

} // namespace mcpp
