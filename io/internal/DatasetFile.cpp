#include "io/internal/DatasetFile.hpp"

#include "io/AtomicFile.hpp"

#include <atomic>
#include <cpl_vsi.h>
#include <filesystem>
#include <unistd.h>

namespace mcpp::io::internal {

namespace fs = std::filesystem;

namespace {

// The dataset is built in GDAL's in-memory file system: drivers do not all check their writes, so the
// real file is written once, by writeFileAtomically, which does.
std::string memoryFolder() {
    static std::atomic<unsigned> counter{0};
    return "/vsimem/mcpp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
}

// ".kml" for LIBKML, ".tif" for GTiff: the first extension the driver lists, else the target's own.
std::string driverExtension(GDALDriver& driver, const std::string& target) {
    for (const char* item : {GDAL_DMD_EXTENSION, GDAL_DMD_EXTENSIONS}) {
        const char* listed = driver.GetMetadataItem(item);
        if (listed != nullptr && *listed != '\0') {
            const std::string extensions(listed);
            return "." + extensions.substr(0, extensions.find(' '));
        }
    }
    return fs::path(target).extension().string();
}

} // namespace

DatasetFile::DatasetFile(std::string path) : path_(std::move(path)), memoryFolder_(memoryFolder()) {}

DatasetFile::~DatasetFile() {
    dataset_.reset();
    VSIRmdirRecursive(memoryFolder_.c_str()); // the file and any journal a driver left beside it
}

Status DatasetFile::placeOnMap(const GeoReference& georeference, double originX, double originY,
                               double pixelSize) {
    const double metresPerUnit = georeference.metresPerUnit();
    double transform[6] = {
        originX / metresPerUnit,   pixelSize / metresPerUnit, 0.0, originY / metresPerUnit, 0.0,
        -pixelSize / metresPerUnit};
    if (dataset_->SetGeoTransform(transform) != CE_None)
        return Status::failure(path_ + ": cannot set the grid's position" + QuietGdalErrors::detail());
    if (georeference.hasCrs() && dataset_->SetProjection(georeference.wkt().c_str()) != CE_None)
        return Status::failure(path_ + ": cannot set the CRS" + QuietGdalErrors::detail());
    return {};
}

Status DatasetFile::create(const char* driverName, int columns, int rows, int bands, GDALDataType type,
                           const char* const* options) {
    ensureGdalRegistered();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driverName);
    if (driver == nullptr)
        return Status::failure(path_ + ": GDAL has no " + driverName + " driver");
    VSIMkdir(memoryFolder_.c_str(), 0755);
    // The driver's own extension: some (KML) write a folder instead when the name lacks it.
    temporary_ = memoryFolder_ + "/output" + driverExtension(*driver, path_);
    dataset_.reset(
        driver->Create(temporary_.c_str(), columns, rows, bands, type, const_cast<char**>(options)));
    if (!dataset_)
        return Status::failure(path_ + ": cannot create" + QuietGdalErrors::detail());
    return {};
}

Status DatasetFile::commit(Sync sync) {
    CPLErrorReset();
    dataset_.reset(); // flushes and closes
    if (CPLGetLastErrorType() == CE_Failure)
        return Status::failure(path_ + ": write failed" + QuietGdalErrors::detail());
    vsi_l_offset size = 0;
    GByte* bytes = VSIGetMemFileBuffer(temporary_.c_str(), &size, FALSE);
    if (bytes == nullptr)
        return Status::failure(path_ + ": the driver wrote no file" + QuietGdalErrors::detail());
    return writeFileAtomically(
        path_, std::string_view(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size)), sync);
}

} // namespace mcpp::io::internal
