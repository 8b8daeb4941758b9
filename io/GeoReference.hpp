#pragma once

#include "core/model/MapPoint.hpp"
#include "io/Result.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcpp::io {

namespace internal {
class TransformationLoan;
}

struct LonLat {
    double longitude = 0.0;
    double latitude = 0.0;
};

// The CRS of the planning frame (metres) and the transforms to and from WGS84 and other CRSs.
// Cheap to copy; no GDAL type shows here.
class GeoReference {
  public:
    GeoReference(); // no CRS: coordinates are taken as metres and cannot go to WGS84
    // Any definition OSR understands: "EPSG:32612", WKT, PROJ string.
    static Result<GeoReference> fromDefinition(const std::string& definition);

    [[nodiscard]] bool hasCrs() const;
    [[nodiscard]] std::string wkt() const;
    [[nodiscard]] std::string name() const;          // e.g. "NAD83 / UTM zone 12N"
    [[nodiscard]] std::string authorityCode() const; // e.g. "EPSG:26912", empty when unknown

    [[nodiscard]] Result<LonLat> toWgs84(MapPoint point) const;
    // Many points at once: one call into PROJ, many times faster than point by point on long paths.
    [[nodiscard]] Result<std::vector<LonLat>> toWgs84(const std::vector<MapPoint>& points) const;
    [[nodiscard]] Result<MapPoint> fromWgs84(LonLat lonLat) const;
    // A point given in another CRS (definition as above), into the planning frame.
    [[nodiscard]] Result<MapPoint> fromCrs(const std::string& definition, MapPoint point) const;

    // The planning frame is always metres; a CRS in feet is kept for export and scaled here.
    // Planning metres = CRS units * metresPerUnit() (1 for metric and for no CRS).
    [[nodiscard]] double metresPerUnit() const;
    [[nodiscard]] MapPoint toCrsUnits(MapPoint planningPoint) const;
    [[nodiscard]] MapPoint fromCrsUnits(MapPoint crsPoint) const;
    // A planning-frame point into another CRS (e.g. "EPSG:4326" gives longitude, latitude).
    [[nodiscard]] Result<MapPoint> toCrs(const std::string& definition, MapPoint point) const;

    // Makes transformations to WGS84 until `count` wait unused for the threads that will need them. A
    // thread's first one costs milliseconds of CRS-database lookups: a batch run has them made on its spare
    // core while it plans, so that its writers find them ready. Nothing without a CRS.
    void prepareTransformationsToWgs84(int count) const;

  private:
    friend class internal::TransformationLoan; // lends the transformations kept here
    struct State;
    std::shared_ptr<const State> state_;
};

// " (an EPSG code is written EPSG:4326)" for a CRS given as a bare number, else empty: the likeliest slip.
[[nodiscard]] std::string epsgSpellingHint(const std::string& definition);

} // namespace mcpp::io
