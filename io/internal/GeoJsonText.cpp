#include "io/internal/GeoJsonText.hpp"

#include "io/internal/JsonValue.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string_view>

namespace mcpp::io::internal {

namespace {

constexpr int kCoordinateDecimals = 9; // well within 1e-7 degrees, about a centimetre

// A longitude or latitude with 9 decimals, trailing zeros dropped ("14.07", "7.0").
void appendCoordinate(std::string& out, double value) {
    std::array<char, 48> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                      std::chars_format::fixed, kCoordinateDecimals);
    std::string_view text(buffer.data(), static_cast<std::size_t>(result.ptr - buffer.data()));
    while (text.size() > 2 && text.back() == '0' && text[text.size() - 2] != '.')
        text.remove_suffix(1);
    out.append(text);
}

// A real field keeps a decimal point, so that readers guessing types from the text keep it real.
void appendReal(std::string& out, double value) {
    const std::size_t start = out.size();
    appendJsonNumber(out, value);
    if (out.find_first_of(".en", start) == std::string::npos)
        out += ".0";
}

void appendPoint(std::string& out, double x, double y) {
    out += '[';
    appendCoordinate(out, x);
    out += ',';
    appendCoordinate(out, y);
    out += ']';
}

// Twice the signed area in degrees: positive when the ring runs counter-clockwise.
double signedArea(const OGRSimpleCurve& ring) {
    double sum = 0.0;
    const int points = ring.getNumPoints();
    for (int i = 0; i + 1 < points; ++i)
        sum += ring.getX(i) * ring.getY(i + 1) - ring.getX(i + 1) * ring.getY(i);
    return sum;
}

void appendCurve(std::string& out, const OGRSimpleCurve& curve, bool reversed) {
    out += '[';
    const int points = curve.getNumPoints();
    for (int k = 0; k < points; ++k) {
        const int i = reversed ? points - 1 - k : k;
        if (k > 0)
            out += ',';
        appendPoint(out, curve.getX(i), curve.getY(i));
    }
    out += ']';
}

// RFC 7946 ring order: the exterior counter-clockwise, holes clockwise.
void appendPolygonRings(std::string& out, const OGRPolygon& polygon) {
    out += '[';
    bool exterior = true;
    for (const OGRLinearRing* ring : polygon) {
        if (!exterior)
            out += ',';
        appendCurve(out, *ring, (signedArea(*ring) > 0.0) != exterior);
        exterior = false;
    }
    out += ']';
}

void appendGeometry(std::string& out, const OGRGeometry* geometry);

// "[a,b,...]": each part of a collection as appendPart writes it.
template <typename Collection, typename AppendPart>
void appendParts(std::string& out, const Collection& parts, AppendPart appendPart) {
    out += '[';
    for (int i = 0; i < parts.getNumGeometries(); ++i) {
        if (i > 0)
            out += ',';
        appendPart(*parts.getGeometryRef(i));
    }
    out += ']';
}

// The geometry object's body after its opening brace: its type and coordinates (or member geometries).
void appendTypeAndCoordinates(std::string& out, const OGRGeometry& geometry) {
    const auto typed = [&out](const char* type, const char* member) {
        out += "\"type\":\"";
        out += type;
        out += "\",\"";
        out += member;
        out += "\":";
    };
    switch (wkbFlatten(geometry.getGeometryType())) {
    case wkbPoint:
        typed("Point", "coordinates");
        appendPoint(out, geometry.toPoint()->getX(), geometry.toPoint()->getY());
        return;
    case wkbLineString:
        typed("LineString", "coordinates");
        appendCurve(out, *geometry.toLineString(), false);
        return;
    case wkbPolygon:
        typed("Polygon", "coordinates");
        appendPolygonRings(out, *geometry.toPolygon());
        return;
    case wkbMultiLineString:
        typed("MultiLineString", "coordinates");
        appendParts(out, *geometry.toMultiLineString(),
                    [&out](const OGRLineString& line) { appendCurve(out, line, false); });
        return;
    case wkbMultiPolygon:
        typed("MultiPolygon", "coordinates");
        appendParts(out, *geometry.toMultiPolygon(),
                    [&out](const OGRPolygon& polygon) { appendPolygonRings(out, polygon); });
        return;
    case wkbGeometryCollection: // as cutting at the antimeridian may leave
        typed("GeometryCollection", "geometries");
        appendParts(out, *geometry.toGeometryCollection(),
                    [&out](const OGRGeometry& part) { appendGeometry(out, &part); });
        return;
    default: // no other kind comes from a plan
        typed("GeometryCollection", "geometries");
        out += "[]";
        return;
    }
}

void appendGeometry(std::string& out, const OGRGeometry* geometry) {
    if (geometry == nullptr || geometry->IsEmpty()) {
        out += "null";
        return;
    }
    // A multipolygon of one part is written as a Polygon, as OGR writes it.
    if (wkbFlatten(geometry->getGeometryType()) == wkbMultiPolygon &&
        geometry->toMultiPolygon()->getNumGeometries() == 1)
        geometry = geometry->toMultiPolygon()->getGeometryRef(0);
    out += '{';
    appendTypeAndCoordinates(out, *geometry);
    out += '}';
}

// Builds one feature line: {"type":"Feature","properties":{...},"geometry":...}
class FeatureLine {
  public:
    FeatureLine(std::string& out, const char* kind) : out_(out) {
        out_ += "{\"type\":\"Feature\",\"properties\":{\"kind\":";
        appendJsonString(out_, kind);
    }
    FeatureLine& robot(const ExportContext& context, int robot) {
        integer("robot", robotNumber(robot));
        out_ += ",\"robot_name\":";
        appendJsonString(out_, context.robotName(robot));
        return *this;
    }
    FeatureLine& integer(const char* key, long long value) {
        name(key);
        std::array<char, 24> buffer{};
        const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
        out_.append(buffer.data(), result.ptr);
        return *this;
    }
    FeatureLine& real(const char* key, double value) {
        name(key);
        appendReal(out_, value);
        return *this;
    }
    void geometry(const OGRGeometry* geometry, bool last) {
        out_ += "},\"geometry\":";
        appendGeometry(out_, geometry);
        out_ += last ? "}\n" : "},\n";
    }

  private:
    void name(const char* key) {
        out_ += ",\"";
        out_ += key;
        out_ += "\":";
    }
    std::string& out_;
};

// Part `part` of a path written in parts: its segments from part x mostSegmentsInAGeoJsonPath on, so that
// each part begins at the point where the one before it ended.
OGRLineString pathPart(const OGRLineString& line, int part) {
    const int first = part * mostSegmentsInAGeoJsonPath;
    const int last = std::min(first + mostSegmentsInAGeoJsonPath, line.getNumPoints() - 1);
    OGRLineString piece;
    piece.setNumPoints(last - first + 1, FALSE);
    for (int i = first; i <= last; ++i)
        piece.setPoint(i - first, line.getX(i), line.getY(i));
    return piece;
}

} // namespace

int geoJsonPathParts(const OGRGeometry& path) {
    if (wkbFlatten(path.getGeometryType()) != wkbLineString)
        return 1; // cut at the antimeridian: lines far shorter than a map of millions of cells
    const int segments = std::max(path.toLineString()->getNumPoints() - 1, 1);
    return (segments + mostSegmentsInAGeoJsonPath - 1) / mostSegmentsInAGeoJsonPath;
}

std::optional<std::string> planGeoJsonText(const ExportContext& context, const PlanFeatures& features) {
    std::size_t pathFeatures = 0;
    for (const auto& line : features.paths)
        pathFeatures += static_cast<std::size_t>(geoJsonPathParts(*line.geometry));
    const std::size_t count = features.regions.size() + pathFeatures + features.starts.size() +
                              features.chargers.size() + features.unreachable.size() +
                              features.takenOver.size() + features.area.size();
    std::size_t written = 0;
    std::string out = "{\n\"type\": \"FeatureCollection\",\n\"features\": [\n";
    for (const auto& region : features.regions) {
        if (context.cancelled())
            return std::nullopt;
        FeatureLine(out, "region")
            .robot(context, region.robot)
            .real("time_s", region.timeSeconds)
            .real("cost_s", region.costSeconds)
            .real("area_m2", region.areaSquareMetres)
            .integer("cells", region.cells)
            .geometry(region.geometry.get(), ++written == count);
    }
    for (const auto& line : features.paths) {
        if (context.cancelled())
            return std::nullopt;
        const int parts = geoJsonPathParts(*line.geometry);
        for (int part = 0; part < parts; ++part) {
            FeatureLine feature(out, "path");
            feature.robot(context, line.robot)
                .real("length_m", line.lengthMetres)
                .real("time_s", line.timeSeconds)
                .integer("turns", line.turns);
            if (parts == 1) {
                feature.geometry(line.geometry.get(), ++written == count);
                continue;
            }
            const OGRLineString piece = pathPart(*line.geometry->toLineString(), part);
            feature.integer("part", part + 1).integer("parts", parts).geometry(&piece, ++written == count);
        }
    }
    for (const auto& start : features.starts)
        FeatureLine(out, "start")
            .robot(context, start.robot)
            .geometry(start.geometry.get(), ++written == count);
    for (const auto& charger : features.chargers)
        FeatureLine(out, "charger")
            .robot(context, charger.robot)
            .geometry(charger.geometry.get(), ++written == count);
    for (const auto& part : features.unreachable) {
        FeatureLine(out, "unreachable")
            .real("area_m2", part.areaSquareMetres)
            .geometry(part.geometry.get(), ++written == count);
    }
    for (const auto& part : features.takenOver) {
        FeatureLine(out, "taken_over")
            .robot(context, part.robot)
            .real("area_m2", part.areaSquareMetres)
            .integer("cells", part.cells)
            .geometry(part.geometry.get(), ++written == count);
    }
    for (const auto& polygon : features.area) {
        FeatureLine(out, polygon.noGoZone ? "no_go_zone" : "area_of_interest")
            .real("area_m2", polygon.areaSquareMetres)
            .geometry(polygon.geometry.get(), ++written == count);
    }
    out += "]\n}\n";
    return out;
}

} // namespace mcpp::io::internal
