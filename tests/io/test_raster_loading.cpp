// Loading the real land-cover rasters of tests/data/landcover: size, CRS, pixel size, class counts, legends,
// plus made-up cases (feet CRS, no CRS, float bands, non-square geographic pixels, coarsening).
// Class counts were taken once with `gdal_translate -of AAIGrid` and counting values; they are fixed here.

#include "io/LoadedRaster.hpp"
#include "tests/support/TestData.hpp"

#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gdal_priv.h>
#include <numeric>
#include <ogr_spatialref.h>
#include <thread>

using namespace mcpp;
using namespace mcpp::io;
using mcpp::test::testDataPath;

namespace {

LoadedRaster loadOrFail(const std::string& path, const RasterLoadOptions& options = {}) {
    auto loaded = loadLandCoverRaster(path, options);
    if (!loaded)
        qFatal("%s", loaded.error().c_str());
    return std::move(loaded.value());
}

const LegendEntry* legendEntry(const LoadedRaster& raster, std::int32_t value) {
    for (const LegendEntry& entry : raster.legend) {
        if (entry.value == value)
            return &entry;
    }
    return nullptr;
}

// OGR's own transformation from a CRS (its file units) to WGS84 longitude, latitude: the tests' oracle.
std::unique_ptr<OGRCoordinateTransformation> oracleToWgs84(const char* definition) {
    OGRSpatialReference crs;
    crs.SetFromUserInput(definition);
    crs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    return std::unique_ptr<OGRCoordinateTransformation>(OGRCreateCoordinateTransformation(&crs, &wgs84));
}

std::int64_t insidePixels(const ClassGrid& grid) {
    std::int64_t count = 0;
    for (int row = 0; row < grid.rows; ++row) {
        for (int column = 0; column < grid.columns; ++column)
            count += grid.isOutside(column, row) ? 0 : 1;
    }
    return count;
}

// Area of a longitude/latitude rectangle on the WGS84 ellipsoid (authalic-latitude formula).
double ellipsoidRectangleArea(double west, double south, double east, double north) {
    const double a = 6378137.0;
    const double f = 1.0 / 298.257223563;
    const double e2 = f * (2.0 - f);
    const double e = std::sqrt(e2);
    const double b2 = a * a * (1.0 - e2);
    const auto s = [&](double latitudeDegrees) {
        const double sine = std::sin(latitudeDegrees * M_PI / 180.0);
        return sine / (2.0 * (1.0 - e2 * sine * sine)) +
               std::log((1.0 + e * sine) / (1.0 - e * sine)) / (4.0 * e);
    };
    return (east - west) * M_PI / 180.0 * b2 * (s(north) - s(south));
}

// Writes a one-band GeoTIFF of the given type, values value(column, row).
template <typename ValueOf>
void writeRaster(const std::string& path, int columns, int rows, GDALDataType type, const double transform[6],
                 const char* crs, ValueOf valueOf, std::optional<double> nodata = std::nullopt) {
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    GDALDataset* dataset = driver->Create(path.c_str(), columns, rows, 1, type, nullptr);
    QVERIFY(dataset != nullptr);
    dataset->SetGeoTransform(const_cast<double*>(transform));
    if (crs != nullptr) {
        OGRSpatialReference reference;
        reference.SetFromUserInput(crs);
        dataset->SetSpatialRef(&reference);
    }
    std::vector<double> values(static_cast<std::size_t>(columns * rows));
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column)
            values[static_cast<std::size_t>(row * columns + column)] = valueOf(column, row);
    }
    GDALRasterBand* band = dataset->GetRasterBand(1);
    if (nodata)
        band->SetNoDataValue(*nodata);
    QCOMPARE(band->RasterIO(GF_Write, 0, 0, columns, rows, values.data(), columns, rows, GDT_Float64, 0, 0,
                            nullptr),
             CE_None);
    GDALClose(dataset);
}

// 200 x 200 pixels of 0.001 x 0.0005 degrees at 45 degrees north, the western half class 1 and the eastern 2.
void writeTwoHalvesInDegrees(const std::string& path) {
    const double transform[6] = {10.0, 0.001, 0.0, 45.1, 0.0, -0.0005};
    writeRaster(path, 200, 200, GDT_Byte, transform, "EPSG:4326",
                [](int column, int) { return column < 100 ? 1 : 2; });
}

} // namespace

class RasterLoadingTest : public QObject {
    Q_OBJECT

  private slots:
    void nlcdUtmWithCategoryNames() {
        const LoadedRaster raster = loadOrFail(testDataPath("landcover/nlcd.tif"));
        QCOMPARE(raster.grid.columns, 1073);
        QCOMPARE(raster.grid.rows, 1359);
        QCOMPARE(raster.sourceColumns, 1073);
        QCOMPARE(raster.georeference.authorityCode(), std::string("EPSG:26912"));
        QVERIFY(raster.georeference.name().find("UTM zone 12N") != std::string::npos);
        QVERIFY(std::abs(raster.grid.pixelWidth - 31.530298224786595) < 1e-9);
        QVERIFY(std::abs(raster.grid.pixelHeight - 31.524658701787931) < 1e-9);
        QVERIFY(std::abs(raster.grid.originX - 301903.344386758) < 1e-6);
        QVERIFY(std::abs(raster.grid.originY - 4154086.47216415) < 1e-6);
        QVERIFY(!raster.warpedFromGeographic);
        QVERIFY(!raster.coarsened);
        const std::map<std::int32_t, std::int64_t> expected{{1, 1209},   {2, 17517}, {3, 106070}, {4, 767537},
                                                            {5, 545771}, {6, 4878},  {7, 8728},   {8, 6497}};
        QVERIFY(raster.classPixelCounts == expected);
        QVERIFY(raster.grid.outside.empty()); // nodata 255 does not occur
        QCOMPARE(raster.legendSource, std::string("category names + palette"));
        QVERIFY(legendEntry(raster, 4) != nullptr);
        QCOMPARE(legendEntry(raster, 4)->name, std::string("Forest"));
        QCOMPARE(legendEntry(raster, 8)->name, std::string("Wetlands"));
        QCOMPARE(legendEntry(raster, 1)->colorRgb.value_or(0), 0x476ba0U);
        QCOMPARE(raster.grid.valueAt(0, 0), raster.grid.values.front());
        // A point in the middle goes to WGS84 where gdalinfo puts the centre: 113d02'41.47"W, 37d19'22.80"N.
        const MapPoint centre{318819.349, 4132665.467};
        auto lonLat = raster.georeference.toWgs84(centre);
        QVERIFY(lonLat.ok());
        QVERIFY(std::abs(lonLat.value().longitude - -(113.0 + 2.0 / 60 + 41.47 / 3600)) < 1e-5);
        QVERIFY(std::abs(lonLat.value().latitude - (37.0 + 19.0 / 60 + 22.80 / 3600)) < 1e-5);
        auto back = raster.georeference.fromWgs84(lonLat.value());
        QVERIFY(back.ok());
        QVERIFY(std::abs(back.value().x - centre.x) < 1e-4 && std::abs(back.value().y - centre.y) < 1e-4);
    }

    void corineSpainNorthingFirstWithQgisStyle() {
        const LoadedRaster raster = loadOrFail(testDataPath("landcover/corine-spain/clc.tif"));
        QCOMPARE(raster.grid.columns, 474);
        QCOMPARE(raster.grid.rows, 745);
        QCOMPARE(raster.georeference.authorityCode(), std::string("EPSG:3042"));
        QCOMPARE(raster.grid.pixelWidth, 25.0);
        QCOMPARE(raster.grid.pixelHeight, 25.0);
        // Easting first in the planning frame although EPSG:3042 lists northing first.
        QCOMPARE(raster.grid.originX, 453239.0);
        QCOMPARE(raster.grid.originY, 4099639.0);
        auto lonLat = raster.georeference.toWgs84({459164.0, 4090326.5});
        QVERIFY(lonLat.ok());
        QVERIFY(std::abs(lonLat.value().longitude - -(3.0 + 27.0 / 60 + 31.33 / 3600)) < 1e-5);
        QVERIFY(std::abs(lonLat.value().latitude - (36.0 + 57.0 / 60 + 29.29 / 3600)) < 1e-5);
        QCOMPARE(raster.classPixelCounts.size(), std::size_t{20});
        QCOMPARE(raster.classPixelCounts.at(111), std::int64_t{891});
        QCOMPARE(raster.classPixelCounts.at(323), std::int64_t{114032});
        QCOMPARE(raster.classPixelCounts.at(512), std::int64_t{2881});
        const std::int64_t total =
            std::accumulate(raster.classPixelCounts.begin(), raster.classPixelCounts.end(), std::int64_t{0},
                            [](std::int64_t sum, const auto& entry) { return sum + entry.second; });
        QCOMPARE(total + (raster.grid.outside.empty()
                              ? 0
                              : std::count(raster.grid.outside.begin(), raster.grid.outside.end(), 1)),
                 std::int64_t{474 * 745});
        QCOMPARE(raster.legendSource, std::string("qml"));
        QCOMPARE(legendEntry(raster, 111)->name, std::string("Tejido urbano continuo"));
        QCOMPARE(legendEntry(raster, 111)->colorRgb.value_or(0), 0xe6004dU);
        QCOMPARE(legendEntry(raster, 312)->name,
                 std::string("Bosques de coniferas")); // trailing newline trimmed
    }

    void worldcoverGeographicIsWarpedToUtm() {
        const LoadedRaster raster = loadOrFail(testDataPath("landcover/worldcover2021_principe_crop.tif"));
        QVERIFY(raster.warpedFromGeographic);
        QCOMPARE(raster.sourceColumns, 2400);
        QCOMPARE(raster.sourceRows, 2640);
        QCOMPARE(raster.georeference.authorityCode(), std::string("EPSG:32632"));
        QVERIFY(raster.grid.pixelWidth > 9.0 && raster.grid.pixelWidth < 9.5);
        // Planning in metres is news, not a warning.
        const std::string warp =
            "geographic CRS WGS 84: planned in WGS 84 / UTM zone 32N (nearest-neighbour warp)";
        QVERIFY(std::find(raster.notes.begin(), raster.notes.end(), warp) != raster.notes.end());
        QVERIFY(std::none_of(raster.warnings.begin(), raster.warnings.end(), [](const std::string& text) {
            return text.find("geographic CRS") != std::string::npos;
        }));
        QCOMPARE(raster.legendSource, std::string("legend metadata + palette"));
        QCOMPARE(legendEntry(raster, 10)->colorRgb.value_or(0), 0x006400U);
        QCOMPARE(legendEntry(raster, 80)->name, std::string("Permanent water bodies"));
        // Total area against the ellipsoidal area of the 0.2 x 0.22 degree extent.
        const double pixelArea = raster.grid.pixelWidth * raster.grid.pixelHeight;
        const double area = static_cast<double>(insidePixels(raster.grid)) * pixelArea;
        const double expected = ellipsoidRectangleArea(7.3, 1.5, 7.5, 1.72);
        QVERIFY2(std::abs(area - expected) / expected < 0.005,
                 qPrintable(QString("area %1 vs %2").arg(area).arg(expected)));
        // The share of water keeps its size through the warp.
        const double water = static_cast<double>(raster.classPixelCounts.at(80)) * pixelArea;
        const double expectedWater = expected * 4721334.0 / 6336000.0;
        QVERIFY(std::abs(water - expectedWater) / expectedWater < 0.005);
        QCOMPARE(raster.classPixelCounts.count(0), std::size_t{0});
    }

    void nrcanLambert() {
        const LoadedRaster raster = loadOrFail(testDataPath("landcover/nrcan_landcover2015_example.tif"));
        QCOMPARE(raster.grid.columns, 652);
        QCOMPARE(raster.grid.rows, 367);
        QCOMPARE(raster.georeference.authorityCode(), std::string("EPSG:3978"));
        QCOMPARE(raster.grid.pixelWidth, 30.0);
        // At 118 W the Lambert grid of central meridian 95 W is turned: true north lies 20.65 degrees
        // clockwise of the grid's north (gdaltransform of the centre and a point a kilometre north of it).
        const double turn = raster.grid.trueNorthRadians * 180.0 / std::acos(-1.0);
        QVERIFY2(std::abs(turn + 20.65) < 0.01, qPrintable(QString::number(turn)));
        QCOMPARE(raster.classPixelCounts.at(1), std::int64_t{125065});
        QCOMPARE(raster.classPixelCounts.at(18), std::int64_t{23017});
        QCOMPARE(raster.classPixelCounts.at(19), std::int64_t{38});
        QCOMPARE(raster.classPixelCounts.size(), std::size_t{13});
        QVERIFY(raster.legend.empty());
        QVERIFY(raster.legendSource.empty());
    }

    void corineSwissHalfNodataWithPalette() {
        const LoadedRaster raster = loadOrFail(testDataPath("landcover/corine2006_swiss_ls100.tif"));
        QCOMPARE(raster.grid.columns, 472);
        QCOMPARE(raster.grid.rows, 325);
        QCOMPARE(raster.georeference.authorityCode(), std::string("EPSG:2056"));
        QVERIFY(std::abs(raster.grid.pixelWidth - 100.005124296245782) < 1e-9);
        QCOMPARE(std::count(raster.grid.outside.begin(), raster.grid.outside.end(), 1),
                 std::ptrdiff_t{76111});
        QCOMPARE(raster.classPixelCounts.at(12), std::int64_t{45681});
        QCOMPARE(raster.classPixelCounts.at(41), std::int64_t{77});
        QCOMPARE(raster.classPixelCounts.count(255), std::size_t{0});
        QCOMPARE(raster.legendSource, std::string("palette"));
        QCOMPARE(legendEntry(raster, 1)->colorRgb.value_or(0), 0xe6004dU);
    }

    void feetCrsIsConvertedToMetres() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("feet.tif").toStdString();
        const double transform[6] = {6000000.0, 100.0, 0.0, 2100000.0, 0.0, -100.0};
        writeRaster(path, 10, 8, GDT_Byte, transform, "EPSG:2227",
                    [](int column, int) { return 1 + column % 3; });
        const LoadedRaster raster = loadOrFail(path);
        const double usFoot = 1200.0 / 3937.0;
        QVERIFY(std::abs(raster.georeference.metresPerUnit() - usFoot) < 1e-12);
        QVERIFY(std::abs(raster.grid.pixelWidth - 100.0 * usFoot) < 1e-9);
        QVERIFY(std::abs(raster.grid.pixelHeight - 100.0 * usFoot) < 1e-9);
        QVERIFY(std::abs(raster.grid.originX - 6000000.0 * usFoot) < 1e-6);
        QVERIFY(std::abs(raster.grid.originY - 2100000.0 * usFoot) < 1e-6);
        QVERIFY(std::abs(raster.grid.width() - 1000.0 * usFoot) < 1e-9);
        // The metre frame maps to the same place as the raw feet coordinates do.
        const auto transformation = oracleToWgs84("EPSG:2227");
        double x = 6000000.0, y = 2100000.0;
        QVERIFY(transformation->Transform(1, &x, &y));
        auto lonLat = raster.georeference.toWgs84({raster.grid.originX, raster.grid.originY});
        QVERIFY(lonLat.ok());
        QVERIFY(std::abs(lonLat.value().longitude - x) < 1e-9);
        QVERIFY(std::abs(lonLat.value().latitude - y) < 1e-9);
        QCOMPARE(raster.georeference.toCrsUnits({raster.grid.originX, raster.grid.originY}).x, 6000000.0);
    }

    // Exports take a path's points to WGS84 in one call: the same places as OGR's own transformation of each
    // point gives (the planning frame is metres, the feet CRS's file units are feet), and a point PROJ cannot
    // place is named.
    void manyPointsGoToWgs84AsOneByOne() {
        // UTM 12N in metres and California zone 3 in US feet, each with points inside its area.
        const std::vector<std::pair<const char*, MapPoint>> crss{{"EPSG:26912", {400000.0, 4100000.0}},
                                                                 {"EPSG:2227", {1830000.0, 640000.0}}};
        for (const auto& [definition, origin] : crss) {
            const GeoReference reference = GeoReference::fromDefinition(definition).value();
            std::vector<MapPoint> points;
            for (int i = 0; i < 50; ++i)
                points.push_back({origin.x + 997.0 * i, origin.y + 1511.0 * i});
            const auto together = reference.toWgs84(points);
            QVERIFY(together.ok());
            QCOMPARE(together.value().size(), points.size());
            const auto oracle = oracleToWgs84(definition);
            const double metresPerUnit = reference.metresPerUnit();
            for (std::size_t i = 0; i < points.size(); ++i) {
                double x = points[i].x / metresPerUnit, y = points[i].y / metresPerUnit;
                QVERIFY(oracle->Transform(1, &x, &y));
                QVERIFY(std::abs(together.value()[i].longitude - x) < 1e-9);
                QVERIFY(std::abs(together.value()[i].latitude - y) < 1e-9);
                const LonLat alone = reference.toWgs84(points[i]).value();
                QCOMPARE(alone.longitude, together.value()[i].longitude);
            }
            QVERIFY(reference.toWgs84(std::vector<MapPoint>{}).value().empty());
        }
        // Far outside the transverse Mercator's domain: the whole call fails, naming the point.
        const GeoReference utm = GeoReference::fromDefinition("EPSG:26912").value();
        const auto failed = utm.toWgs84(std::vector<MapPoint>{{400000.0, 4100000.0}, {1e30, -1e30}});
        QVERIFY(!failed.ok());
        QVERIFY2(failed.error().find("point (1000000000000000") != std::string::npos &&
                     failed.error().find("cannot be transformed to WGS84") != std::string::npos,
                 failed.error().c_str());
    }

    // A batch run makes its writers' transformations on a spare thread while it plans: made there, on a
    // thread since ended, and then used by several threads at once, they place every point where one made
    // on the spot does (NAD83 to WGS84 picks among datum shifts; UTM in WGS84 needs none).
    void transformationsMadeAheadOnAnotherThreadAgree() {
        for (const char* definition : {"EPSG:26912", "EPSG:32633"}) {
            const GeoReference fresh = GeoReference::fromDefinition(definition).value();
            const GeoReference prepared = GeoReference::fromDefinition(definition).value();
            std::thread([&prepared] { prepared.prepareTransformationsToWgs84(3); }).join();
            const MapPoint origin = std::string(definition) == "EPSG:26912" ? MapPoint{400000.0, 4100000.0}
                                                                            : MapPoint{431000.0, 5398000.0};
            std::vector<MapPoint> points;
            for (int i = 0; i < 40; ++i)
                points.push_back({origin.x + 613.0 * i, origin.y + 911.0 * i});
            const std::vector<LonLat> expected = fresh.toWgs84(points).value();
            std::vector<std::vector<LonLat>> placed(3);
            std::vector<std::thread> writers;
            for (std::size_t writer = 0; writer < placed.size(); ++writer)
                writers.emplace_back([&, writer] {
                    if (auto lonLats = prepared.toWgs84(points))
                        placed[writer] = std::move(lonLats.value());
                });
            for (std::thread& writer : writers)
                writer.join();
            for (const std::vector<LonLat>& lonLats : placed) {
                QCOMPARE(lonLats.size(), expected.size());
                for (std::size_t i = 0; i < expected.size(); ++i) {
                    QCOMPARE(lonLats[i].longitude, expected[i].longitude);
                    QCOMPARE(lonLats[i].latitude, expected[i].latitude);
                }
            }
        }
        GeoReference().prepareTransformationsToWgs84(2); // no CRS: nothing to make, and no failure
    }

    void noCrsIsPlannedInItsOwnUnits() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("nocrs.tif").toStdString();
        const double transform[6] = {1000.0, 2.0, 0.0, 500.0, 0.0, -2.0};
        writeRaster(path, 6, 4, GDT_Int16, transform, nullptr,
                    [](int column, int row) { return column + row; });
        const LoadedRaster raster = loadOrFail(path);
        QVERIFY(!raster.georeference.hasCrs());
        QCOMPARE(raster.grid.pixelWidth, 2.0);
        QCOMPARE(raster.grid.originX, 1000.0);
        QVERIFY(!raster.warnings.empty());
        QVERIFY(!raster.georeference.toWgs84({1000.0, 500.0}).ok());
    }

    void floatBandWithWholeValuesIsAccepted() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("float.tif").toStdString();
        const double transform[6] = {500000.0, 10.0, 0.0, 4000000.0, 0.0, -10.0};
        writeRaster(
            path, 5, 5, GDT_Float32, transform, "EPSG:32633",
            [](int column, int row) {
                return row == 0 && column == 0 ? -9999.0 : 10.0 * (1 + (column + row) % 2);
            },
            -9999.0);
        const LoadedRaster raster = loadOrFail(path);
        QCOMPARE(raster.classPixelCounts.at(10) + raster.classPixelCounts.at(20), std::int64_t{24});
        QVERIFY(raster.grid.isOutside(0, 0));
        QVERIFY(!raster.grid.isOutside(1, 0));
    }

    void floatBandWithFractionsIsRejected() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("fractions.tif").toStdString();
        const double transform[6] = {500000.0, 10.0, 0.0, 4000000.0, 0.0, -10.0};
        writeRaster(path, 4, 4, GDT_Float64, transform, "EPSG:32633",
                    [](int column, int) { return column * 0.25; });
        auto loaded = loadLandCoverRaster(path);
        QVERIFY(!loaded.ok());
        QVERIFY(loaded.error().find("fractional") != std::string::npos);
        QVERIFY(loaded.error().find("fractions.tif") != std::string::npos);
    }

    void geographicNonSquarePixels() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("geographic.tif").toStdString();
        writeTwoHalvesInDegrees(path);
        const LoadedRaster raster = loadOrFail(path);
        QVERIFY(raster.warpedFromGeographic);
        QCOMPARE(raster.georeference.authorityCode(), std::string("EPSG:32632"));
        const double area =
            static_cast<double>(insidePixels(raster.grid)) * raster.grid.pixelWidth * raster.grid.pixelHeight;
        const double expected = ellipsoidRectangleArea(10.0, 45.0, 10.2, 45.1);
        QVERIFY2(std::abs(area - expected) / expected < 0.005,
                 qPrintable(QString("area %1 vs %2").arg(area).arg(expected)));
        // Both halves keep about half the area.
        const double ratio = static_cast<double>(raster.classPixelCounts.at(1)) /
                             static_cast<double>(raster.classPixelCounts.at(2));
        QVERIFY(std::abs(ratio - 1.0) < 0.02);
    }

    void largeRasterIsCoarsenedWithinBudget() {
        RasterLoadOptions options;
        options.pixelBudget = 100000;
        const LoadedRaster raster = loadOrFail(testDataPath("landcover/nlcd.tif"), options);
        QVERIFY(raster.coarsened);
        QVERIFY(static_cast<std::int64_t>(raster.grid.columns) * raster.grid.rows <= 100000);
        QVERIFY(raster.grid.columns > 200);
        QVERIFY(std::abs(raster.grid.width() - 1073 * 31.530298224786595) < 1e-6);
        QVERIFY(std::abs(raster.grid.height() - 1359 * 31.524658701787931) < 1e-6);
        QVERIFY(raster.effectiveResolutionMetres > 100.0 && raster.effectiveResolutionMetres < 140.0);
        QVERIFY(!raster.warnings.empty());
        QVERIFY2(
            raster.warnings.back().rfind(
                "raster has 1073 x 1359 pixels (1.46 million), above the budget of 0.1 million pixels: read "
                "at ",
                0) == 0,
            raster.warnings.back().c_str());
        // Mode resampling keeps the proportions of the big classes.
        const double pixels = static_cast<double>(raster.grid.columns) * raster.grid.rows;
        QVERIFY(std::abs(raster.classPixelCounts.at(4) / pixels - 767537.0 / 1458207.0) < 0.05);
        QVERIFY(std::abs(raster.classPixelCounts.at(5) / pixels - 545771.0 / 1458207.0) < 0.05);
    }

    // A raster in degrees is warped to UTM; where the warped grid is above the budget, it is warped straight
    // to a coarser one, and the warning gives the warped size in pixels and millions.
    void geographicRasterAboveTheBudgetIsWarpedCoarser() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("geographic.tif").toStdString();
        writeTwoHalvesInDegrees(path);
        const LoadedRaster whole = loadOrFail(path);
        const std::int64_t wholePixels = static_cast<std::int64_t>(whole.grid.columns) * whole.grid.rows;
        QVERIFY(!whole.coarsened);
        RasterLoadOptions options;
        options.pixelBudget = 10000;
        const LoadedRaster raster = loadOrFail(path, options);
        QVERIFY(raster.coarsened);
        QVERIFY(raster.warpedFromGeographic);
        QVERIFY(static_cast<std::int64_t>(raster.grid.columns) * raster.grid.rows <= options.pixelBudget);
        // The same ground, in fewer and larger pixels.
        QVERIFY(std::abs(raster.grid.width() - whole.grid.width()) / whole.grid.width() < 0.02);
        QVERIFY(std::abs(raster.grid.height() - whole.grid.height()) / whole.grid.height() < 0.02);
        const std::string head = "raster warps to " + std::to_string(whole.grid.columns) + " x " +
                                 std::to_string(whole.grid.rows) + " pixels (";
        const std::string tail = " million), above the budget of 0.01 million pixels: warped straight to " +
                                 std::to_string(raster.grid.columns) + " x " +
                                 std::to_string(raster.grid.rows) + " (mode resampling)";
        const auto warning = std::find_if(raster.warnings.begin(), raster.warnings.end(),
                                          [&](const std::string& text) { return text.rfind(head, 0) == 0; });
        QVERIFY(!raster.warnings.empty());
        QVERIFY2(warning != raster.warnings.end(), raster.warnings.front().c_str());
        QVERIFY2(warning->size() > head.size() + tail.size() &&
                     warning->compare(warning->size() - tail.size(), tail.size(), tail) == 0,
                 warning->c_str());
        // The count in millions, to three significant digits.
        const double millions = std::stod(warning->substr(head.size()));
        QVERIFY2(std::abs(millions * 1e6 - static_cast<double>(wholePixels)) <= 0.005 * wholePixels,
                 warning->c_str());
        QVERIFY(std::any_of(raster.notes.begin(), raster.notes.end(), [](const std::string& text) {
            return text.find("(warped by mode to the pixel budget)") != std::string::npos;
        }));
    }

    void bandOutOfRangeIsAnError() {
        RasterLoadOptions options;
        options.band = 2;
        auto loaded = loadLandCoverRaster(testDataPath("landcover/nlcd.tif"), options);
        QVERIFY(!loaded.ok());
        QVERIFY(loaded.error().find("band 2") != std::string::npos);
    }

    void inputRasterIsNeverWritten() {
        QTemporaryDir folder;
        const std::filesystem::path copy = std::filesystem::path(folder.path().toStdString()) / "copy.tif";
        std::filesystem::copy_file(testDataPath("landcover/nrcan_landcover2015_example.tif"), copy);
        const auto before = std::filesystem::last_write_time(copy);
        RasterLoadOptions options;
        options.pixelBudget = 50000; // the coarsening path too
        QVERIFY(loadLandCoverRaster(copy.string(), options).ok());
        QVERIFY(loadLandCoverRaster(copy.string()).ok());
        QCOMPARE(std::filesystem::last_write_time(copy), before);
        int files = 0;
        for ([[maybe_unused]] const auto& entry :
             std::filesystem::directory_iterator(folder.path().toStdString()))
            ++files;
        QCOMPARE(files, 1); // no .aux.xml or .ovr appeared
    }
};

QTEST_GUILESS_MAIN(RasterLoadingTest)
#include "test_raster_loading.moc"
