#include "core/model/RobotColours.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/DatasetFile.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/PlanGeometry.hpp"

#include <gdal_priv.h>
#include <limits>

namespace mcpp::io {

namespace {

using internal::QuietGdalErrors;

// Robots by their number from 1, as in every other file; 0 is nodata so that the number is the value.
struct Encoding {
    GDALDataType type = GDT_Byte;
    unsigned nodata = 0;
    unsigned unreachable = 255;
};

Encoding encodingFor(int robots) {
    if (robots < 255)
        return {};
    return {GDT_UInt16, 0, 65535};
}

GDALColorTable colourTable(int robots, const Encoding& encoding) {
    GDALColorTable table;
    for (int robot = 0; robot < robots; ++robot) {
        const RgbColour colour = robotColour(robot);
        const GDALColorEntry entry{colour.red, colour.green, colour.blue, 255};
        table.SetColorEntry(robotNumber(robot), &entry);
    }
    const GDALColorEntry grey{160, 160, 160, 255};
    table.SetColorEntry(static_cast<int>(encoding.unreachable), &grey);
    const GDALColorEntry transparent{0, 0, 0, 0};
    table.SetColorEntry(static_cast<int>(encoding.nodata), &transparent);
    return table;
}

// The labels as the file stores them, one row at a time.
template <typename Value>
Status writeRows(GDALRasterBand& band, const LabelGrid& labels, const Encoding& encoding,
                 const ExportContext& context, const std::string& path) {
    std::vector<Value> row(static_cast<std::size_t>(labels.columns));
    for (int r = 0; r < labels.rows; ++r) {
        if (context.cancelled())
            return Status::failure(path + ": cancelled");
        for (int c = 0; c < labels.columns; ++c) {
            const std::int32_t label = labels.labels[labels.index(c, r)];
            const unsigned value = label >= 0                  ? static_cast<unsigned>(robotNumber(label))
                                   : label == unreachableLabel ? encoding.unreachable
                                                               : encoding.nodata;
            row[static_cast<std::size_t>(c)] = static_cast<Value>(value);
        }
        if (band.RasterIO(GF_Write, 0, r, labels.columns, 1, row.data(), labels.columns, 1, encoding.type, 0,
                          0, nullptr) != CE_None) {
            return Status::failure(path + ": cannot write row " + std::to_string(r) +
                                   QuietGdalErrors::detail());
        }
    }
    return {};
}

Status describe(internal::DatasetFile& file, const ExportContext& context, const LabelGrid& labels) {
    if (Status placed =
            file.placeOnMap(context.georeference, labels.originX, labels.originY, labels.pixelSize);
        !placed)
        return placed;
    GDALDataset& dataset = file.dataset();
    dataset.SetMetadataItem("MCPP_VALUES",
                            "robot number from 1; 255 (65535 as UInt16) passable but unreachable; 0 nodata");
    dataset.SetMetadataItem("MCPP_PLANNER", context.plan.planner.c_str());
    return {};
}

} // namespace

Status writeRegionRaster(const ExportContext& context, const std::string& path) {
    QuietGdalErrors quiet;
    const LabelGrid& labels = context.outlines().labels;
    if (labels.columns == 0 || labels.rows == 0)
        return Status::failure(path + ": the plan has no cells");
    const int robots = internal::robotCount(context.plan);
    const Encoding encoding = encodingFor(robots);
    internal::DatasetFile file(path);
    const char* const options[] = {"TILED=YES",   "BLOCKXSIZE=256", "BLOCKYSIZE=256",   "COMPRESS=DEFLATE",
                                   "PREDICTOR=2", "ZLEVEL=6",       "BIGTIFF=IF_SAFER", nullptr};
    if (Status status = file.create("GTiff", labels.columns, labels.rows, 1, encoding.type, options); !status)
        return status;
    if (Status status = describe(file, context, labels); !status)
        return status;
    GDALDataset& dataset = file.dataset();
    GDALRasterBand& band = *dataset.GetRasterBand(1);
    band.SetNoDataValue(encoding.nodata);
    GDALColorTable table = colourTable(robots, encoding);
    band.SetColorTable(&table);
    band.SetColorInterpretation(GCI_PaletteIndex);
    const Status written = encoding.type == GDT_Byte
                               ? writeRows<std::uint8_t>(band, labels, encoding, context, path)
                               : writeRows<std::uint16_t>(band, labels, encoding, context, path);
    if (!written)
        return written;
    return file.commit(Sync::BySystem);
}

} // namespace mcpp::io
