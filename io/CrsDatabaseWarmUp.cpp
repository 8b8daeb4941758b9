#include "io/CrsDatabaseWarmUp.hpp"

#include "io/internal/GdalSupport.hpp"

#include <ogr_spatialref.h>

namespace mcpp::io {

CrsDatabaseWarmUp::CrsDatabaseWarmUp()
    : thread_([] {
          internal::QuietGdalErrors quiet;
          OGRSpatialReference wgs84;
          wgs84.importFromEPSG(4326); // a lookup in the database: opens and reads it
      }) {}

CrsDatabaseWarmUp::~CrsDatabaseWarmUp() {
    if (thread_.joinable())
        thread_.join();
}

} // namespace mcpp::io
