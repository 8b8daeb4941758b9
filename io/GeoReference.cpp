#include "io/GeoReference.hpp"

#include "core/model/HumanUnits.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/GeoReferenceState.hpp"
#include "io/internal/TransformationLoan.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

namespace mcpp::io {

using internal::QuietGdalErrors;

namespace {

bool transformPoint(OGRCoordinateTransformation& transformation, double& x, double& y) {
    int success = 0;
    return transformation.Transform(1, &x, &y, nullptr, nullptr, &success) && success != 0 &&
           std::isfinite(x) && std::isfinite(y);
}

std::string notUnderstood(const std::string& definition, const std::string& detail) {
    const std::string hint = epsgSpellingHint(definition);
    return "CRS \"" + definition + "\" is not understood" + (hint.empty() ? detail : hint);
}

} // namespace

std::string epsgSpellingHint(const std::string& definition) {
    const bool digitsOnly = !definition.empty() && std::all_of(definition.begin(), definition.end(),
                                                               [](char c) { return c >= '0' && c <= '9'; });
    return digitsOnly ? " (an EPSG code is written EPSG:" + definition + ")" : std::string();
}

GeoReference::GeoReference() = default;

Result<GeoReference> GeoReference::fromDefinition(const std::string& definition) {
    internal::ensureGdalRegistered();
    QuietGdalErrors quiet;
    auto crs = internal::spatialReferenceFromDefinition(definition);
    if (!crs)
        return Result<GeoReference>::failure(notUnderstood(definition, quiet.detail()));
    if (crs->IsGeographic() || crs->IsGeocentric()) {
        return Result<GeoReference>::failure(
            "CRS \"" + definition + "\" is not projected (degrees); a planning frame needs metres or feet");
    }
    auto state = std::make_shared<State>();
    const double factor = crs->GetLinearUnits(nullptr);
    state->metresPerUnit = (std::isfinite(factor) && factor > 0.0) ? factor : 1.0;
    state->wkt = internal::wktOf(*crs);
    if (const char* crsName = crs->GetName(); crsName != nullptr)
        state->name = crsName;
    const char* authority = crs->GetAuthorityName(nullptr);
    const char* code = crs->GetAuthorityCode(nullptr);
    if (authority != nullptr && code != nullptr)
        state->authorityCode = std::string(authority) + ":" + code;
    state->crs = std::move(crs);
    GeoReference reference;
    reference.state_ = std::move(state);
    return reference;
}

bool GeoReference::hasCrs() const {
    return state_ && state_->crs;
}

std::string GeoReference::wkt() const {
    return hasCrs() ? state_->wkt : std::string();
}

std::string GeoReference::name() const {
    return hasCrs() ? state_->name : std::string();
}

std::string GeoReference::authorityCode() const {
    return hasCrs() ? state_->authorityCode : std::string();
}

double GeoReference::metresPerUnit() const {
    return state_ ? state_->metresPerUnit : 1.0;
}

MapPoint GeoReference::toCrsUnits(MapPoint planningPoint) const {
    const double factor = metresPerUnit();
    return {planningPoint.x / factor, planningPoint.y / factor};
}

MapPoint GeoReference::fromCrsUnits(MapPoint crsPoint) const {
    const double factor = metresPerUnit();
    return {crsPoint.x * factor, crsPoint.y * factor};
}

Result<LonLat> GeoReference::toWgs84(MapPoint point) const {
    auto lonLats = toWgs84(std::vector<MapPoint>{point});
    if (!lonLats)
        return Result<LonLat>::failure(lonLats.error());
    return lonLats.value().front();
}

Result<std::vector<LonLat>> GeoReference::toWgs84(const std::vector<MapPoint>& points) const {
    using LonLats = std::vector<LonLat>;
    if (!hasCrs())
        return Result<LonLats>::failure("the map has no CRS, so its points have no longitude and latitude");
    QuietGdalErrors quiet;
    std::vector<double> x(points.size()), y(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const MapPoint crsPoint = toCrsUnits(points[i]);
        x[i] = crsPoint.x;
        y[i] = crsPoint.y;
    }
    std::vector<int> success(points.size(), 0);
    {
        const internal::TransformationLoan transformation(*this);
        if (transformation.get() == nullptr)
            return Result<LonLats>::failure("no transformation from " + name() + " to WGS84" +
                                            quiet.detail());
        if (!points.empty())
            transformation.get()->Transform(points.size(), x.data(), y.data(), nullptr, nullptr,
                                            success.data());
    }
    LonLats lonLats(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (success[i] == 0 || !std::isfinite(x[i]) || !std::isfinite(y[i])) {
            return Result<LonLats>::failure("point (" + formatQuantity(points[i].x, 12) + ", " +
                                            formatQuantity(points[i].y, 12) +
                                            ") cannot be transformed to WGS84" + quiet.detail());
        }
        lonLats[i] = {x[i], y[i]};
    }
    return lonLats;
}

void GeoReference::prepareTransformationsToWgs84(int count) const {
    if (!hasCrs())
        return;
    QuietGdalErrors quiet;
    const auto wgs84 = internal::wgs84SpatialReference();
    for (;;) {
        // Under the lock, as every use of the CRS object here (its const methods may touch caches); taken
        // anew for each, so that a writer that comes early waits for one transformation at most.
        const std::lock_guard lock(state_->mutex);
        if (static_cast<int>(state_->idleToWgs84.size()) >= count)
            return;
        auto made = internal::transformationBetween(*state_->crs, *wgs84);
        if (!made)
            return; // the writers will say why
        state_->idleToWgs84.push_back(std::move(made));
    }
}

Result<MapPoint> GeoReference::fromWgs84(LonLat lonLat) const {
    if (!hasCrs())
        return Result<MapPoint>::failure(
            "the map has no CRS, so longitude and latitude cannot be placed on it");
    QuietGdalErrors quiet;
    std::lock_guard lock(state_->mutex);
    if (!state_->fromWgs84) {
        const auto wgs84 = internal::wgs84SpatialReference();
        state_->fromWgs84 = internal::transformationBetween(*wgs84, *state_->crs);
        if (!state_->fromWgs84) {
            return Result<MapPoint>::failure("no transformation from WGS84 to " + name() + quiet.detail());
        }
    }
    double x = lonLat.longitude;
    double y = lonLat.latitude;
    if (!transformPoint(*state_->fromWgs84, x, y)) {
        return Result<MapPoint>::failure("longitude " + formatQuantity(lonLat.longitude, 10) + ", latitude " +
                                         formatQuantity(lonLat.latitude, 10) + " cannot be transformed to " +
                                         name() + quiet.detail());
    }
    return fromCrsUnits({x, y});
}

Result<MapPoint> GeoReference::fromCrs(const std::string& definition, MapPoint point) const {
    if (definition.empty())
        return point;
    QuietGdalErrors quiet;
    const auto source = internal::spatialReferenceFromDefinition(definition);
    if (!source)
        return Result<MapPoint>::failure(notUnderstood(definition, quiet.detail()));
    if (!hasCrs())
        return Result<MapPoint>::failure("the map has no CRS, so a point in " + definition +
                                         " cannot be placed on it");
    std::unique_lock lock(state_->mutex);
    const auto transformation = internal::transformationBetween(*source, *state_->crs);
    lock.unlock();
    double x = point.x;
    double y = point.y;
    if (!transformation || !transformPoint(*transformation, x, y)) {
        return Result<MapPoint>::failure("point (" + formatQuantity(point.x, 12) + ", " +
                                         formatQuantity(point.y, 12) + ") in " + definition +
                                         " cannot be transformed to " + name() + quiet.detail());
    }
    return fromCrsUnits({x, y});
}

Result<MapPoint> GeoReference::toCrs(const std::string& definition, MapPoint point) const {
    if (definition.empty())
        return point;
    QuietGdalErrors quiet;
    const auto target = internal::spatialReferenceFromDefinition(definition);
    if (!target)
        return Result<MapPoint>::failure(notUnderstood(definition, quiet.detail()));
    if (!hasCrs())
        return Result<MapPoint>::failure("the map has no CRS, so its points cannot go to " + definition);
    std::unique_lock lock(state_->mutex);
    const auto transformation = internal::transformationBetween(*state_->crs, *target);
    lock.unlock();
    const MapPoint crsPoint = toCrsUnits(point);
    double x = crsPoint.x;
    double y = crsPoint.y;
    if (!transformation || !transformPoint(*transformation, x, y)) {
        return Result<MapPoint>::failure("point (" + formatQuantity(point.x, 12) + ", " +
                                         formatQuantity(point.y, 12) + ") cannot be transformed to " +
                                         definition + quiet.detail());
    }
    return MapPoint{x, y};
}

} // namespace mcpp::io
