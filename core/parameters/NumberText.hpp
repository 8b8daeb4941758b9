#pragma once

#include <optional>
#include <string_view>

namespace mcpp {

// A finite decimal number written the way a user types it ("0.5", "+3", " -1e3 "), or nothing. Shared by
// parameter values and command-line coordinates so both accept the same spellings.
[[nodiscard]] std::optional<double> parseFiniteNumber(std::string_view text);
// A duration as a user types it, in seconds: "1500", "1500 s", "25min", "0.5 h"; nothing for other text.
[[nodiscard]] std::optional<double> parseDuration(std::string_view text);
// The text without leading and trailing white space.
[[nodiscard]] std::string_view trimmedText(std::string_view text);

} // namespace mcpp
