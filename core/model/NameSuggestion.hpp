#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mcpp {

// The text with its ASCII letters in lower case: names, keys and headers compared without case.
[[nodiscard]] std::string lowercase(std::string text);

// The known name a mistyped one most likely meant: the only one holding it ("worldcover"), the same but for
// case, or within a few typed letters (two, or a quarter of the name's length when longer), else the only
// name of four letters or more the typed one holds ("robots" for "robots_list"); none when no name is that
// close. For presets, planners, parameters, flags and mission keys alike.
[[nodiscard]] std::optional<std::string> closestName(const std::string& typed,
                                                     const std::vector<std::string>& known);

} // namespace mcpp
