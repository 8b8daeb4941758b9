#pragma once

#include "io/GeoReference.hpp"

#include <memory>
#include <mutex>
#include <ogr_spatialref.h>
#include <string>
#include <vector>

namespace mcpp::io {

// What a GeoReference holds, shared by its copies; seen by io's own files only (GDAL stays private).
struct GeoReference::State {
    std::unique_ptr<OGRSpatialReference> crs;
    double metresPerUnit = 1.0;
    // Read once: OGRSpatialReference's const methods may touch caches, and exports run on several threads.
    std::string wkt;
    std::string name;
    std::string authorityCode;
    // OGRCoordinateTransformation is not thread-safe and copies share these: the lock guards the
    // transformations kept here, and a transformation is used by one thread at a time.
    mutable std::mutex mutex;
    // Transformations to WGS84 not in use: each writer thread borrows one, so that exports written side
    // by side do not wait for each other's points.
    mutable std::vector<std::unique_ptr<OGRCoordinateTransformation>> idleToWgs84;
    mutable std::unique_ptr<OGRCoordinateTransformation> fromWgs84;
};

} // namespace mcpp::io
