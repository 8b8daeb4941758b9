#include "io/ClassTableSources.hpp"

#include "core/model/NameSuggestion.hpp"
#include "io/internal/ClassTablePresets.hpp"
#include "io/internal/LegendReader.hpp"
#include "io/internal/ProductRecognition.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace mcpp::io {

namespace {

using internal::trimmed;

const std::vector<std::string> requiredColumns = {"value", "name", "speed_mps", "fov_m", "passable"};
// A legend (a raster's class names and colours) is not a class table: said with where a table comes from.
const std::string legendOnlyAdvice =
    ". A class table gives each class its speed_mps, fov_m and passable, which a legend of names does not: "
    "start from a preset's table (--preset NAME, or the Preset list) or the one the raster opens with, and "
    "edit it (Save CSV... in the window)";

bool parseDouble(const std::string& text, double& value) {
    const std::string clean = trimmed(text);
    if (clean.empty())
        return false;
    char* end = nullptr;
    value = std::strtod(clean.c_str(), &end);
    return end != nullptr && *end == '\0';
}

bool parseBoolean(const std::string& text, bool& value) {
    const std::string clean = internal::lowercase(trimmed(text));
    if (clean == "true" || clean == "yes" || clean == "1")
        value = true;
    else if (clean == "false" || clean == "no" || clean == "0")
        value = false;
    else
        return false;
    return true;
}

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const auto& preset : internal::presetDefinitions())
        names.push_back(preset.name);
    return names;
}

std::string knownPresetNames() {
    std::string names;
    for (const std::string& name : presetNames())
        names += (names.empty() ? "" : ", ") + name;
    return names;
}

} // namespace

std::vector<PresetInfo> classTablePresets() {
    std::vector<PresetInfo> presets;
    for (const auto& preset : internal::presetDefinitions())
        presets.push_back({preset.name, preset.description});
    return presets;
}

Result<ClassTable> presetClassTable(const std::string& name) {
    for (const auto& preset : internal::presetDefinitions()) {
        if (preset.name == name)
            return ClassTable(preset.classes);
    }
    const auto meant = closestName(name, presetNames());
    return Result<ClassTable>::failure("unknown class table preset \"" + name + "\"" +
                                       (meant ? ": did you mean \"" + *meant + "\"?" : std::string()) +
                                       " (known: " + knownPresetNames() + ")");
}

Result<ClassTable> loadClassTableCsv(const std::string& path, ClassesWithoutColour* withoutColour) {
    auto contents = internal::readWholeFile(path);
    if (!contents)
        return Result<ClassTable>::failure(contents.error());
    return parseClassTableCsv(contents.value(), path, withoutColour);
}

Result<ClassTable> parseClassTableCsv(const std::string& text, const std::string& path,
                                      ClassesWithoutColour* withoutColour) {
    std::stringstream stream(text);
    std::string line;
    std::vector<std::string> fields;
    const auto failure = [&](int lineNumber, const std::string& what) {
        return Result<ClassTable>::failure(path + ": line " + std::to_string(lineNumber) + ": " + what);
    };
    if (!std::getline(stream, line) || trimmed(line).empty()) {
        return failure(1, "expected the header value,name,speed_mps,fov_m,passable[,color]");
    }
    if (line.rfind("\xEF\xBB\xBF", 0) == 0)
        line.erase(0, 3); // UTF-8 byte order mark from spreadsheets
    if (!internal::splitCsvLine(line, fields))
        return failure(1, "unterminated quote");

    // Column index of each known column; -1 when absent.
    std::vector<std::string> header;
    int valueColumn = -1, nameColumn = -1, speedColumn = -1, fovColumn = -1, passableColumn = -1,
        colorColumn = -1, detectionColumn = -1;
    // A file without speeds is a legend, not a table: its errors say so.
    const bool givesSpeeds = std::any_of(fields.begin(), fields.end(), [](const std::string& field) {
        return internal::lowercase(trimmed(field)) == "speed_mps";
    });
    const std::string advice = givesSpeeds ? std::string() : legendOnlyAdvice;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const std::string column = internal::lowercase(trimmed(fields[i]));
        header.push_back(column);
        int* slot = nullptr;
        if (column == "value")
            slot = &valueColumn;
        else if (column == "name")
            slot = &nameColumn;
        else if (column == "speed_mps")
            slot = &speedColumn;
        else if (column == "fov_m")
            slot = &fovColumn;
        else if (column == "passable")
            slot = &passableColumn;
        else if (column == "color" || column == "colour")
            slot = &colorColumn;
        else if (column == "detection_probability")
            slot = &detectionColumn;
        if (slot == nullptr) {
            return failure(1, "column " + std::to_string(i + 1) + ": unknown column \"" + trimmed(fields[i]) +
                                  "\" (expected value,name,speed_mps,fov_m,passable and optionally color, "
                                  "detection_probability)" +
                                  advice);
        }
        if (*slot >= 0)
            return failure(1, "column " + std::to_string(i + 1) + ": \"" + column + "\" appears twice");
        *slot = static_cast<int>(i);
    }
    for (const std::string& required : requiredColumns) {
        if (std::find(header.begin(), header.end(), required) == header.end()) {
            return failure(1, "missing column \"" + required + "\"" + advice);
        }
    }

    ClassTable table;
    std::set<std::int32_t> seen;
    int lineNumber = 1;
    while (std::getline(stream, line)) {
        ++lineNumber;
        if (trimmed(line).empty())
            continue;
        if (!internal::splitCsvLine(line, fields))
            return failure(lineNumber, "unterminated quote");
        if (fields.size() != header.size()) {
            return failure(lineNumber, "expected " + std::to_string(header.size()) + " fields, found " +
                                           std::to_string(fields.size()));
        }
        const auto cell = [&](int column) { return trimmed(fields[static_cast<std::size_t>(column)]); };
        const auto bad = [&](int column, const std::string& what) {
            return failure(lineNumber, "column " + header[static_cast<std::size_t>(column)] + ": \"" +
                                           cell(column) + "\" " + what);
        };
        LandCoverClass entry;
        double number = 0.0;
        if (!parseDouble(cell(valueColumn), number) || number != std::floor(number) ||
            std::abs(number) > 2147483647.0) {
            return bad(valueColumn, "is not an integer class value");
        }
        entry.value = static_cast<std::int32_t>(number);
        if (!seen.insert(entry.value).second)
            return bad(valueColumn, "repeats a class value given earlier");
        entry.name = cell(nameColumn);
        if (!parseDouble(cell(speedColumn), entry.speedMetresPerSecond) ||
            !std::isfinite(entry.speedMetresPerSecond) || entry.speedMetresPerSecond < 0.0) {
            return bad(speedColumn, "is not a speed (a number >= 0 in m/s)");
        }
        if (!parseDouble(cell(fovColumn), entry.fieldOfViewMetres) ||
            !std::isfinite(entry.fieldOfViewMetres)) {
            return bad(fovColumn, "is not a field of view in metres");
        }
        if (!parseBoolean(cell(passableColumn), entry.passable))
            return bad(passableColumn, "is not true or false");
        if (colorColumn >= 0 && !cell(colorColumn).empty()) {
            const auto color = internal::parseColor(cell(colorColumn));
            if (!color)
                return bad(colorColumn, "is not a colour (#rrggbb)");
            entry.colorRgb = *color;
        } else if (withoutColour != nullptr) {
            withoutColour->insert(entry.value);
        }
        if (detectionColumn >= 0 && !cell(detectionColumn).empty()) {
            double probability = 0.0;
            if (!parseDouble(cell(detectionColumn), probability) ||
                !(probability >= 0.0 && probability <= 1.0))
                return bad(detectionColumn, "is not a probability from 0 to 1");
            entry.detectionProbability = probability;
        }
        if (entry.passable && entry.speedMetresPerSecond > 0.0 && !(entry.fieldOfViewMetres > 0.0)) {
            return bad(fovColumn, "must be > 0 for a passable class");
        }
        table.set(entry);
    }
    if (table.empty())
        return failure(lineNumber, "the table has no classes");
    if (const auto problem = table.validate())
        return Result<ClassTable>::failure(path + ": " + *problem);
    return table;
}

Status saveClassTableCsv(const ClassTable& table, const std::string& path) {
    // The detection column only where some class gives one, so tables without it read as before.
    const bool detection =
        std::any_of(table.classes().begin(), table.classes().end(),
                    [](const LandCoverClass& entry) { return entry.detectionProbability; });
    std::string text = std::string("value,name,speed_mps,fov_m,passable,color") +
                       (detection ? ",detection_probability" : "") + "\n";
    for (const LandCoverClass& entry : table.classes()) {
        text += std::to_string(entry.value) + "," + internal::quoteCsvField(entry.name) + "," +
                internal::formatShortest(entry.speedMetresPerSecond) + "," +
                internal::formatShortest(entry.fieldOfViewMetres) + "," +
                (entry.passable ? "true" : "false") + "," + internal::formatColor(entry.colorRgb);
        if (detection)
            text += "," +
                    (entry.detectionProbability ? internal::formatShortest(*entry.detectionProbability) : "");
        text += "\n";
    }
    return internal::writeFileAtomically(path, text);
}

ClassTable withColoursFrom(ClassTable table, const ClassesWithoutColour& withoutColour,
                           const ClassTable& reference) {
    for (const std::int32_t value : withoutColour) {
        const LandCoverClass* own = table.find(value);
        const LandCoverClass* coloured = reference.find(value);
        if (own == nullptr || coloured == nullptr)
            continue;
        LandCoverClass entry = *own;
        entry.colorRgb = coloured->colorRgb;
        table.set(entry);
    }
    return table;
}

ClassTable colourReference(const ClassTable& forRaster, const std::string& preset) {
    ClassTable reference = forRaster;
    if (preset.empty())
        return reference;
    if (auto rows = presetClassTable(preset))
        for (const LandCoverClass& row : rows.value().classes())
            if (reference.find(row.value) == nullptr)
                reference.set(row);
    return reference;
}

ClassTable missionClassTable(const ClassTable& ownRows, const std::string& preset, const LoadedRaster& raster,
                             const ClassesWithoutColour& withoutColour) {
    if (preset.empty() && ownRows.empty())
        return openingClassTable(raster).table;
    if (preset.empty()) {
        if (withoutColour.empty())
            return ownRows;
        const OpeningClassTable opening = openingClassTable(raster);
        return withColoursFrom(ownRows, withoutColour, colourReference(opening.table, opening.preset));
    }
    const ClassTable presetRows = classTableForRaster(raster, preset);
    ClassTable table = withColoursFrom(ownRows, withoutColour, colourReference(presetRows, preset));
    for (const auto& landCover : presetRows.classes())
        if (table.find(landCover.value) == nullptr)
            table.set(landCover);
    return table;
}

ClassTable classTableForRaster(const LoadedRaster& raster, const std::string& preset) {
    ClassTable defaults;
    if (!preset.empty()) {
        if (auto found = presetClassTable(preset))
            defaults = std::move(found.value());
    }
    ClassTable table;
    std::size_t index = 0;
    for (const auto& [value, count] : raster.classPixelCounts) {
        LandCoverClass entry;
        if (const LandCoverClass* known = defaults.find(value))
            entry = *known;
        else
            entry = internal::genericClass(value, index);
        ++index;
        const auto legend =
            std::find_if(raster.legend.begin(), raster.legend.end(),
                         [value = value](const LegendEntry& item) { return item.value == value; });
        if (legend != raster.legend.end()) {
            if (!legend->name.empty())
                entry.name = legend->name;
            if (legend->colorRgb)
                entry.colorRgb = *legend->colorRgb;
        }
        table.set(entry);
    }
    return table;
}

namespace {

// "category names + palette" -> "category names": where the names came from, for a sentence.
std::string describeLegendSource(std::string source) {
    if (const std::size_t plus = source.find(" + "); plus != std::string::npos)
        source.resize(plus);
    if (source == "qml")
        return "QGIS style file";
    if (source == "csv")
        return "legend CSV";
    return source;
}

} // namespace

OpeningClassTable openingClassTable(const LoadedRaster& raster) {
    OpeningClassTable opening;
    if (const auto product = internal::recogniseProduct(raster)) {
        opening.preset = product->preset;
        opening.table = classTableForRaster(raster, product->preset);
        opening.explanation = "Recognised " + product->productName + " from " + product->evidence +
                              ": applied preset " + product->preset + ".";
        return opening;
    }
    opening.table = classTableForRaster(raster);
    const std::size_t classes = opening.table.size();
    const auto named =
        std::count_if(opening.table.classes().begin(), opening.table.classes().end(),
                      [](const LandCoverClass& entry) { return entry.name.rfind("Class ", 0) != 0; });
    opening.fromLegendNames = named > 0;
    const std::string defaults = "speed 1 m/s, field of view 10 m and passable for every class until you set "
                                 "them or choose a preset";
    opening.explanation = opening.fromLegendNames
                              ? "Land cover not recognised as a known product: class names from the file's " +
                                    describeLegendSource(raster.legendSource) + "; " + defaults + "."
                              : "Land cover not recognised: " + std::to_string(classes) +
                                    " classes without names, each with its own colour; " + defaults + ".";
    return opening;
}

Status reconcileRasterWithTable(LoadedRaster& raster, const ClassTable& table, bool missingAsObstacles) {
    std::vector<std::int32_t> missing;
    std::int64_t missingPixels = 0;
    for (const auto& [value, count] : raster.classPixelCounts) {
        if (table.find(value) == nullptr) {
            missing.push_back(value);
            missingPixels += count;
        }
    }
    if (missing.empty())
        return {};
    std::string list;
    for (const std::int32_t value : missing)
        list += (list.empty() ? "" : ", ") + std::to_string(value);
    const std::string subject = missing.size() == 1 ? "class " + list + " has" : "classes " + list + " have";
    if (!missingAsObstacles) {
        return Status::failure(
            raster.path + ": " + subject +
            " no row in the class table (add rows, or treat missing classes as obstacles)");
    }
    ClassGrid& grid = raster.grid;
    if (grid.outside.empty())
        grid.outside.assign(grid.values.size(), 0);
    const std::set<std::int32_t> missingSet(missing.begin(), missing.end());
    for (std::size_t i = 0; i < grid.values.size(); ++i) {
        if (grid.outside[i] == 0 && missingSet.count(grid.values[i]) != 0)
            grid.outside[i] = ClassGrid::outsideUnlisted;
    }
    for (const std::int32_t value : missing)
        raster.classPixelCounts.erase(value);
    raster.warnings.push_back(subject + " no row in the class table: " + std::to_string(missingPixels) +
                              " pixels treated as outside the area");
    return {};
}

} // namespace mcpp::io
