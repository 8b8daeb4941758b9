#pragma once

// Private to mcpp_io.

#include "io/AtomicFile.hpp"
#include "io/GeoReference.hpp"
#include "io/Result.hpp"
#include "io/internal/GdalSupport.hpp"

#include <string>

namespace mcpp::io::internal {

// A file written by a GDAL driver into memory and written out whole by commit() (io::writeFileAtomically),
// so a failed, cancelled or disk-full export never leaves half a file under the real name or replaces the
// previous one.
class DatasetFile {
  public:
    explicit DatasetFile(std::string path);
    ~DatasetFile(); // frees the in-memory file
    DatasetFile(const DatasetFile&) = delete;
    DatasetFile& operator=(const DatasetFile&) = delete;

    // Vector drivers take no size: columns = rows = bands = 0, GDT_Unknown.
    [[nodiscard]] Status create(const char* driverName, int columns, int rows, int bands, GDALDataType type,
                                const char* const* options = nullptr);
    [[nodiscard]] GDALDataset& dataset() { return *dataset_; }
    [[nodiscard]] const std::string& path() const { return path_; }
    // Places a raster of square pixels of `pixelSize` planning metres, its north-west corner at
    // (originX, originY), in the map's CRS (its own units); the CRS is written when the map has one.
    [[nodiscard]] Status placeOnMap(const GeoReference& georeference, double originX, double originY,
                                    double pixelSize);
    // Closes the dataset (flushing it) and writes the file into place: exports left to the system to flush,
    // files the user drew synced to the disk (io::Sync).
    [[nodiscard]] Status commit(Sync sync);

  private:
    std::string path_;
    std::string memoryFolder_;
    std::string temporary_; // in memoryFolder_
    DatasetPointer dataset_;
};

} // namespace mcpp::io::internal
