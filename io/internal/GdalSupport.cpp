#include "io/internal/GdalSupport.hpp"

#include <mutex>

namespace mcpp::io::internal {

void ensureGdalRegistered() {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
}

QuietGdalErrors::QuietGdalErrors() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
}

QuietGdalErrors::~QuietGdalErrors() {
    CPLPopErrorHandler();
}

std::string QuietGdalErrors::lastMessage() {
    const char* message = CPLGetLastErrorMsg();
    std::string text = message == nullptr ? std::string() : std::string(message);
    // One line: GDAL messages sometimes end with or contain line breaks.
    for (char& character : text) {
        if (character == '\n' || character == '\r')
            character = ' ';
    }
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

std::string QuietGdalErrors::detail() {
    const std::string message = lastMessage();
    return message.empty() ? std::string() : ": " + message;
}

void DatasetCloser::operator()(GDALDataset* dataset) const {
    if (dataset != nullptr)
        GDALClose(GDALDataset::ToHandle(dataset));
}

std::unique_ptr<OGRSpatialReference> makeSpatialReference() {
    auto reference = std::make_unique<OGRSpatialReference>();
    reference->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    return reference;
}

std::unique_ptr<OGRSpatialReference> spatialReferenceFromDefinition(const std::string& definition) {
    if (definition.empty())
        return nullptr;
    ensureGdalRegistered();
    auto reference = makeSpatialReference();
    if (reference->SetFromUserInput(
            definition.c_str(), OGRSpatialReference::SET_FROM_USER_INPUT_LIMITATIONS_get()) != OGRERR_NONE) {
        return nullptr;
    }
    reference->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    return reference;
}

std::unique_ptr<OGRSpatialReference> wgs84SpatialReference() {
    auto reference = makeSpatialReference();
    reference->SetWellKnownGeogCS("WGS84");
    return reference;
}

std::unique_ptr<OGRCoordinateTransformation> transformationBetween(const OGRSpatialReference& from,
                                                                   const OGRSpatialReference& to) {
    return std::unique_ptr<OGRCoordinateTransformation>(OGRCreateCoordinateTransformation(&from, &to));
}

std::string wktOf(const OGRSpatialReference& reference) {
    char* text = nullptr;
    const char* const options[] = {"FORMAT=WKT2_2019", "MULTILINE=NO", nullptr};
    std::string result;
    if (reference.exportToWkt(&text, options) == OGRERR_NONE && text != nullptr)
        result = text;
    CPLFree(text);
    return result;
}

std::unique_ptr<OGRLinearRing> crsRing(const std::vector<MapPoint>& corners, double metresPerUnit) {
    auto ring = std::make_unique<OGRLinearRing>();
    ring->setNumPoints(static_cast<int>(corners.size()));
    for (std::size_t i = 0; i < corners.size(); ++i)
        ring->setPoint(static_cast<int>(i), corners[i].x / metresPerUnit, corners[i].y / metresPerUnit);
    ring->closeRings();
    return ring;
}

} // namespace mcpp::io::internal
