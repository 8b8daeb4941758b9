#include "io/internal/DatasetFile.hpp"

#include <filesystem>
#include <unistd.h>

namespace mcpp::io::internal {

namespace fs = std::filesystem;

DatasetFile::DatasetFile(std::string path) : path_(std::move(path)) {
    const fs::path target(path_);
    temporary_ = (target.parent_path() / ("." + target.stem().string() + ".partial-" +
                                          std::to_string(getpid()) + target.extension().string()))
                     .string();
}

DatasetFile::~DatasetFile() {
    dataset_.reset();
    std::error_code ignored;
    if (!committed_)
        fs::remove(temporary_, ignored);
}

Status DatasetFile::create(const char* driverName, int columns, int rows, int bands, GDALDataType type,
                           const char* const* options) {
    ensureGdalRegistered();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driverName);
    if (driver == nullptr)
        return Status::failure(path_ + ": GDAL has no " + driverName + " driver");
    std::error_code ignored;
    fs::remove(temporary_, ignored);
    dataset_.reset(
        driver->Create(temporary_.c_str(), columns, rows, bands, type, const_cast<char**>(options)));
    if (!dataset_)
        return Status::failure(path_ + ": cannot create" + QuietGdalErrors::detail());
    return {};
}

Status DatasetFile::commit() {
    CPLErrorReset();
    dataset_.reset(); // flushes and closes
    if (CPLGetLastErrorType() == CE_Failure)
        return Status::failure(path_ + ": write failed" + QuietGdalErrors::detail());
    std::error_code error;
    fs::rename(temporary_, path_, error);
    if (error)
        return Status::failure(path_ + ": cannot move the finished file into place: " + error.message());
    committed_ = true;
    return {};
}

} // namespace mcpp::io::internal
