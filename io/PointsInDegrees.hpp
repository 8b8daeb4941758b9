#pragma once

#include "core/model/ClassGrid.hpp"
#include "io/GeoReference.hpp"

#include <string>

namespace mcpp::io {

// A message with each map point it names, "(431385, 5399995)", given its longitude and latitude inside the
// brackets, "(431385, 5399995; longitude 14.0648, latitude 48.7492)", as start errors name starts: field
// teams read GPS degrees, and metres of UTM mean little to most. Only where the map has a CRS, and only
// pairs of numbers that lie on the map or within its size of it (others are not its points).
// "longitude 14.0813625, latitude 47.8599126": seven decimals, about a centimetre on the ground, whatever
// the size of the degrees.
[[nodiscard]] std::string degreesText(LonLat lonLat);

[[nodiscard]] std::string withPointsInDegrees(const std::string& message, const GeoReference& georeference,
                                              const ClassGrid& grid);

} // namespace mcpp::io
