#include "io/internal/TransformationLoan.hpp"

#include "io/internal/GdalSupport.hpp"
#include "io/internal/GeoReferenceState.hpp"

namespace mcpp::io::internal {

TransformationLoan::TransformationLoan(const GeoReference& reference) : state_(reference.state_) {
    const std::lock_guard lock(state_->mutex);
    if (state_->idleToWgs84.empty()) {
        transformation_ = transformationBetween(*state_->crs, *wgs84SpatialReference());
        return;
    }
    transformation_ = std::move(state_->idleToWgs84.back());
    state_->idleToWgs84.pop_back();
}

TransformationLoan::~TransformationLoan() {
    if (!transformation_)
        return;
    const std::lock_guard lock(state_->mutex);
    state_->idleToWgs84.push_back(std::move(transformation_));
}

} // namespace mcpp::io::internal
