#pragma once

#include "io/Result.hpp"

#include <string>
#include <string_view>

namespace mcpp::io {

// Writes the whole file or nothing: the bytes go to a temporary file beside `path`, every write checked
// (a full disk or a file-size limit shows, as a short write, not only as an error), synced, and renamed over
// `path`. On failure the previous file is untouched and the temporary file removed.
[[nodiscard]] Status writeFileAtomically(const std::string& path, std::string_view bytes);

} // namespace mcpp::io
