#include "io/internal/LegendReader.hpp"

#include "io/internal/GdalSupport.hpp"
#include "io/internal/TextFiles.hpp"

#include <QByteArray>
#include <QXmlStreamReader>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gdal_rat.h>
#include <map>
#include <sstream>

namespace mcpp::io::internal {

namespace fs = std::filesystem;

namespace {

std::uint32_t rgbOf(int red, int green, int blue) {
    const auto clamp = [](int channel) { return static_cast<std::uint32_t>(std::clamp(channel, 0, 255)); };
    return (clamp(red) << 16U) | (clamp(green) << 8U) | clamp(blue);
}

bool parseInteger(const std::string& text, std::int32_t& value) {
    const std::string clean = trimmed(text);
    if (clean.empty())
        return false;
    char* end = nullptr;
    const double number = std::strtod(clean.c_str(), &end);
    if (end == nullptr || *end != '\0' || !std::isfinite(number) || number != std::floor(number))
        return false;
    if (number < -2147483648.0 || number > 2147483647.0)
        return false;
    value = static_cast<std::int32_t>(number);
    return true;
}

std::vector<LegendEntry> paletteLegend(GDALRasterBand& band,
                                       const std::map<std::int32_t, std::int64_t>& present) {
    std::vector<LegendEntry> entries;
    const GDALColorTable* table = band.GetColorTable();
    if (table == nullptr)
        return entries;
    for (const auto& [value, count] : present) {
        if (value < 0 || value >= table->GetColorEntryCount())
            continue;
        const GDALColorEntry* entry = table->GetColorEntry(value);
        if (entry == nullptr)
            continue;
        entries.push_back({value, {}, rgbOf(entry->c1, entry->c2, entry->c3)});
    }
    return entries;
}

std::vector<LegendEntry> categoryNameLegend(GDALRasterBand& band) {
    std::vector<LegendEntry> entries;
    char** names = band.GetCategoryNames();
    if (names == nullptr)
        return entries;
    for (int index = 0; names[index] != nullptr; ++index) {
        const std::string name = trimmed(names[index]);
        if (!name.empty())
            entries.push_back({index, name, std::nullopt});
    }
    return entries;
}

std::vector<LegendEntry> attributeTableLegend(GDALRasterBand& band) {
    std::vector<LegendEntry> entries;
    GDALRasterAttributeTable* table = band.GetDefaultRAT();
    if (table == nullptr || table->GetRowCount() == 0)
        return entries;
    int valueColumn = table->GetColOfUsage(GFU_MinMax);
    if (valueColumn < 0)
        valueColumn = table->GetColOfUsage(GFU_Min);
    int nameColumn = table->GetColOfUsage(GFU_Name);
    const int redColumn = table->GetColOfUsage(GFU_Red);
    const int greenColumn = table->GetColOfUsage(GFU_Green);
    const int blueColumn = table->GetColOfUsage(GFU_Blue);
    for (int column = 0; column < table->GetColumnCount(); ++column) {
        const std::string columnName = lowercase(table->GetNameOfCol(column));
        if (valueColumn < 0 && (columnName == "value" || columnName == "code" || columnName == "class"))
            valueColumn = column;
        if (nameColumn < 0 && table->GetTypeOfCol(column) == GFT_String &&
            (columnName == "name" || columnName == "label" || columnName == "class_name" ||
             columnName == "land_cover" || columnName == "category" || columnName == "description")) {
            nameColumn = column;
        }
    }
    double rowZero = 0.0;
    double binSize = 1.0;
    const bool linear = table->GetLinearBinning(&rowZero, &binSize);
    for (int row = 0; row < table->GetRowCount(); ++row) {
        double value = row;
        if (valueColumn >= 0)
            value = table->GetValueAsDouble(row, valueColumn);
        else if (linear)
            value = rowZero + row * binSize;
        if (!std::isfinite(value) || value != std::floor(value))
            continue;
        LegendEntry entry;
        entry.value = static_cast<std::int32_t>(value);
        if (nameColumn >= 0)
            entry.name = trimmed(table->GetValueAsString(row, nameColumn));
        if (redColumn >= 0 && greenColumn >= 0 && blueColumn >= 0) {
            entry.colorRgb =
                rgbOf(table->GetValueAsInt(row, redColumn), table->GetValueAsInt(row, greenColumn),
                      table->GetValueAsInt(row, blueColumn));
        }
        if (!entry.name.empty() || entry.colorRgb)
            entries.push_back(entry);
    }
    return entries;
}

// The first existing file among the candidates, else empty.
std::string firstExisting(const std::vector<fs::path>& candidates) {
    std::error_code error;
    for (const fs::path& candidate : candidates) {
        if (fs::is_regular_file(candidate, error))
            return candidate.string();
    }
    return {};
}

// A QGIS style beside the raster: <stem>.qml, <file>.qml, else the only .qml in the folder starting with
// the stem (clc_style.qml for clc.tif).
std::string findStyleFile(const fs::path& raster) {
    const fs::path folder = raster.parent_path().empty() ? fs::path(".") : raster.parent_path();
    const std::string stem = raster.stem().string();
    std::string found =
        firstExisting({folder / (stem + ".qml"), folder / (raster.filename().string() + ".qml")});
    if (!found.empty())
        return found;
    std::vector<std::string> matches;
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const fs::path candidate = it->path();
        if (lowercase(candidate.extension().string()) != ".qml")
            continue;
        if (candidate.filename().string().rfind(stem, 0) == 0)
            matches.push_back(candidate.string());
    }
    return matches.size() == 1 ? matches.front() : std::string();
}

std::string findLegendCsv(const fs::path& raster) {
    const fs::path folder = raster.parent_path().empty() ? fs::path(".") : raster.parent_path();
    const std::string stem = raster.stem().string();
    return firstExisting({folder / (stem + ".csv"), folder / (stem + "_legend.csv"),
                          folder / (stem + ".legend.csv"), folder / (raster.filename().string() + ".csv")});
}

} // namespace

std::optional<std::uint32_t> parseColor(const std::string& text) {
    const std::string clean = trimmed(text);
    if (clean.size() == 7 && clean[0] == '#') {
        unsigned value = 0;
        for (std::size_t i = 1; i < 7; ++i) {
            const char digit = static_cast<char>(std::tolower(static_cast<unsigned char>(clean[i])));
            value <<= 4U;
            if (digit >= '0' && digit <= '9')
                value |= static_cast<unsigned>(digit - '0');
            else if (digit >= 'a' && digit <= 'f')
                value |= static_cast<unsigned>(digit - 'a' + 10);
            else
                return std::nullopt;
        }
        return value;
    }
    // "r,g,b[,a]" (QGIS) or "r-g-b" (CORINE legends)
    const char separator = clean.find(',') != std::string::npos ? ',' : '-';
    std::vector<int> channels;
    std::stringstream stream(clean);
    std::string part;
    while (std::getline(stream, part, separator)) {
        std::int32_t channel = 0;
        if (!parseInteger(part, channel) || channel < 0 || channel > 255)
            return std::nullopt;
        channels.push_back(channel);
    }
    if (channels.size() != 3 && channels.size() != 4)
        return std::nullopt;
    return rgbOf(channels[0], channels[1], channels[2]);
}

std::string formatColor(std::uint32_t rgb) {
    char text[8];
    std::snprintf(text, sizeof text, "#%06x", rgb & 0xFFFFFFU);
    return text;
}

Result<std::vector<LegendEntry>> readLegendCsv(const std::string& path) {
    auto contents = readWholeFile(path);
    if (!contents)
        return Result<std::vector<LegendEntry>>::failure(contents.error());
    return parseLegendCsv(contents.value(), path);
}

Result<std::vector<LegendEntry>> parseLegendCsv(const std::string& text, const std::string& path) {
    using Entries = std::vector<LegendEntry>;
    std::stringstream stream(text);
    std::string line;
    std::vector<std::string> fields;
    if (!std::getline(stream, line) || !splitCsvLine(line, fields)) {
        return Result<Entries>::failure(path + ": line 1: expected a header");
    }
    int valueColumn = -1, nameColumn = -1, colorColumn = -1, red = -1, green = -1, blue = -1;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        std::string header = lowercase(trimmed(fields[i]));
        if (!header.empty() && static_cast<unsigned char>(header[0]) == 0xEF)
            header.erase(0, 3); // UTF-8 BOM
        const int column = static_cast<int>(i);
        if (header == "value" || header == "code" || header == "grid_code" || header == "class_value") {
            if (valueColumn < 0)
                valueColumn = column;
        } else if (header == "name" || header == "label" || header == "label3" || header == "class_name" ||
                   header == "class" || header == "description") {
            // LABEL3 is CORINE's most detailed level; prefer it over LABEL1/LABEL2.
            if (nameColumn < 0 || header == "label3")
                nameColumn = column;
        } else if (header == "color" || header == "colour" || header == "rgb") {
            colorColumn = column;
        } else if (header == "r" || header == "red") {
            red = column;
        } else if (header == "g" || header == "green") {
            green = column;
        } else if (header == "b" || header == "blue") {
            blue = column;
        }
    }
    if (valueColumn < 0)
        return Result<Entries>::failure(path + ": line 1: no value column (value, code or grid_code)");
    Entries entries;
    int lineNumber = 1;
    while (std::getline(stream, line)) {
        ++lineNumber;
        if (trimmed(line).empty())
            continue;
        if (!splitCsvLine(line, fields)) {
            return Result<Entries>::failure(path + ": line " + std::to_string(lineNumber) +
                                            ": unterminated quote");
        }
        const auto field = [&](int column) {
            return column >= 0 && static_cast<std::size_t>(column) < fields.size()
                       ? trimmed(fields[static_cast<std::size_t>(column)])
                       : std::string();
        };
        LegendEntry entry;
        if (!parseInteger(field(valueColumn), entry.value)) {
            return Result<Entries>::failure(path + ": line " + std::to_string(lineNumber) + ", column " +
                                            std::to_string(valueColumn + 1) + ": \"" + field(valueColumn) +
                                            "\" is not an integer class value");
        }
        entry.name = field(nameColumn);
        if (colorColumn >= 0)
            entry.colorRgb = parseColor(field(colorColumn));
        std::int32_t r = 0, g = 0, b = 0;
        if (!entry.colorRgb && red >= 0 && green >= 0 && blue >= 0 && parseInteger(field(red), r) &&
            parseInteger(field(green), g) && parseInteger(field(blue), b)) {
            entry.colorRgb = rgbOf(r, g, b);
        }
        entries.push_back(entry);
    }
    return entries;
}

Result<std::vector<LegendEntry>> readQgisStyleLegend(const std::string& path) {
    auto contents = readWholeFile(path);
    if (!contents)
        return Result<std::vector<LegendEntry>>::failure(contents.error());
    return parseQgisStyleLegend(contents.value(), path);
}

Result<std::vector<LegendEntry>> parseQgisStyleLegend(const std::string& text, const std::string& path) {
    using Entries = std::vector<LegendEntry>;
    // Styles exported by some tools carry text before the XML; start at the first tag.
    std::size_t start = text.find("<?xml");
    if (start == std::string::npos)
        start = text.find("<!DOCTYPE");
    if (start == std::string::npos)
        start = text.find("<qgis");
    if (start == std::string::npos)
        return Result<Entries>::failure(path + ": not a QGIS style (no <qgis> element)");
    QXmlStreamReader xml(QByteArray(text.data() + start, static_cast<qsizetype>(text.size() - start)));

    Entries entries;
    struct Category {
        std::int32_t value;
        std::string label;
        std::string symbol;
    };
    std::vector<Category> categories;
    std::map<std::string, std::uint32_t> symbolColors;
    std::string currentSymbol;
    int symbolDepth = 0;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::EndElement && xml.name() == QLatin1String("symbol")) {
            if (--symbolDepth == 0)
                currentSymbol.clear();
            continue;
        }
        if (token != QXmlStreamReader::StartElement)
            continue;
        const auto attributes = xml.attributes();
        const auto attribute = [&](const char* key) {
            return attributes.value(QLatin1String(key)).toString().toStdString();
        };
        const auto name = xml.name();
        if (name == QLatin1String("paletteEntry") || name == QLatin1String("item")) {
            // Paletted renderer entries and pseudocolour (classified) ramp items.
            LegendEntry entry;
            if (!parseInteger(attribute("value"), entry.value))
                continue;
            entry.name = trimmed(attribute("label"));
            entry.colorRgb = parseColor(attribute("color"));
            entries.push_back(entry);
        } else if (name == QLatin1String("category")) {
            Category category{};
            if (!parseInteger(attribute("value"), category.value))
                continue;
            category.label = trimmed(attribute("label"));
            category.symbol = attribute("symbol");
            categories.push_back(category);
        } else if (name == QLatin1String("symbol")) {
            if (symbolDepth++ == 0)
                currentSymbol = attribute("name");
        } else if (symbolDepth > 0 && !symbolColors.count(currentSymbol) &&
                   ((name == QLatin1String("prop") && attribute("k") == "color") ||
                    (name == QLatin1String("Option") && attribute("name") == "color"))) {
            const std::string value = name == QLatin1String("prop") ? attribute("v") : attribute("value");
            if (const auto color = parseColor(value))
                symbolColors[currentSymbol] = *color;
        }
    }
    if (xml.hasError() && entries.empty() && categories.empty()) {
        return Result<Entries>::failure(path + ": line " + std::to_string(xml.lineNumber()) + ": " +
                                        xml.errorString().toStdString());
    }
    for (const Category& category : categories) {
        LegendEntry entry{category.value, category.label, std::nullopt};
        if (const auto found = symbolColors.find(category.symbol); found != symbolColors.end())
            entry.colorRgb = found->second;
        entries.push_back(entry);
    }
    if (entries.empty())
        return Result<Entries>::failure(path + ": no paletted, classified or categorized classes found");
    return entries;
}

std::vector<LegendEntry> parseMetadataLegend(const std::string& text) {
    std::vector<LegendEntry> entries;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        const std::string clean = trimmed(line);
        const std::size_t end = clean.find_first_of(" \t:=");
        std::int32_t value = 0;
        if (end == std::string::npos || !parseInteger(clean.substr(0, end), value))
            continue;
        const std::size_t nameStart = clean.find_first_not_of(" \t:=", end);
        if (nameStart != std::string::npos)
            entries.push_back({value, clean.substr(nameStart), std::nullopt});
    }
    return entries;
}

namespace {

// Every "key=value" item of the default metadata domain of the band and its dataset, and the band's
// description: where products name themselves (ESA WorldCover's copyright and legend items).
std::string metadataTextOf(GDALRasterBand& band) {
    std::string text;
    const auto append = [&text](GDALMajorObject& object) {
        if (char** items = object.GetMetadata(); items != nullptr)
            for (int index = 0; items[index] != nullptr; ++index)
                text += std::string(items[index]) + "\n";
        if (const char* description = object.GetDescription(); description != nullptr)
            text += std::string("description=") + description + "\n";
    };
    if (GDALDataset* dataset = band.GetDataset(); dataset != nullptr) {
        if (char** items = dataset->GetMetadata(); items != nullptr)
            for (int index = 0; items[index] != nullptr; ++index)
                text += std::string(items[index]) + "\n";
    }
    append(band);
    return text;
}

std::vector<LegendEntry> metadataItemLegend(GDALRasterBand& band) {
    for (GDALMajorObject* object :
         {static_cast<GDALMajorObject*>(&band), static_cast<GDALMajorObject*>(band.GetDataset())}) {
        if (object == nullptr)
            continue;
        for (const char* key : {"legend", "LEGEND", "Legend"})
            if (const char* item = object->GetMetadataItem(key); item != nullptr)
                if (auto entries = parseMetadataLegend(item); !entries.empty())
                    return entries;
    }
    return {};
}

} // namespace

void readRasterLegend(GDALRasterBand& band, const std::string& rasterPath, LoadedRaster& raster) {
    raster.metadataText = metadataTextOf(band);
    std::vector<LegendEntry> named;
    std::string source;
    if (auto fromTable = attributeTableLegend(band); !fromTable.empty()) {
        named = std::move(fromTable);
        source = "attribute table";
    } else if (auto fromCategories = categoryNameLegend(band); !fromCategories.empty()) {
        named = std::move(fromCategories);
        source = "category names";
    } else if (auto fromMetadata = metadataItemLegend(band); !fromMetadata.empty()) {
        named = std::move(fromMetadata);
        source = "legend metadata";
    } else if (const std::string style = findStyleFile(rasterPath); !style.empty()) {
        auto fromStyle = readQgisStyleLegend(style);
        if (fromStyle) {
            named = std::move(fromStyle.value());
            source = "qml";
        } else {
            raster.warnings.push_back("legend style ignored: " + fromStyle.error());
        }
    }
    if (named.empty()) {
        if (const std::string csv = findLegendCsv(rasterPath); !csv.empty()) {
            auto fromCsv = readLegendCsv(csv);
            if (fromCsv) {
                named = std::move(fromCsv.value());
                source = "csv";
            } else {
                raster.warnings.push_back("legend CSV ignored: " + fromCsv.error());
            }
        }
    }
    const std::vector<LegendEntry> palette = paletteLegend(band, raster.classPixelCounts);
    if (named.empty()) {
        raster.legend = palette;
        raster.legendSource = palette.empty() ? std::string() : "palette";
        return;
    }
    bool usedPalette = false;
    for (LegendEntry& entry : named) {
        if (entry.colorRgb)
            continue;
        const auto match = std::find_if(palette.begin(), palette.end(), [&](const LegendEntry& colour) {
            return colour.value == entry.value;
        });
        if (match != palette.end()) {
            entry.colorRgb = match->colorRgb;
            usedPalette = true;
        }
    }
    std::stable_sort(named.begin(), named.end(),
                     [](const LegendEntry& a, const LegendEntry& b) { return a.value < b.value; });
    raster.legend = std::move(named);
    raster.legendSource = usedPalette ? source + " + palette" : source;
}

} // namespace mcpp::io::internal
