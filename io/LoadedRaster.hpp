#pragma once

#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "io/GeoReference.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::io {

struct LegendEntry {
    std::int32_t value = 0;
    std::string name;
    std::optional<std::uint32_t> colorRgb; // 0xRRGGBB
};

// A land-cover raster ready for planning: the grid in metres and where it sits on the Earth.
struct LoadedRaster {
    std::string path;
    int band = 1;
    ClassGrid grid;            // planning frame, metres
    GeoReference georeference; // CRS of the planning frame
    std::string sourceCrsName; // CRS of the file as read
    bool warpedFromGeographic = false;
    int sourceColumns = 0;
    int sourceRows = 0;
    double effectiveResolutionMetres = 0.0; // pixel side after any coarsening
    bool coarsened = false;
    std::vector<LegendEntry> legend; // from palette, category names, RAT, .qml or CSV beside the file
    std::string legendSource;        // "palette", "category names", "qml", ... or empty
    std::string metadataText; // the file's metadata items and band description, for recognising products
    std::map<std::int32_t, std::int64_t> classPixelCounts; // inside pixels only
    std::vector<std::string> warnings;
    // News, not warnings: what an area of interest leaves to plan on ("planning on 4.04 km2 of the map"), the
    // CRS a geographic raster is planned in.
    std::vector<std::string> notes;
    // The area of interest's and the no-go zones' polygons the raster was limited to (applyAreaOfInterest).
    AreaOutline area;
};

struct RasterLoadOptions {
    int band = 1;
    std::int64_t pixelBudget = 32'000'000; // above this, read a coarser level and say so
};

// The class values with pixels inside the area planned, in ascending order: the classes taking part.
[[nodiscard]] std::vector<std::int32_t> presentClassValues(const LoadedRaster& raster);

[[nodiscard]] Result<LoadedRaster> loadLandCoverRaster(const std::string& path,
                                                       const RasterLoadOptions& options = {});

} // namespace mcpp::io
