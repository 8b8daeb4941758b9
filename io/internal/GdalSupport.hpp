#pragma once

// Private to mcpp_io: GDAL types may appear here, never in io's public headers.

#include "core/model/MapPoint.hpp"

#include <cpl_error.h>
#include <gdal_priv.h>
#include <memory>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <string>
#include <vector>

namespace mcpp::io::internal {

// Registers GDAL's drivers once per process.
void ensureGdalRegistered();

// Keeps GDAL's messages off stderr while alive and remembers the last one for our own error text.
class QuietGdalErrors {
  public:
    QuietGdalErrors();
    ~QuietGdalErrors();
    QuietGdalErrors(const QuietGdalErrors&) = delete;
    QuietGdalErrors& operator=(const QuietGdalErrors&) = delete;

    // GDAL's last error message, or an empty string.
    [[nodiscard]] static std::string lastMessage();
    // ": <message>" when GDAL said something, else empty: for appending to our messages.
    [[nodiscard]] static std::string detail();
};

struct DatasetCloser {
    void operator()(GDALDataset* dataset) const;
};
using DatasetPointer = std::unique_ptr<GDALDataset, DatasetCloser>;

// Every spatial reference mcpp creates uses x = easting / longitude, y = northing / latitude.
[[nodiscard]] std::unique_ptr<OGRSpatialReference> makeSpatialReference();
// Null when OSR does not understand the definition.
[[nodiscard]] std::unique_ptr<OGRSpatialReference>
spatialReferenceFromDefinition(const std::string& definition);
[[nodiscard]] std::unique_ptr<OGRSpatialReference> wgs84SpatialReference();
// Null when PROJ finds no way from one to the other; GDAL's last error says why.
[[nodiscard]] std::unique_ptr<OGRCoordinateTransformation>
transformationBetween(const OGRSpatialReference& from, const OGRSpatialReference& to);
[[nodiscard]] std::string wktOf(const OGRSpatialReference& reference);
// A closed ring of corners in the planning frame (metres), in the CRS's units.
[[nodiscard]] std::unique_ptr<OGRLinearRing> crsRing(const std::vector<MapPoint>& corners,
                                                     double metresPerUnit);

} // namespace mcpp::io::internal
