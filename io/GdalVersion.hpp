#pragma once

#include <string>

namespace mcpp::io {

// The version of the GDAL library mcpp runs with, e.g. "3.6.2" (for the About box and reports).
[[nodiscard]] std::string gdalVersion();

} // namespace mcpp::io
