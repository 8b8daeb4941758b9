#include "io/GdalVersion.hpp"

#include <gdal.h>

namespace mcpp::io {

std::string gdalVersion() {
    return GDALVersionInfo("RELEASE_NAME");
}

} // namespace mcpp::io
