#pragma once

#include "core/model/ClassTable.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Result.hpp"

#include <set>
#include <string>
#include <vector>

namespace mcpp::io {

struct PresetInfo {
    std::string name;        // command-line name, e.g. "esa-worldcover"
    std::string description; // one line for menus and --help
};

[[nodiscard]] std::vector<PresetInfo> classTablePresets();
[[nodiscard]] Result<ClassTable> presetClassTable(const std::string& name);

// The class values of a table's rows that gave no colour: they are grey until coloured from the map's own
// table (withColoursFrom).
using ClassesWithoutColour = std::set<std::int32_t>;

// CSV with columns value,name,speed_mps,fov_m,passable and an optional color (#rrggbb). The rows without a
// colour are added to `withoutColour` when given.
[[nodiscard]] Result<ClassTable> loadClassTableCsv(const std::string& path,
                                                   ClassesWithoutColour* withoutColour = nullptr);
// The same from the file's text; path only names it in messages.
[[nodiscard]] Result<ClassTable> parseClassTableCsv(const std::string& text, const std::string& path,
                                                    ClassesWithoutColour* withoutColour = nullptr);
// The colours of a table's rows for a raster: those of `forRaster` (its classes: the preset's, or the
// file's palette), then the preset's for the values the raster does not hold (a class outside the area of
// interest).
[[nodiscard]] ClassTable colourReference(const ClassTable& forRaster, const std::string& preset);
// The table with the colours its rows did not give taken from `reference` (colourReference), where it has a
// row of that value.
[[nodiscard]] ClassTable withColoursFrom(ClassTable table, const ClassesWithoutColour& withoutColour,
                                         const ClassTable& reference);
[[nodiscard]] Status saveClassTableCsv(const ClassTable& table, const std::string& path);

// A table for the raster: the preset's (or a generic default's) speed, FOV and passability,
// with names and colours from the raster's own legend where it has one.
[[nodiscard]] ClassTable classTableForRaster(const LoadedRaster& raster, const std::string& preset = {});

// The table a raster opens with, and where it came from in a sentence for the user: the preset of the
// well-known product the raster is recognised as (ESA WorldCover, CORINE, NLCD, ...) with the file's own
// names and colours on top, else the file's legend with default speeds and fields of view.
struct OpeningClassTable {
    ClassTable table;
    std::string preset;           // the recognised product's preset; empty when none was recognised
    bool fromLegendNames = false; // not recognised, but the file names its classes
    std::string explanation;
};
[[nodiscard]] OpeningClassTable openingClassTable(const LoadedRaster& raster);

// The table a mission plans with (docs/mission-format.md): its own rows, and for the values they lack,
// the preset's rows for this raster; with neither, the raster's opening table (openingClassTable). Its own
// rows without a colour take the colour the preset's or the opening table's row has for the raster (the
// preset's own for a value the raster does not hold).
[[nodiscard]] ClassTable missionClassTable(const ClassTable& ownRows, const std::string& preset,
                                           const LoadedRaster& raster,
                                           const ClassesWithoutColour& withoutColour = {});

// Checks every class present in the raster has a row. When it does not: an error listing the missing
// values, or, with missingAsObstacles, the grid is changed so those pixels are outside, with a warning.
[[nodiscard]] Status reconcileRasterWithTable(LoadedRaster& raster, const ClassTable& table,
                                              bool missingAsObstacles);

} // namespace mcpp::io
