#pragma once

#include "io/LoadedRaster.hpp"
#include "io/Result.hpp"

#include <string>
#include <vector>

class GDALRasterBand;

namespace mcpp::io::internal {

// Fills raster.legend and raster.legendSource from, in this order of preference for names: the raster
// attribute table, GDAL category names (also from a .aux.xml), a "legend" metadata item, a QGIS .qml style
// beside the file, a CSV legend beside the file. Colours come from the same source, else from the band's
// palette. Also keeps the file's metadata text in raster.metadataText.
void readRasterLegend(GDALRasterBand& band, const std::string& rasterPath, LoadedRaster& raster);

// Legend CSV: a header naming a value column (value, code, grid_code, ...) and a name column
// (name, label, label3, class, ...), optionally colour as color (#rrggbb), rgb ("r-g-b") or r,g,b columns.
[[nodiscard]] Result<std::vector<LegendEntry>> readLegendCsv(const std::string& path);
// The same from the file's text; path only names it in messages.
[[nodiscard]] Result<std::vector<LegendEntry>> parseLegendCsv(const std::string& text,
                                                              const std::string& path);

// A "legend" metadata item as ESA WorldCover writes it: one class per line, its value, spaces, its name.
// Lines that do not start with a value are skipped.
[[nodiscard]] std::vector<LegendEntry> parseMetadataLegend(const std::string& text);

// QGIS style: paletted raster renderer, raster pseudocolour items, or a categorized (unique values) renderer.
[[nodiscard]] Result<std::vector<LegendEntry>> readQgisStyleLegend(const std::string& path);
[[nodiscard]] Result<std::vector<LegendEntry>> parseQgisStyleLegend(const std::string& text,
                                                                    const std::string& path);

// "#rrggbb", "r,g,b[,a]" or "r-g-b"; nothing when the text is none of these.
[[nodiscard]] std::optional<std::uint32_t> parseColor(const std::string& text);
[[nodiscard]] std::string formatColor(std::uint32_t rgb);

} // namespace mcpp::io::internal
