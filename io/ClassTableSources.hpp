#pragma once

#include "core/model/ClassTable.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Result.hpp"

#include <string>
#include <vector>

namespace mcpp::io {

struct PresetInfo {
    std::string name;        // command-line name, e.g. "esa-worldcover"
    std::string description; // one line for menus and --help
};

[[nodiscard]] std::vector<PresetInfo> classTablePresets();
[[nodiscard]] Result<ClassTable> presetClassTable(const std::string& name);

// CSV with columns value,name,speed_mps,fov_m,passable and an optional color (#rrggbb).
[[nodiscard]] Result<ClassTable> loadClassTableCsv(const std::string& path);
// The same from the file's text; path only names it in messages.
[[nodiscard]] Result<ClassTable> parseClassTableCsv(const std::string& text, const std::string& path);
[[nodiscard]] Status saveClassTableCsv(const ClassTable& table, const std::string& path);

// A table for the raster: the preset's (or a generic default's) speed, FOV and passability,
// with names and colours from the raster's own legend where it has one.
[[nodiscard]] ClassTable classTableForRaster(const LoadedRaster& raster, const std::string& preset = {});

// The table a mission plans with (docs/mission-format.md): its own rows, and for the values they lack,
// the preset's rows for this raster; with neither, the generic table for the raster.
[[nodiscard]] ClassTable missionClassTable(const ClassTable& ownRows, const std::string& preset,
                                           const LoadedRaster& raster);

// Checks every class present in the raster has a row. When it does not: an error listing the missing
// values, or, with missingAsObstacles, the grid is changed so those pixels are outside, with a warning.
[[nodiscard]] Status reconcileRasterWithTable(LoadedRaster& raster, const ClassTable& table,
                                              bool missingAsObstacles);

} // namespace mcpp::io
