#pragma once

// Private to mcpp_io.

#include "io/Result.hpp"
#include "io/internal/GdalSupport.hpp"

#include <string>

namespace mcpp::io::internal {

// A file written by a GDAL driver under a temporary name beside its target and renamed into place by
// commit(), so a failed or cancelled export never leaves half a file under the real name.
class DatasetFile {
  public:
    explicit DatasetFile(std::string path);
    ~DatasetFile(); // removes the temporary file unless committed
    DatasetFile(const DatasetFile&) = delete;
    DatasetFile& operator=(const DatasetFile&) = delete;

    // Vector drivers take no size: columns = rows = bands = 0, GDT_Unknown.
    [[nodiscard]] Status create(const char* driverName, int columns, int rows, int bands, GDALDataType type,
                                const char* const* options = nullptr);
    [[nodiscard]] GDALDataset& dataset() { return *dataset_; }
    [[nodiscard]] const std::string& path() const { return path_; }
    // Closes the dataset (flushing it) and moves the file into place.
    [[nodiscard]] Status commit();

  private:
    std::string path_;
    std::string temporary_;
    DatasetPointer dataset_;
    bool committed_ = false;
};

} // namespace mcpp::io::internal
