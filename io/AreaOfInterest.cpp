#include "io/AreaOfInterest.hpp"

#include "core/model/HumanUnits.hpp"
#include "io/internal/DatasetFile.hpp"
#include "io/internal/GdalSupport.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gdal_alg.h>
#include <ogrsf_frmts.h>
#include <optional>
#include <vector>

namespace mcpp::io {

namespace {

using internal::QuietGdalErrors;

struct OwnedGeometries {
    std::vector<OGRGeometry*> geometries;
    OwnedGeometries() = default;
    OwnedGeometries(const OwnedGeometries&) = delete;
    OwnedGeometries& operator=(const OwnedGeometries&) = delete;
    ~OwnedGeometries() {
        for (OGRGeometry* geometry : geometries)
            OGRGeometryFactory::destroyGeometry(geometry);
    }
};

// Planning metres = CRS units x metresPerUnit: polygons in feet are scaled like the raster was.
void scaleRings(OGRGeometry& geometry, double factor) {
    if (factor == 1.0)
        return;
    if (auto* collection = dynamic_cast<OGRGeometryCollection*>(&geometry)) {
        for (int index = 0; index < collection->getNumGeometries(); ++index)
            scaleRings(*collection->getGeometryRef(index), factor);
        return;
    }
    if (auto* polygon = dynamic_cast<OGRPolygon*>(&geometry)) {
        for (OGRLinearRing* ring : *polygon)
            for (int point = 0; point < ring->getNumPoints(); ++point)
                ring->setPoint(point, ring->getX(point) * factor, ring->getY(point) * factor);
    }
}

// Each polygon as its rings (the outer one, then its holes) of corners in the planning frame, for drawing.
void appendPolygons(const OGRGeometry& geometry, std::vector<AreaOutline::Polygon>& polygons) {
    if (const auto* collection = dynamic_cast<const OGRGeometryCollection*>(&geometry)) {
        for (int index = 0; index < collection->getNumGeometries(); ++index)
            appendPolygons(*collection->getGeometryRef(index), polygons);
        return;
    }
    if (const auto* polygon = dynamic_cast<const OGRPolygon*>(&geometry)) {
        AreaOutline::Polygon& rings = polygons.emplace_back();
        for (const OGRLinearRing* ring : *polygon) {
            AreaOutline::Ring& corners = rings.emplace_back();
            corners.reserve(static_cast<std::size_t>(ring->getNumPoints()));
            for (int point = 0; point < ring->getNumPoints(); ++point)
                corners.push_back({ring->getX(point), ring->getY(point)});
        }
    }
}

// Where a file's CRS is in degrees but its coordinates cannot be (metres read as longitude and latitude,
// most often a GeoJSON file without a "crs" member), what to do about it; empty otherwise.
std::string notDegreesProblem(const OGRGeometry& geometry, const OGRSpatialReference& source,
                              const std::string& path, bool geoJson, const LoadedRaster& raster) {
    if (!source.IsGeographic())
        return {};
    OGREnvelope envelope;
    geometry.getEnvelope(&envelope);
    // The corner quoted is one that cannot be degrees.
    const double x = std::abs(envelope.MinX) > 360.0 ? envelope.MinX : envelope.MaxX;
    const double y = std::abs(envelope.MinY) > 90.0 ? envelope.MinY : envelope.MaxY;
    if (std::abs(x) <= 360.0 && std::abs(y) <= 90.0)
        return {};
    const std::string code = raster.georeference.authorityCode();
    const char* name = source.GetName();
    return " has coordinates such as (" + formatQuantity(x, 10) + ", " + formatQuantity(y, 10) +
           "), which are not longitude and latitude, yet the file's CRS is " +
           (name != nullptr ? std::string(name) : std::string("geographic")) +
           (geoJson ? " (a GeoJSON file without a \"crs\" member is read as WGS 84)" : "") +
           ": give the file its CRS" +
           (code.empty()
                ? std::string()
                : " (ogr2ogr -a_srs " + code + " fixed" + std::filesystem::path(path).extension().string() +
                      " " + path + ", if they are in the raster's, " + raster.georeference.name() + ")");
}

// The polygons of a geometry GEOS mended, without the lines and points mending may leave; null if none.
OGRGeometry* polygonalPart(std::unique_ptr<OGRGeometry> geometry) {
    if (!geometry)
        return nullptr;
    const OGRwkbGeometryType type = wkbFlatten(geometry->getGeometryType());
    if (type == wkbPolygon || type == wkbMultiPolygon)
        return geometry.release();
    auto polygons = std::make_unique<OGRMultiPolygon>();
    if (const auto* collection = dynamic_cast<const OGRGeometryCollection*>(geometry.get()))
        for (const OGRGeometry* part : *collection) {
            const OGRwkbGeometryType partType = wkbFlatten(part->getGeometryType());
            if (partType == wkbPolygon)
                polygons->addGeometry(part);
            else if (partType == wkbMultiPolygon)
                for (const OGRPolygon* polygon : *part->toMultiPolygon())
                    polygons->addGeometry(polygon);
        }
    return polygons->IsEmpty() ? nullptr : polygons.release();
}

// A polygon whose outline crosses itself (a star drawn in one stroke, a bow-tie) is laid on the raster by
// GDAL even-odd, leaving out the parts its outline goes round twice (a star's middle); mended by joining
// its rings' enclosures (GEOS's structure method), it covers all it encloses. Whether it was mended.
bool mendedIfCrossing(OGRGeometry*& geometry) {
    if (!OGRGeometryFactory::haveGEOS() || geometry->IsValid())
        return false;
    const char* const structure[] = {"METHOD=STRUCTURE", nullptr};
    OGRGeometry* mended = polygonalPart(std::unique_ptr<OGRGeometry>(geometry->MakeValid(structure)));
    if (mended == nullptr)
        return false;
    OGRGeometryFactory::destroyGeometry(geometry);
    geometry = mended;
    return true;
}

// Every polygon of every layer, in the raster's planning frame; mended counts those whose outlines crossed
// themselves and were mended.
Result<int> readPolygons(const std::string& path, const LoadedRaster& raster, OwnedGeometries& out,
                         int& mended) {
    using Count = Result<int>;
    internal::ensureGdalRegistered();
    const QuietGdalErrors quiet;
    std::error_code code;
    if (path.rfind("/vsi", 0) != 0 && !std::filesystem::exists(path, code) &&
        !code) // not when it cannot tell
        return Count::failure(path + ": no such file");
    internal::DatasetPointer dataset(
        GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!dataset)
        return Count::failure(path + ": cannot be opened as a vector file" + QuietGdalErrors::detail());
    std::unique_ptr<OGRSpatialReference> planning;
    if (raster.georeference.hasCrs())
        planning = internal::spatialReferenceFromDefinition(raster.georeference.wkt());
    const double metresPerUnit = raster.georeference.metresPerUnit();
    int count = 0;
    for (OGRLayer* layer : dataset->GetLayers()) {
        std::unique_ptr<OGRCoordinateTransformation> toPlanning;
        if (const OGRSpatialReference* source = layer->GetSpatialRef(); source != nullptr && planning) {
            std::unique_ptr<OGRSpatialReference> traditional(source->Clone());
            traditional->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
            toPlanning.reset(OGRCreateCoordinateTransformation(traditional.get(), planning.get()));
            if (!toPlanning)
                return Count::failure(path + ": its CRS cannot be converted to the raster's (" +
                                      raster.georeference.name() + ")" + QuietGdalErrors::detail());
        }
        for (auto& feature : *layer) {
            const OGRGeometry* geometry = feature->GetGeometryRef();
            if (geometry == nullptr)
                continue;
            const OGRwkbGeometryType type = wkbFlatten(geometry->getGeometryType());
            if (type != wkbPolygon && type != wkbMultiPolygon)
                continue;
            OGRGeometry* copy = geometry->clone();
            out.geometries.push_back(copy);
            if (toPlanning && copy->transform(toPlanning.get()) != OGRERR_NONE) {
                const std::string where = path + ": feature " + std::to_string(feature->GetFID());
                const bool geoJson = std::string(dataset->GetDriver()->GetDescription()) == "GeoJSON";
                if (auto notDegrees =
                        notDegreesProblem(*geometry, *layer->GetSpatialRef(), path, geoJson, raster);
                    !notDegrees.empty())
                    return Count::failure(where + notDegrees);
                return Count::failure(where + " cannot be converted to the raster's CRS" +
                                      QuietGdalErrors::detail());
            }
            scaleRings(*copy, metresPerUnit);
            mended += mendedIfCrossing(out.geometries.back()) ? 1 : 0;
            ++count;
        }
    }
    if (count == 0)
        return Count::failure(path + ": holds no polygons (an area needs polygons or multipolygons)");
    return count;
}

// The polygons' union, overlaps counted once; null where GEOS cannot join them.
std::unique_ptr<OGRGeometry> unionOf(const std::vector<std::unique_ptr<OGRGeometry>>& geometries) {
    OGRMultiPolygon all;
    for (const auto& owned : geometries) {
        const OGRGeometry* geometry = owned.get();
        if (const auto* several = dynamic_cast<const OGRMultiPolygon*>(geometry))
            for (const OGRPolygon* polygon : *several)
                all.addGeometry(polygon);
        else
            all.addGeometry(geometry);
    }
    return std::unique_ptr<OGRGeometry>(all.UnionCascaded()); // the caller keeps GDAL quiet
}

double areaOf(const OGRGeometry* geometry) {
    return geometry != nullptr ? OGR_G_Area(OGRGeometry::ToHandle(const_cast<OGRGeometry*>(geometry))) : 0.0;
}

// How much of the polygons' area, in square metres, lies off the raster; 0 where GDAL has no GEOS to
// measure it with.
double areaOffTheRaster(const OwnedGeometries& polygons, const ClassGrid& grid) {
    if (!OGRGeometryFactory::haveGEOS())
        return 0.0;
    // Only polygons reaching past the raster's edge can lie off it: joining thousands of parcels wholly on
    // it would take a second for nothing.
    const QuietGdalErrors quiet;
    std::vector<std::unique_ptr<OGRGeometry>> crossing;
    for (const OGRGeometry* geometry : polygons.geometries) {
        OGREnvelope envelope;
        geometry->getEnvelope(&envelope);
        if (envelope.MinX >= grid.originX && envelope.MaxX <= grid.maxX() && envelope.MinY >= grid.minY() &&
            envelope.MaxY <= grid.originY)
            continue;
        // A polygon that crosses itself fails GEOS's overlay: it is mended first.
        std::unique_ptr<OGRGeometry> valid(geometry->IsValid() ? geometry->clone() : geometry->MakeValid());
        if (valid)
            crossing.push_back(std::move(valid));
    }
    if (crossing.empty())
        return 0.0;
    OGRLinearRing corners;
    corners.addPoint(grid.originX, grid.minY());
    corners.addPoint(grid.maxX(), grid.minY());
    corners.addPoint(grid.maxX(), grid.originY);
    corners.addPoint(grid.originX, grid.originY);
    corners.closeRings();
    OGRPolygon map;
    map.addRing(&corners);
    double off = 0.0;
    if (const std::unique_ptr<OGRGeometry> reaching = unionOf(crossing)) {
        const std::unique_ptr<OGRGeometry> offTheMap(reaching->Difference(&map));
        off = areaOf(offTheMap.get());
    } else {
        // Where the union still fails: each polygon's own part off the raster, overlaps counted twice,
        // rather than no warning at all.
        for (const auto& geometry : crossing) {
            const std::unique_ptr<OGRGeometry> offTheMap(geometry->Difference(&map));
            off += areaOf(offTheMap.get());
        }
    }
    return off;
}

// What an area file lays on the raster: 1 where a polygon covers the pixel's centre, on the raster's grid,
// and how much of the polygons' area lies off the raster (square metres).
struct LaidArea {
    std::vector<std::uint8_t> mask;
    double offTheRaster = 0.0;
    std::vector<AreaOutline::Polygon> polygons; // their edges, planning frame
    int mended = 0;                             // polygons whose outlines crossed themselves
};

// measured: whether to measure the part off the raster (an area to plan on, not a no-go zone).
Result<LaidArea> rasterise(const std::string& path, const LoadedRaster& raster, bool measured) {
    using Mask = Result<LaidArea>;
    OwnedGeometries polygons;
    int mended = 0;
    if (auto read = readPolygons(path, raster, polygons, mended); !read)
        return Mask::failure(read.error());
    const ClassGrid& grid = raster.grid;
    GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
    internal::DatasetPointer canvas(memory->Create("", grid.columns, grid.rows, 1, GDT_Byte, nullptr));
    double transform[6] = {grid.originX, grid.pixelWidth, 0.0, grid.originY, 0.0, -grid.pixelHeight};
    canvas->SetGeoTransform(transform);
    int bands[1] = {1};
    // One burn value per polygon and band: GDAL reads as many as it is given polygons.
    const std::vector<double> burn(polygons.geometries.size(), 1.0);
    const QuietGdalErrors quiet;
    if (GDALRasterizeGeometries(canvas.get(), 1, bands, static_cast<int>(polygons.geometries.size()),
                                reinterpret_cast<OGRGeometryH*>(polygons.geometries.data()), nullptr, nullptr,
                                burn.data(), nullptr, nullptr, nullptr) != CE_None)
        return Mask::failure(path + ": its polygons could not be laid on the raster" +
                             QuietGdalErrors::detail());
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(grid.columns) *
                                   static_cast<std::size_t>(grid.rows));
    if (canvas->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, grid.columns, grid.rows, mask.data(), grid.columns,
                                           grid.rows, GDT_Byte, 0, 0, nullptr) != CE_None)
        return Mask::failure(path + ": its polygons could not be laid on the raster" +
                             QuietGdalErrors::detail());
    const double off = measured ? areaOffTheRaster(polygons, grid) : 0.0;
    std::vector<AreaOutline::Polygon> edges;
    for (const OGRGeometry* geometry : polygons.geometries)
        appendPolygons(*geometry, edges);
    return LaidArea{std::move(mask), off, std::move(edges), mended};
}

// What of the area drawn to plan on is left out, off the raster or over its nodata, where that is more than a
// pixel's worth (and, over nodata, more than half a percent of the area: rasters have stray nodata pixels).
std::optional<std::string> areaLeftOut(double offTheRaster, double onTheRaster, double overNodata,
                                       double pixelArea, const std::string& path) {
    const double drawn = offTheRaster + onTheRaster;
    const bool off = offTheRaster > pixelArea;
    const bool nodata = overNodata > std::max(pixelArea, 0.005 * drawn);
    if (!off && !nodata)
        return std::nullopt;
    std::string where;
    if (off)
        where = formatArea(offTheRaster) + " lies off the raster";
    if (nodata)
        where += (off ? " and " + formatArea(overNodata) + " over its nodata,"
                      : formatArea(overNodata) + " lies over the raster's nodata (no land cover)");
    return "area of interest: of the " + formatArea(drawn) + " in " +
           std::filesystem::path(path).filename().string() + ", " + where + " and is left out" +
           (off ? " (a larger raster, or a mosaic of tiles, would cover it)" : "");
}

// What mending polygons that crossed themselves did, for the user to check against what they meant.
std::optional<std::string> mendedNote(const std::string& subject, int mended, const std::string& path) {
    if (mended == 0)
        return std::nullopt;
    return subject + ": " + std::to_string(mended) + (mended == 1 ? " polygon" : " polygons") + " of " +
           std::filesystem::path(path).filename().string() +
           (mended == 1 ? " is not a simple polygon (its outline crosses itself)"
                        : " are not simple polygons (their outlines cross themselves)") +
           ": taken as all " + (mended == 1 ? "its outline encloses" : "their outlines enclose") +
           ", parts gone round twice included";
}

} // namespace

Status applyAreaOfInterest(LoadedRaster& raster, const std::string& includePath,
                           const std::string& excludePath) {
    if (includePath.empty() && excludePath.empty())
        return {};
    ClassGrid& grid = raster.grid;
    if (grid.outside.empty())
        grid.outside.assign(grid.values.size(), 0);
    std::vector<std::uint8_t> include;
    std::vector<std::uint8_t> exclude;
    double offTheRaster = 0.0;
    if (!includePath.empty()) {
        auto laid = rasterise(includePath, raster, true);
        if (!laid)
            return Status::failure(laid.error());
        include = std::move(laid.value().mask);
        offTheRaster = laid.value().offTheRaster;
        raster.area.include = std::move(laid.value().polygons);
        if (auto note = mendedNote("area of interest", laid.value().mended, includePath))
            raster.warnings.push_back(std::move(*note));
    }
    if (!excludePath.empty()) {
        auto laid = rasterise(excludePath, raster, false);
        if (!laid)
            return Status::failure(laid.error());
        exclude = std::move(laid.value().mask);
        raster.area.exclude = std::move(laid.value().polygons);
        if (auto note = mendedNote("no-go zones", laid.value().mended, excludePath))
            raster.warnings.push_back(std::move(*note));
    }
    std::map<std::int32_t, std::int64_t> counts;
    std::int64_t inside = 0;
    std::int64_t laidPixels = 0; // of the area to plan on, on the raster
    std::int64_t overNodata = 0; // of those, where the raster has no land cover
    std::int64_t noGoPixels = 0; // of the no-go zones, on the raster
    for (std::size_t pixel = 0; pixel < grid.values.size(); ++pixel) {
        if (!include.empty() && include[pixel] != 0) {
            ++laidPixels;
            overNodata += grid.outside[pixel] == ClassGrid::outsideNodata ? 1 : 0;
        }
        noGoPixels += !exclude.empty() && exclude[pixel] != 0 ? 1 : 0;
        if (grid.outside[pixel] != 0)
            continue;
        if (!include.empty() && include[pixel] == 0) {
            grid.outside[pixel] = ClassGrid::outsideArea;
            continue;
        }
        if (!exclude.empty() && exclude[pixel] != 0) {
            grid.outside[pixel] = ClassGrid::inNoGoZone;
            continue;
        }
        ++counts[grid.values[pixel]];
        ++inside;
    }
    if (inside == 0) {
        const std::string files = includePath.empty() ? excludePath : includePath;
        return Status::failure(files + ": the area leaves no pixel of " + raster.path +
                               " to plan on (do the polygons overlap the map, in the right CRS?)");
    }
    raster.classPixelCounts = std::move(counts);
    const double pixelArea = grid.pixelWidth * grid.pixelHeight;
    raster.notes.push_back(
        (includePath.empty() ? "no-go zones: planning on " : "area of interest: planning on ") +
        formatArea(static_cast<double>(inside) * pixelArea) + " of the map");
    // A file in the wrong place or CRS would otherwise leave nothing out without a word.
    if (!excludePath.empty() && noGoPixels == 0)
        raster.warnings.push_back("no-go zones: no polygon of " +
                                  std::filesystem::path(excludePath).filename().string() +
                                  " lies on the raster, so none is left out (are its coordinates in the "
                                  "CRS the file names?)");
    if (auto leftOut = areaLeftOut(offTheRaster, static_cast<double>(laidPixels) * pixelArea,
                                   static_cast<double>(overNodata) * pixelArea, pixelArea, includePath))
        raster.warnings.push_back(std::move(*leftOut));
    return {};
}

Status writeAreaPolygons(const std::string& path, const std::vector<std::vector<MapPoint>>& rings,
                         const LoadedRaster& raster, const std::string& keepPolygonsOf) {
    internal::ensureGdalRegistered();
    const QuietGdalErrors quiet;
    OwnedGeometries kept;
    if (!keepPolygonsOf.empty()) {
        int mended = 0; // kept as planning takes them
        if (auto read = readPolygons(keepPolygonsOf, raster, kept, mended); !read)
            return Status::failure(read.error());
    }
    internal::DatasetFile file(path);
    if (Status status = file.create("GeoJSON", 0, 0, 0, GDT_Unknown); !status)
        return status;
    std::unique_ptr<OGRSpatialReference> crs;
    if (raster.georeference.hasCrs())
        crs = internal::spatialReferenceFromDefinition(raster.georeference.wkt());
    OGRLayer* layer = file.dataset().CreateLayer("area", crs.get(), wkbUnknown, nullptr);
    if (layer == nullptr)
        return Status::failure(path + ": cannot create the layer" + QuietGdalErrors::detail());
    const double metresPerUnit = raster.georeference.metresPerUnit();
    const auto add = [&](const OGRGeometry& geometry) {
        OGRFeature feature(layer->GetLayerDefn());
        feature.SetGeometry(&geometry);
        return layer->CreateFeature(&feature) == OGRERR_NONE;
    };
    for (OGRGeometry* geometry : kept.geometries) {
        scaleRings(*geometry, 1.0 / metresPerUnit); // planning metres back to the CRS's units
        if (!add(*geometry))
            return Status::failure(path + ": cannot write a polygon" + QuietGdalErrors::detail());
    }
    for (const std::vector<MapPoint>& corners : rings) {
        OGRPolygon polygon;
        polygon.addRingDirectly(internal::crsRing(corners, metresPerUnit).release());
        if (!add(polygon))
            return Status::failure(path + ": cannot write a polygon" + QuietGdalErrors::detail());
    }
    return file.commit(Sync::ToDisk); // an area the user drew
}

} // namespace mcpp::io
