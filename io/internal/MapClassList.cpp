#include "io/internal/MapClassList.hpp"

#include "core/model/HumanUnits.hpp"

#include <vector>

namespace mcpp::io::internal {

MapClassList mapClassList(const LoadedRaster& raster, const ClassTable& classes,
                          const std::function<bool(const LandCoverClass&)>& picked) {
    std::int64_t inside = 0;
    for (const auto& [value, count] : raster.classPixelCounts)
        inside += count;
    const double pixelArea = raster.grid.pixelWidth * raster.grid.pixelHeight;
    std::vector<std::string> named;
    for (const auto& [value, count] : raster.classPixelCounts) {
        const LandCoverClass* landCover = classes.find(value);
        if (landCover == nullptr || count == 0 || !picked(*landCover))
            continue;
        const std::string name = landCover->name.empty() ? "class " + std::to_string(value) : landCover->name;
        named.push_back(name + " (class " + std::to_string(value) + ", " +
                        formatArea(static_cast<double>(count) * pixelArea) + ", " +
                        formatPercent(static_cast<double>(count) / static_cast<double>(inside)) +
                        " of the map)");
    }
    MapClassList list;
    list.classes = named.size();
    for (std::size_t i = 0; i < named.size(); ++i)
        list.text += (i == 0 ? "" : i + 1 == named.size() ? " and " : ", ") + named[i];
    return list;
}

} // namespace mcpp::io::internal
