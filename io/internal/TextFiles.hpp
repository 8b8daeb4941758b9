#pragma once

#include "core/model/NameSuggestion.hpp"
#include "io/AtomicFile.hpp"
#include "io/Result.hpp"

#include <string>
#include <vector>

namespace mcpp::io::internal {

// Writes the whole file or nothing (io::writeFileAtomically): a failed save leaves an older file untouched.
[[nodiscard]] Status writeFileAtomically(const std::string& path, const std::string& contents,
                                         Sync sync = Sync::ToDisk);
// The whole file, or an error naming it.
[[nodiscard]] Result<std::string> readWholeFile(const std::string& path);
// "PATH: file not found", and where a relative path was looked for: it is read from the folder the program
// runs in, or a mission file's, which the user may not have in mind.
[[nodiscard]] std::string fileNotFound(const std::string& path);

// Shortest decimal text that reads back as the same double.
[[nodiscard]] std::string formatShortest(double value);
// Shortest decimal text that reads back as the same float: 0.3F gives "0.3", not 0.30000001192092896.
[[nodiscard]] std::string formatShortestFloat(float value);
// The double that text stands for: a float speed as a double field, 0.3F as 0.3.
[[nodiscard]] double decimalDouble(float value);
// printf-style fixed decimals, e.g. formatFixed(1.5, 6) == "1.500000".
[[nodiscard]] std::string formatFixed(double value, int decimals);
// The same texts added to the end of `out`, for files of many rows: no string is made per decimal number.
void appendShortest(std::string& out, double value);
void appendShortestFloat(std::string& out, float value);
void appendFixed(std::string& out, double value, int decimals);
// `value` rounded to `decimals` places, in fixed notation without trailing zeros: 322009.0365214371 at 3 as
// "322009.037", 300000 as "300000". For files of many points, whose digits beyond a millimetre or a
// hundred-millionth of a degree mean nothing.
void appendRounded(std::string& out, double value, int decimals);

// One CSV record split into fields (RFC 4180 quoting; no line breaks inside fields).
// Returns false on an unterminated quote.
[[nodiscard]] bool splitCsvLine(const std::string& line, std::vector<std::string>& fields);
[[nodiscard]] std::string quoteCsvField(const std::string& field);
[[nodiscard]] std::string trimmed(const std::string& text);
using mcpp::lowercase; // where io's files have always found it

} // namespace mcpp::io::internal
