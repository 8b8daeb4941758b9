#pragma once

#include "io/PlanExport.hpp"
#include "io/internal/PlanGeometry.hpp"

#include <optional>
#include <string>

namespace mcpp::io::internal {

// The plan's features, already in WGS84 longitude and latitude, as RFC 7946 GeoJSON text: one feature per
// line, coordinates to 9 decimals, exterior rings counter-clockwise and holes clockwise. Written directly,
// several times faster than OGR's GeoJSON driver, which builds a JSON object per coordinate. Nothing when
// the context is cancelled.
[[nodiscard]] std::optional<std::string> planGeoJsonText(const ExportContext& context,
                                                         const PlanFeatures& features);

} // namespace mcpp::io::internal
