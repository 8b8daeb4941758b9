#pragma once

#include "io/LoadedRaster.hpp"

#include <optional>
#include <string>

namespace mcpp::io::internal {

struct ProductMatch {
    std::string preset;      // a preset name of presetDefinitions()
    std::string productName; // "ESA WorldCover"
    std::string evidence;    // what recognised it: "its metadata", "its palette", ...
};

// Which well-known land-cover product the raster is, from, in this order: its metadata or its file name
// naming the product, its class names (a file naming its classes otherwise is not taken for a product),
// its palette, and last its values alone (only where a product's codes are its own, or where the CRS is
// one the product comes in). A product is considered only when its
// preset has a row for nearly every pixel (99%). Nothing when the evidence is missing or ambiguous.
[[nodiscard]] std::optional<ProductMatch> recogniseProduct(const LoadedRaster& raster);

} // namespace mcpp::io::internal
