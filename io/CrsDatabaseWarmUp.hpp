#pragma once

#include <thread>

namespace mcpp::io {

// Opens the CRS database (PROJ's proj.db) on a background thread. Its first use in a process costs 30-40 ms,
// which a batch run otherwise pays when it reads the raster's CRS; started first, it overlaps with the
// mission, the Qt and the GDAL set-up. The destructor waits for it.
class CrsDatabaseWarmUp {
  public:
    CrsDatabaseWarmUp();
    ~CrsDatabaseWarmUp();
    CrsDatabaseWarmUp(const CrsDatabaseWarmUp&) = delete;
    CrsDatabaseWarmUp& operator=(const CrsDatabaseWarmUp&) = delete;

  private:
    std::thread thread_;
};

} // namespace mcpp::io
