#pragma once

#include "io/GeoReference.hpp"

#include <memory>

class OGRCoordinateTransformation;

namespace mcpp::io::internal {

// A transformation from a reference's CRS to WGS84, lent to one thread while this lives and then given back
// for the next writer. One transformation must not be used by two threads at once, and each one made costs
// CRS-database lookups, so writers borrow the reference's instead of making their own.
class TransformationLoan {
  public:
    explicit TransformationLoan(const GeoReference& reference); // the reference must have a CRS
    ~TransformationLoan();
    TransformationLoan(const TransformationLoan&) = delete;
    TransformationLoan& operator=(const TransformationLoan&) = delete;

    // Null when none can be made; GDAL's last error says why.
    [[nodiscard]] OGRCoordinateTransformation* get() const { return transformation_.get(); }

  private:
    std::shared_ptr<const GeoReference::State> state_;
    std::unique_ptr<OGRCoordinateTransformation> transformation_;
};

} // namespace mcpp::io::internal
