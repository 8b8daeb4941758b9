// libFuzzer harness: a raster's own legend as GDAL hands it over (category names, or an attribute table
// of value and name columns), from any bytes, one entry per line; never a crash.
#include "io/LoadedRaster.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/LegendReader.hpp"

#include <cstdint>
#include <gdal_priv.h>
#include <gdal_rat.h>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::stringstream stream(text);
    std::string line;
    while (std::getline(stream, line) && result.size() < 4096)
        result.push_back(line);
    return result;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    mcpp::io::internal::ensureGdalRegistered();
    const bool asTable = (data[0] & 1) != 0;
    const std::vector<std::string> entries =
        lines(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDataset* dataset = memory->Create("", 4, 4, 1, GDT_Byte, nullptr);
    GDALRasterBand* band = dataset->GetRasterBand(1);
    if (asTable) {
        GDALDefaultRasterAttributeTable table;
        table.CreateColumn("Value", GFT_Integer, GFU_MinMax);
        table.CreateColumn("Class_Name", GFT_String, GFU_Name);
        table.SetRowCount(static_cast<int>(entries.size()));
        for (std::size_t row = 0; row < entries.size(); ++row) {
            const std::string& entry = entries[row];
            const auto comma = entry.find(',');
            table.SetValue(static_cast<int>(row), 0, entry.substr(0, comma).c_str());
            table.SetValue(static_cast<int>(row), 1,
                           comma == std::string::npos ? "" : entry.substr(comma + 1).c_str());
        }
        band->SetDefaultRAT(&table);
    } else {
        std::vector<char*> names;
        for (const std::string& entry : entries)
            names.push_back(const_cast<char*>(entry.c_str()));
        names.push_back(nullptr);
        band->SetCategoryNames(names.data());
    }
    mcpp::io::LoadedRaster raster;
    mcpp::io::internal::readRasterLegend(*band, "/nonexistent/fuzz.tif", raster);
    GDALClose(dataset);
    return 0;
}
