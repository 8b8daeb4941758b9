#pragma once

#include "core/model/MapPoint.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Result.hpp"

#include <string>
#include <vector>

namespace mcpp::io {

// Limits the raster's task area to the polygons of includePath (when not empty) and takes out those of
// excludePath (no-go zones): the pixels left out become outside, as nodata is, so every planner keeps to
// the area. The files are any vector format GDAL reads; their polygons are taken to the raster's planning
// CRS (a file without a CRS is taken to be in the raster's CRS units). Class counts follow. raster.notes
// gains how much of the map is left; raster.warnings, where some of the area lies off the raster or over its
// nodata, how much. Errors name the file and what is wrong with it.
[[nodiscard]] Status applyAreaOfInterest(LoadedRaster& raster, const std::string& includePath,
                                         const std::string& excludePath);

// Writes polygons drawn on the map (rings of corners in the planning frame, metres) as a GeoJSON file in the
// raster's planning CRS, for a mission's area.include or area.exclude to name; with keepPolygonsOf, the
// polygons of that vector file come first (no-go zones drawn one after another add up). Written atomically.
[[nodiscard]] Status writeAreaPolygons(const std::string& path,
                                       const std::vector<std::vector<MapPoint>>& rings,
                                       const LoadedRaster& raster, const std::string& keepPolygonsOf = {});

} // namespace mcpp::io
