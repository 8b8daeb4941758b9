#include "io/PointsInDegrees.hpp"

#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <regex>

namespace mcpp::io {

namespace {

// Whether a point lies on the grid or within the grid's larger side of it.
bool nearTheMap(const ClassGrid& grid, MapPoint point) {
    const double margin = std::max(grid.width(), grid.height());
    return point.x >= grid.originX - margin && point.x <= grid.originX + grid.width() + margin &&
           point.y >= grid.minY() - margin && point.y <= grid.originY + margin;
}

// Seven decimals, about a centimetre, whatever the size of the degrees; trailing zeros dropped.
std::string sevenDecimals(double degrees) {
    std::string text;
    internal::appendRounded(text, degrees, 7);
    return text;
}

} // namespace

std::string degreesText(LonLat lonLat) {
    return "longitude " + sevenDecimals(lonLat.longitude) + ", latitude " + sevenDecimals(lonLat.latitude);
}

std::string withPointsInDegrees(const std::string& message, const GeoReference& georeference,
                                const ClassGrid& grid) {
    if (!georeference.hasCrs() || message.find('(') == std::string::npos)
        return message;
    static const std::regex point(R"(\((-?[0-9]+(?:\.[0-9]+)?), (-?[0-9]+(?:\.[0-9]+)?)\))");
    std::string result;
    std::size_t copied = 0;
    for (auto match = std::sregex_iterator(message.begin(), message.end(), point);
         match != std::sregex_iterator(); ++match) {
        const MapPoint mapPoint{std::stod((*match)[1].str()), std::stod((*match)[2].str())};
        if (!nearTheMap(grid, mapPoint))
            continue;
        const auto degrees = georeference.toWgs84(mapPoint);
        if (!degrees)
            continue;
        const auto closing = static_cast<std::size_t>(match->position(0) + match->length(0) - 1);
        result += message.substr(copied, closing - copied) + "; " + degreesText(degrees.value());
        copied = closing;
    }
    return result + message.substr(copied);
}

} // namespace mcpp::io
