#include "core/model/HumanUnits.hpp"
#include "io/LoadedRaster.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/LegendReader.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gdal_utils.h>
#include <unordered_map>
#include <vector>

namespace mcpp::io {

namespace {

// Where true north points on the grid at its centre (ClassGrid::trueNorthRadians): the bearing of the grid's
// +y over a kilometre, 0 where the map has no CRS.
double trueNorthRadians(const GeoReference& georeference, const ClassGrid& grid) {
    if (!georeference.hasCrs())
        return 0.0;
    const MapPoint centre{grid.originX + grid.width() / 2.0, grid.originY - grid.height() / 2.0};
    const auto from = georeference.toWgs84(centre);
    const auto to = georeference.toWgs84(MapPoint{centre.x, centre.y + 1000.0});
    if (!from || !to)
        return 0.0;
    const double degrees = std::acos(-1.0) / 180.0;
    const double east = std::remainder(to.value().longitude - from.value().longitude, 360.0) *
                        std::cos(from.value().latitude * degrees);
    const double north = to.value().latitude - from.value().latitude;
    return std::isfinite(east) && std::isfinite(north) && (east != 0.0 || north != 0.0)
               ? std::atan2(east, north)
               : 0.0;
}

using internal::DatasetPointer;
using internal::QuietGdalErrors;
namespace fs = std::filesystem;

using RasterResult = Result<LoadedRaster>;

// Largest number of buffer pixels read in one RasterIO call: keeps memory flat on big rasters.
constexpr std::int64_t chunkPixels = 1 << 22;

Status checkFileReadable(const std::string& path) {
    if (path.empty())
        return Status::failure("no raster file given");
    if (path.rfind("/vsi", 0) == 0)
        return {}; // GDAL virtual file systems: let GDAL judge
    std::error_code error;
    if (!fs::exists(path, error))
        return Status::failure(internal::fileNotFound(path));
    if (fs::is_directory(path, error))
        return Status::failure(path + ": is a folder, not a raster file");
    if (fs::is_regular_file(path, error) && fs::file_size(path, error) == 0)
        return Status::failure(path + ": file is empty");
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
        return Status::failure(path + ": cannot be read (permission denied?)");
    return {};
}

bool isColourChannel(GDALColorInterp interpretation) {
    return interpretation == GCI_RedBand || interpretation == GCI_GreenBand ||
           interpretation == GCI_BlueBand || interpretation == GCI_AlphaBand;
}

bool isFloatType(GDALDataType type) {
    return type == GDT_Float32 || type == GDT_Float64;
}

bool isComplexType(GDALDataType type) {
    return GDALDataTypeIsComplex(type) != 0;
}

// The UTM zone of the raster's centre, on the raster's own datum where it is not WGS84.
std::unique_ptr<OGRSpatialReference> utmForCentre(const OGRSpatialReference& geographic, double longitude,
                                                  double latitude) {
    while (longitude >= 180.0)
        longitude -= 360.0;
    while (longitude < -180.0)
        longitude += 360.0;
    const int zone = std::clamp(static_cast<int>(std::floor((longitude + 180.0) / 6.0)) + 1, 1, 60);
    const bool north = latitude >= 0.0;
    auto utm = internal::makeSpatialReference();
    const auto wgs84 = internal::wgs84SpatialReference();
    if (geographic.IsSameGeogCS(wgs84.get())) {
        if (utm->importFromEPSG((north ? 32600 : 32700) + zone) == OGRERR_NONE)
            return utm;
        utm = internal::makeSpatialReference();
    }
    utm->CopyGeogCSFrom(&geographic);
    utm->SetUTM(zone, north ? TRUE : FALSE);
    const char* datum = geographic.GetAttrValue("DATUM");
    utm->SetProjCS(("UTM zone " + std::to_string(zone) + (north ? "N" : "S") + " (" +
                    (datum ? datum : "unknown datum") + ")")
                       .c_str());
    return utm;
}

// Nearest-neighbour warp of one band into the UTM frame as a lazily computed VRT: nothing is held in memory
// beyond what a read asks for. Out-of-footprint and nodata pixels become NaN.
// The caller keeps `selected` (the band-selection VRT) alive until the warped dataset is closed.
// With a target size, the warp resamples straight to it by the class mode (using the source's overviews
// where it has them), so a raster far above the pixel budget is never warped at full resolution.
DatasetPointer warpToUtm(GDALDataset& source, int band, const OGRSpatialReference& utm,
                         DatasetPointer& selected, std::string& error, int targetColumns = 0,
                         int targetRows = 0) {
    GDALDatasetH input = GDALDataset::ToHandle(&source);
    if (source.GetRasterCount() > 1 && !selected) {
        const std::string bandText = std::to_string(band);
        const char* translateArguments[] = {"-of", "VRT", "-b", bandText.c_str(), nullptr};
        GDALTranslateOptions* translateOptions =
            GDALTranslateOptionsNew(const_cast<char**>(translateArguments), nullptr);
        selected.reset(GDALDataset::FromHandle(GDALTranslate("", input, translateOptions, nullptr)));
        GDALTranslateOptionsFree(translateOptions);
        if (!selected) {
            error = "could not select band " + bandText + QuietGdalErrors::detail();
            return nullptr;
        }
    }
    if (selected)
        input = GDALDataset::ToHandle(selected.get());
    const std::string wkt = internal::wktOf(utm);
    const std::string columnsText = std::to_string(targetColumns);
    const std::string rowsText = std::to_string(targetRows);
    std::vector<const char*> warpArguments{"-of", "VRT",     "-t_srs",     wkt.c_str(),
                                           "-ot", "Float64", "-dstnodata", "nan"};
    if (targetColumns > 0 && targetRows > 0) {
        for (const char* argument : {"-r", "mode", "-ts"})
            warpArguments.push_back(argument);
        warpArguments.push_back(columnsText.c_str());
        warpArguments.push_back(rowsText.c_str());
    } else {
        warpArguments.push_back("-r");
        warpArguments.push_back("near");
    }
    warpArguments.push_back(nullptr);
    GDALWarpAppOptions* warpOptions =
        GDALWarpAppOptionsNew(const_cast<char**>(warpArguments.data()), nullptr);
    int usageError = 0;
    DatasetPointer warped(
        GDALDataset::FromHandle(GDALWarp("", nullptr, 1, &input, warpOptions, &usageError)));
    GDALWarpAppOptionsFree(warpOptions);
    if (!warped) {
        error = "could not warp to " + std::string(utm.GetName()) + QuietGdalErrors::detail();
        return nullptr;
    }
    return warped;
}

struct ReadPlan {
    int sourceColumns = 0;
    int sourceRows = 0;
    int columns = 0; // after coarsening
    int rows = 0;
    bool coarsened = false;
};

// "21.9 million", "1.3 billion": a count a person reads at once.
std::string countText(double count) {
    return count >= 999.5e6 ? formatQuantity(count / 1e9, 3) + " billion"
                            : formatQuantity(count / 1e6, 3) + " million";
}

// "4471 x 4887 pixels (21.9 million)".
std::string pixelsText(int columns, int rows) {
    return std::to_string(columns) + " x " + std::to_string(rows) + " pixels (" +
           countText(static_cast<double>(columns) * rows) + ")";
}

std::string budgetText(std::int64_t budget) {
    return "the budget of " + countText(static_cast<double>(budget)) + " pixels";
}

ReadPlan planRead(int columns, int rows, std::int64_t budget) {
    ReadPlan plan{columns, rows, columns, rows, false};
    const std::int64_t pixels = static_cast<std::int64_t>(columns) * rows;
    if (budget <= 0 || pixels <= budget)
        return plan;
    double scale = std::sqrt(static_cast<double>(pixels) / static_cast<double>(budget));
    for (;;) {
        plan.columns = std::max(1, static_cast<int>(std::floor(columns / scale)));
        plan.rows = std::max(1, static_cast<int>(std::floor(rows / scale)));
        if (static_cast<std::int64_t>(plan.columns) * plan.rows <= budget ||
            (plan.columns == 1 && plan.rows == 1))
            break;
        scale *= 1.01;
    }
    plan.coarsened = true;
    return plan;
}

// Reads the band into raster.grid (values, outside) and raster.classPixelCounts, chunk by chunk.
Status readClasses(GDALRasterBand& band, const ReadPlan& plan, const std::string& path, int bandNumber,
                   LoadedRaster& raster) {
    ClassGrid& grid = raster.grid;
    grid.columns = plan.columns;
    grid.rows = plan.rows;
    const auto cellCount = static_cast<std::size_t>(plan.columns) * static_cast<std::size_t>(plan.rows);
    grid.values.assign(cellCount, 0);
    grid.outside.assign(cellCount, 0);

    const GDALDataType type = band.GetRasterDataType();
    const bool floating = isFloatType(type);
    int hasNodata = 0;
    const double nodata = band.GetNoDataValue(&hasNodata);
    const bool nodataIsNan = hasNodata != 0 && std::isnan(nodata);
    const auto isNodata = [&](double value) {
        if (hasNodata == 0)
            return false;
        if (nodataIsNan)
            return std::isnan(value);
        if (type == GDT_Float32)
            return static_cast<float>(value) == static_cast<float>(nodata);
        return value == nodata;
    };

    int blockColumns = 0;
    int blockRows = 0;
    band.GetBlockSize(&blockColumns, &blockRows);
    int chunkRows = static_cast<int>(std::max<std::int64_t>(1, chunkPixels / std::max(1, plan.columns)));
    if (!plan.coarsened && blockRows > 0 && chunkRows > blockRows)
        chunkRows -= chunkRows % blockRows; // whole blocks
    chunkRows = std::min(chunkRows, plan.rows);

    std::vector<double> buffer(static_cast<std::size_t>(chunkRows) * static_cast<std::size_t>(plan.columns));
    // A mask of its own (a .msk side file, an internal mask, an alpha band) marks pixels as nodata too.
    const int maskFlags = band.GetMaskFlags();
    GDALRasterBand* mask = (maskFlags & (GMF_ALL_VALID | GMF_NODATA)) == 0 ? band.GetMaskBand() : nullptr;
    std::vector<std::uint8_t> maskBuffer(mask != nullptr ? buffer.size() : 0);
    std::unordered_map<std::int32_t, std::int64_t> counts;
    std::int64_t nanPixels = 0;
    std::int64_t outsidePixels = 0;
    const double rowScale = static_cast<double>(plan.sourceRows) / plan.rows;

    for (int firstRow = 0; firstRow < plan.rows; firstRow += chunkRows) {
        const int rowsHere = std::min(chunkRows, plan.rows - firstRow);
        GDALRasterIOExtraArg extra;
        INIT_RASTERIO_EXTRA_ARG(extra);
        int sourceFirstRow = firstRow;
        int sourceRowCount = rowsHere;
        if (plan.coarsened) {
            // Mode keeps a real class (no averaging of codes) and ignores nodata.
            extra.eResampleAlg = GRIORA_Mode;
            extra.bFloatingPointWindowValidity = TRUE;
            extra.dfXOff = 0.0;
            extra.dfXSize = plan.sourceColumns;
            extra.dfYOff = firstRow * rowScale;
            extra.dfYSize = rowsHere * rowScale;
            sourceFirstRow = static_cast<int>(std::floor(extra.dfYOff));
            const int lastRow =
                std::min(plan.sourceRows, static_cast<int>(std::ceil(extra.dfYOff + extra.dfYSize)));
            sourceRowCount = std::max(1, lastRow - sourceFirstRow);
            extra.dfYSize = std::min(extra.dfYSize, plan.sourceRows - extra.dfYOff);
        }
        if (band.RasterIO(GF_Read, 0, sourceFirstRow, plan.sourceColumns, sourceRowCount, buffer.data(),
                          plan.columns, rowsHere, GDT_Float64, 0, 0, &extra) != CE_None) {
            return Status::failure(path + ": read failed at row " + std::to_string(sourceFirstRow) +
                                   " of band " + std::to_string(bandNumber) + QuietGdalErrors::detail());
        }
        if (mask != nullptr) {
            extra.eResampleAlg = GRIORA_NearestNeighbour;
            if (mask->RasterIO(GF_Read, 0, sourceFirstRow, plan.sourceColumns, sourceRowCount,
                               maskBuffer.data(), plan.columns, rowsHere, GDT_Byte, 0, 0,
                               &extra) != CE_None) {
                return Status::failure(path + ": read failed at row " + std::to_string(sourceFirstRow) +
                                       " of the mask of band " + std::to_string(bandNumber) +
                                       QuietGdalErrors::detail());
            }
        }
        for (int row = 0; row < rowsHere; ++row) {
            // Land cover comes in runs of one class: count a run at a time, not a pixel at a time.
            std::int32_t runValue = 0;
            std::int64_t runLength = 0;
            for (int column = 0; column < plan.columns; ++column) {
                const double value =
                    buffer[static_cast<std::size_t>(row) * static_cast<std::size_t>(plan.columns) +
                           static_cast<std::size_t>(column)];
                const std::size_t index = grid.index(column, firstRow + row);
                const std::size_t inChunk =
                    static_cast<std::size_t>(row) * static_cast<std::size_t>(plan.columns) +
                    static_cast<std::size_t>(column);
                const bool masked = mask != nullptr && maskBuffer[inChunk] == 0;
                if (masked || isNodata(value) || std::isnan(value)) {
                    if (!masked && !isNodata(value))
                        ++nanPixels;
                    grid.outside[index] = ClassGrid::outsideNodata;
                    ++outsidePixels;
                    continue;
                }
                const auto where = [&] {
                    return " at column " + std::to_string(column) + ", row " + std::to_string(firstRow + row);
                };
                if (floating && value != std::floor(value)) {
                    return Status::failure(path + ": band " + std::to_string(bandNumber) +
                                           " holds the fractional value " + formatQuantity(value, 10) +
                                           where() + "; a land-cover raster needs integer class values");
                }
                if (value < -2147483648.0 || value > 2147483647.0) {
                    return Status::failure(path + ": value " + formatQuantity(value, 12) + where() +
                                           " does not fit a 32-bit class value (is the nodata value set?)");
                }
                const auto classValue = static_cast<std::int32_t>(value);
                grid.values[index] = classValue;
                if (runLength > 0 && classValue != runValue) {
                    counts[runValue] += runLength;
                    runLength = 0;
                }
                runValue = classValue;
                ++runLength;
            }
            if (runLength > 0)
                counts[runValue] += runLength;
        }
    }
    if (outsidePixels == static_cast<std::int64_t>(cellCount)) {
        return Status::failure(path + ": every pixel of band " + std::to_string(bandNumber) +
                               " is nodata or masked; there is no area to plan");
    }
    if (outsidePixels == 0)
        grid.outside.clear();
    if (nanPixels > 0 && !raster.warpedFromGeographic) {
        raster.warnings.push_back(std::to_string(nanPixels) + " NaN pixels treated as outside the area");
    }
    raster.classPixelCounts = std::map<std::int32_t, std::int64_t>(counts.begin(), counts.end());
    return {};
}

void flipRows(ClassGrid& grid) {
    const auto width = static_cast<std::size_t>(grid.columns);
    for (int top = 0, bottom = grid.rows - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(grid.values.begin() + static_cast<std::ptrdiff_t>(grid.index(0, top)),
                         grid.values.begin() + static_cast<std::ptrdiff_t>(grid.index(0, top) + width),
                         grid.values.begin() + static_cast<std::ptrdiff_t>(grid.index(0, bottom)));
        if (!grid.outside.empty()) {
            std::swap_ranges(grid.outside.begin() + static_cast<std::ptrdiff_t>(grid.index(0, top)),
                             grid.outside.begin() + static_cast<std::ptrdiff_t>(grid.index(0, top) + width),
                             grid.outside.begin() + static_cast<std::ptrdiff_t>(grid.index(0, bottom)));
        }
    }
}

std::string formatMetres(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

} // namespace

std::vector<std::int32_t> presentClassValues(const LoadedRaster& raster) {
    std::vector<std::int32_t> present;
    for (const auto& [value, count] : raster.classPixelCounts)
        if (count > 0)
            present.push_back(value);
    return present;
}

Result<LoadedRaster> loadLandCoverRaster(const std::string& path, const RasterLoadOptions& options) {
    if (Status readable = checkFileReadable(path); !readable)
        return RasterResult::failure(readable.error());
    internal::ensureGdalRegistered();
    QuietGdalErrors quiet;

    DatasetPointer source(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!source)
        return RasterResult::failure(path + ": not a raster GDAL can read" + quiet.detail());
    const int bandCount = source->GetRasterCount();
    if (bandCount < 1)
        return RasterResult::failure(path + ": has no raster bands");
    if (options.band < 1 || options.band > bandCount) {
        return RasterResult::failure(path + ": band " + std::to_string(options.band) +
                                     " requested but the file has " + std::to_string(bandCount) +
                                     (bandCount == 1 ? " band" : " bands"));
    }
    GDALRasterBand* sourceBand = source->GetRasterBand(options.band);
    const GDALDataType type = sourceBand->GetRasterDataType();
    const std::string typeName = GDALGetDataTypeName(type);
    if (type == GDT_Byte && sourceBand->GetColorTable() == nullptr &&
        (isColourChannel(sourceBand->GetColorInterpretation()) || bandCount == 3 || bandCount == 4)) {
        return RasterResult::failure(
            path + ": looks like an RGB image (" + std::to_string(bandCount) +
            " Byte bands, no palette), not a land-cover class raster; classify it first");
    }
    if (isComplexType(type) || type == GDT_Unknown) {
        return RasterResult::failure(path + ": band " + std::to_string(options.band) + " is " + typeName +
                                     "; a land-cover raster needs one integer band");
    }

    LoadedRaster raster;
    raster.path = path;
    raster.band = options.band;
    raster.sourceColumns = source->GetRasterXSize();
    raster.sourceRows = source->GetRasterYSize();

    double transform[6] = {0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
    const bool georeferenced = source->GetGeoTransform(transform) == CE_None;
    if (!georeferenced) {
        // Pixel coordinates, row 0 at the top: y runs from rows down to 0.
        transform[0] = 0.0;
        transform[1] = 1.0;
        transform[3] = raster.sourceRows;
        transform[5] = -1.0;
        raster.warnings.push_back("no georeferencing: planned in pixel units taken as metres");
    }
    if (transform[2] != 0.0 || transform[4] != 0.0) {
        return RasterResult::failure(
            path + ": the geotransform is rotated or sheared; warp it to a north-up grid first");
    }
    if (!(transform[1] > 0.0) || transform[5] == 0.0 || !std::isfinite(transform[1]) ||
        !std::isfinite(transform[5])) {
        return RasterResult::failure(path + ": pixel size " + formatQuantity(transform[1]) + " x " +
                                     formatQuantity(transform[5]) + " is not usable (must run west to east)");
    }

    std::unique_ptr<OGRSpatialReference> planningCrs;
    if (const OGRSpatialReference* fileCrs = source->GetSpatialRef(); fileCrs != nullptr && georeferenced) {
        planningCrs.reset(fileCrs->Clone());
        planningCrs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        const char* crsName = planningCrs->GetName();
        raster.sourceCrsName = crsName == nullptr ? "unnamed CRS" : crsName;
    } else if (georeferenced) {
        raster.warnings.push_back(
            "no CRS: coordinates taken as metres; exports cannot be placed on the Earth");
    }

    GDALDataset* readDataset = source.get();
    int readBand = options.band;
    // Declared after `source` so they close first: the warped VRT reads from them.
    DatasetPointer selectedBand;
    DatasetPointer warped;
    double metresPerUnit = 1.0;
    if (planningCrs && planningCrs->IsGeographic()) {
        const double centreLongitude = transform[0] + transform[1] * raster.sourceColumns / 2.0;
        const double centreLatitude = transform[3] + transform[5] * raster.sourceRows / 2.0;
        auto utm = utmForCentre(*planningCrs, centreLongitude, centreLatitude);
        std::string error;
        warped = warpToUtm(*source, options.band, *utm, selectedBand, error);
        if (!warped)
            return RasterResult::failure(path + ": " + error);
        const ReadPlan coarse =
            planRead(warped->GetRasterXSize(), warped->GetRasterYSize(), options.pixelBudget);
        if (coarse.coarsened) {
            warped = warpToUtm(*source, options.band, *utm, selectedBand, error, coarse.columns, coarse.rows);
            if (!warped)
                return RasterResult::failure(path + ": " + error);
            raster.coarsened = true;
            raster.warnings.push_back(
                "raster warps to " + pixelsText(coarse.sourceColumns, coarse.sourceRows) + ", above " +
                budgetText(options.pixelBudget) + ": warped straight to " + std::to_string(coarse.columns) +
                " x " + std::to_string(coarse.rows) + " (mode resampling)");
        }
        raster.warpedFromGeographic = true;
        // News, not a warning: planning in metres is what a geographic raster needs.
        raster.notes.push_back(
            "geographic CRS " + raster.sourceCrsName + ": planned in " + utm->GetName() +
            (raster.coarsened ? " (warped by mode to the pixel budget)" : " (nearest-neighbour warp)"));
        planningCrs = std::move(utm);
        readDataset = warped.get();
        readBand = 1;
        if (readDataset->GetGeoTransform(transform) != CE_None) {
            return RasterResult::failure(path + ": the warped grid has no geotransform" + quiet.detail());
        }
    } else if (planningCrs && planningCrs->IsGeocentric()) {
        return RasterResult::failure(path + ": geocentric CRS " + raster.sourceCrsName +
                                     " cannot be planned on");
    } else if (planningCrs) {
        metresPerUnit = planningCrs->GetLinearUnits(nullptr);
        if (!std::isfinite(metresPerUnit) || metresPerUnit <= 0.0)
            metresPerUnit = 1.0;
        if (metresPerUnit != 1.0) {
            const char* unitName = nullptr;
            planningCrs->GetLinearUnits(&unitName);
            raster.warnings.push_back(std::string("CRS units are ") + (unitName ? unitName : "not metres") +
                                      ": converted to metres (x " + formatMetres(metresPerUnit) + ")");
        }
    }

    GDALRasterBand* band = readDataset->GetRasterBand(readBand);
    const ReadPlan plan =
        planRead(readDataset->GetRasterXSize(), readDataset->GetRasterYSize(), options.pixelBudget);
    if (Status read = readClasses(*band, plan, path, options.band, raster); !read)
        return RasterResult::failure(read.error());

    const double columnScale = static_cast<double>(plan.sourceColumns) / plan.columns;
    const double rowScale = static_cast<double>(plan.sourceRows) / plan.rows;
    ClassGrid& grid = raster.grid;
    grid.pixelWidth = transform[1] * columnScale * metresPerUnit;
    grid.pixelHeight = std::abs(transform[5]) * rowScale * metresPerUnit;
    grid.originX = transform[0] * metresPerUnit;
    if (transform[5] > 0.0) {
        // South-up file: row 0 is the southern edge; flip so row 0 is north as ClassGrid expects.
        grid.originY = (transform[3] + transform[5] * plan.sourceRows) * metresPerUnit;
        flipRows(grid);
    } else {
        grid.originY = transform[3] * metresPerUnit;
    }
    raster.coarsened = raster.coarsened || plan.coarsened;
    raster.effectiveResolutionMetres = std::max(grid.pixelWidth, grid.pixelHeight);
    if (plan.coarsened) {
        raster.warnings.push_back("raster has " + pixelsText(plan.sourceColumns, plan.sourceRows) +
                                  ", above " + budgetText(options.pixelBudget) + ": read at " +
                                  formatMetres(raster.effectiveResolutionMetres) +
                                  " m resolution (mode resampling)");
    }

    if (planningCrs) {
        auto reference = GeoReference::fromDefinition(internal::wktOf(*planningCrs));
        if (reference) {
            raster.georeference = std::move(reference.value());
            grid.trueNorthRadians = trueNorthRadians(raster.georeference, grid);
        } else {
            raster.warnings.push_back("CRS " + raster.sourceCrsName +
                                      " could not be used: " + reference.error());
        }
    }
    internal::readRasterLegend(*sourceBand, path, raster);
    return raster;
}

} // namespace mcpp::io
