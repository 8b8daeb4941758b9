#pragma once

#include "io/Result.hpp"

#include <string>
#include <string_view>

namespace mcpp::io {

// Whether a write is on the disk when it returns. The user's own files (missions, class tables, saved
// plans, drawn areas) are synced; exports, which the mission makes again, are left to the system to flush: a
// sync cost about 1.5 ms a file, a third of the time of writing a 20-robot plan's 108 files.
enum class Sync { ToDisk, BySystem };

// Writes the whole file or nothing: the bytes go to a temporary file beside `path`, every write checked
// (a full disk or a file-size limit shows, as a short write, not only as an error), synced if asked, and
// renamed over `path`, so a reader sees the old file or the whole new one. On failure the previous file is
// untouched and the temporary file removed.
[[nodiscard]] Status writeFileAtomically(const std::string& path, std::string_view bytes,
                                         Sync sync = Sync::ToDisk);

} // namespace mcpp::io
