#pragma once

#include "core/model/ClassTable.hpp"
#include "io/LoadedRaster.hpp"

#include <cstddef>
#include <functional>
#include <string>

namespace mcpp::io::internal {

// Classes of the map's pixels named in a message, with what they cover.
struct MapClassList {
    std::string text;        // "Water (class 1, 1.2 km2, 0.08% of the map) and Snow (class 2, ...)"
    std::size_t classes = 0; // how many it names
};

// The classes on the map (in value order) whose table row `picked` chooses.
[[nodiscard]] MapClassList mapClassList(const LoadedRaster& raster, const ClassTable& classes,
                                        const std::function<bool(const LandCoverClass&)>& picked);

} // namespace mcpp::io::internal
