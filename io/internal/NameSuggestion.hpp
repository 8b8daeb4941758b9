#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mcpp::io::internal {

// The known name a mistyped one most likely meant: the only one holding it ("worldcover"), the same but for
// case, or within a few typed letters (two, or a quarter of the name's length when longer); none when no
// name is that close.
[[nodiscard]] std::optional<std::string> closestName(const std::string& typed,
                                                     const std::vector<std::string>& known);

} // namespace mcpp::io::internal
