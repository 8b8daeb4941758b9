#pragma once

#include "io/PlanExport.hpp"
#include "io/internal/PlanGeometry.hpp"

#include <optional>
#include <string>

namespace mcpp::io::internal {

// A path longer than this many segments (a dense path of millions of cells) is written as consecutive
// features, kind "path" with `part` 1 to `parts`, each beginning where the one before ended and each with
// the whole path's figures: GDAL's GeoJSON reader, and QGIS with it, refuses a feature whose parse takes
// more than 200 MB (OGR_GEOJSON_MAX_OBJ_SIZE), which a line of about a million points does.
inline constexpr int mostSegmentsInAGeoJsonPath = 100'000;

// How many features the path is written as: 1 up to mostSegmentsInAGeoJsonPath segments.
[[nodiscard]] int geoJsonPathParts(const OGRGeometry& path);

// The plan's features, already in WGS84 longitude and latitude, as RFC 7946 GeoJSON text: one feature per
// line, coordinates to 9 decimals, exterior rings counter-clockwise and holes clockwise. Written directly,
// several times faster than OGR's GeoJSON driver, which builds a JSON object per coordinate. Nothing when
// the context is cancelled.
[[nodiscard]] std::optional<std::string> planGeoJsonText(const ExportContext& context,
                                                         const PlanFeatures& features);

} // namespace mcpp::io::internal
