#include "core/model/DetectionLayer.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/DatasetFile.hpp"
#include "io/internal/GdalSupport.hpp"

#include <algorithm>
#include <cmath>
#include <gdal_priv.h>

namespace mcpp::io {

namespace {

using internal::QuietGdalErrors;

// No probability is negative, and QGIS shows a number as nodata more readily than NaN.
constexpr float noDetectionData = -1.0F;

// The part of the grid the file holds: the box around the cells robots go to, on the grid's lattice (a small
// area on a large raster gives a small file).
struct Window {
    int firstColumn = 0;
    int firstRow = 0;
    int columns = 0;
    int rows = 0;
};

Window windowOfData(const DetectionGrid& grid) {
    int west = grid.columns;
    int east = -1;
    int north = grid.rows;
    int south = -1;
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            const std::size_t index = static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.columns) +
                                      static_cast<std::size_t>(column);
            if (std::isnan(grid.probability[index]) && std::isnan(grid.required[index]))
                continue;
            west = std::min(west, column);
            east = std::max(east, column);
            north = std::min(north, row);
            south = std::max(south, row);
        }
    if (east < 0)
        return {};
    return {west, north, east - west + 1, south - north + 1};
}

Status describe(internal::DatasetFile& file, const ExportContext& context, const DetectionGrid& grid,
                const Window& window) {
    if (Status placed =
            file.placeOnMap(context.georeference, grid.originX + window.firstColumn * grid.cellSize,
                            grid.originY - window.firstRow * grid.cellSize, grid.cellSize);
        !placed)
        return placed;
    file.dataset().SetMetadataItem("MCPP_VALUES",
                                   "band 1: chance a target in the cell is seen by the plan; band 2: "
                                   "chance it had to be seen (0 where the land cover hides targets); "
                                   "-1 where no robot goes");
    file.dataset().SetMetadataItem("MCPP_PLANNER", context.plan.planner.c_str());
    return {};
}

Status writeBand(GDALRasterBand& band, const std::vector<float>& values, const DetectionGrid& grid,
                 const Window& window, const char* description, const ExportContext& context,
                 const std::string& path) {
    band.SetDescription(description);
    band.SetNoDataValue(noDetectionData);
    std::vector<float> line(static_cast<std::size_t>(window.columns));
    for (int row = 0; row < window.rows; ++row) {
        if (context.cancelled())
            return Status::failure(path + ": cancelled");
        for (int column = 0; column < window.columns; ++column) {
            const float value = values[static_cast<std::size_t>(window.firstRow + row) *
                                           static_cast<std::size_t>(grid.columns) +
                                       static_cast<std::size_t>(window.firstColumn + column)];
            line[static_cast<std::size_t>(column)] = std::isnan(value) ? noDetectionData : value;
        }
        if (band.RasterIO(GF_Write, 0, row, window.columns, 1, line.data(), window.columns, 1, GDT_Float32, 0,
                          0, nullptr) != CE_None)
            return Status::failure(path + ": cannot write row " + std::to_string(row) +
                                   QuietGdalErrors::detail());
    }
    return {};
}

} // namespace

Status writeDetectionRaster(const ExportContext& context, const std::string& path) {
    QuietGdalErrors quiet;
    const DetectionLayer* layer = detectionLayerOf(context.plan);
    if (layer == nullptr)
        return Status::failure(path + ": the plan has no detection layer (only CPPIED plans model what the "
                                      "sensor sees)");
    const DetectionGrid& grid = layer->grid();
    const Window window = windowOfData(grid);
    if (window.columns == 0 || window.rows == 0)
        return Status::failure(path + ": the plan has no cells");
    internal::DatasetFile file(path);
    const char* const options[] = {"TILED=YES",   "BLOCKXSIZE=256", "BLOCKYSIZE=256",   "COMPRESS=DEFLATE",
                                   "PREDICTOR=3", "ZLEVEL=6",       "BIGTIFF=IF_SAFER", nullptr};
    if (Status status = file.create("GTiff", window.columns, window.rows, 2, GDT_Float32, options); !status)
        return status;
    if (Status status = describe(file, context, grid, window); !status)
        return status;
    GDALDataset& dataset = file.dataset();
    if (Status status = writeBand(*dataset.GetRasterBand(1), grid.probability, grid, window,
                                  "detection probability", context, path);
        !status)
        return status;
    if (Status status = writeBand(*dataset.GetRasterBand(2), grid.required, grid, window,
                                  "required probability", context, path);
        !status)
        return status;
    return file.commit(Sync::BySystem);
}

} // namespace mcpp::io
