// Areas of interest and no-go zones from vector files laid on the raster's grid.

#include "io/AreaOfInterest.hpp"
#include "io/Mission.hpp"
#include "io/MissionInputs.hpp"
#include "tests/support/TestData.hpp"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace mcpp;
using namespace mcpp::io;

namespace {

LoadedRaster zion() {
    auto raster = loadLandCoverRaster(test::testDataPath("landcover/nlcd.tif"));
    if (!raster)
        qFatal("%s", raster.error().c_str());
    return std::move(raster.value());
}

bool writeText(const QString& path, const QByteArray& text) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(text) == text.size();
}

// A GeoJSON FeatureCollection of one rectangle; crs names the CRS of its coordinates (empty: none given,
// which GeoJSON readers take as WGS84 longitude, latitude).
QByteArray rectangleJson(double west, double south, double east, double north, const QString& crs) {
    const QString ring = QStringLiteral("[[%1,%2],[%3,%2],[%3,%4],[%1,%4],[%1,%2]]")
                             .arg(west, 0, 'f', 6)
                             .arg(south, 0, 'f', 6)
                             .arg(east, 0, 'f', 6)
                             .arg(north, 0, 'f', 6);
    const QString crsMember =
        crs.isEmpty()
            ? QString()
            : QStringLiteral("\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"%1\"}},").arg(crs);
    return QStringLiteral(
               "{\"type\":\"FeatureCollection\",%1\"features\":[{\"type\":\"Feature\",\"properties\":{},"
               "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[%2]}}]}")
        .arg(crsMember, ring)
        .toUtf8();
}

std::int64_t insidePixels(const LoadedRaster& raster) {
    std::int64_t inside = 0;
    for (const auto& [value, count] : raster.classPixelCounts)
        inside += count;
    return inside;
}

// Whether the pixel whose centre is nearest to (x, y) is inside the task area.
bool insideAt(const LoadedRaster& raster, double x, double y) {
    const ClassGrid& grid = raster.grid;
    const int column = static_cast<int>((x - grid.originX) / grid.pixelWidth);
    const int row = static_cast<int>((grid.originY - y) / grid.pixelHeight);
    return !grid.isOutside(column, row);
}

// Why the pixel at (x, y) is left out (ClassGrid's flags), 0 inside.
std::uint8_t flagAt(const LoadedRaster& raster, double x, double y) {
    const ClassGrid& grid = raster.grid;
    const int column = static_cast<int>((x - grid.originX) / grid.pixelWidth);
    const int row = static_cast<int>((grid.originY - y) / grid.pixelHeight);
    return grid.outside[grid.index(column, row)];
}

} // namespace

class AreaOfInterestTest : public QObject {
    Q_OBJECT

  private slots:
    void includeKeepsOnlyThePolygonAndExcludeCutsAHole() {
        QTemporaryDir folder;
        const QString area = folder.filePath("area.geojson");
        const QString noGo = folder.filePath("no-go.geojson");
        QVERIFY(
            writeText(area, rectangleJson(305000, 4130000, 325000, 4150000, "urn:ogc:def:crs:EPSG::26912")));
        QVERIFY(
            writeText(noGo, rectangleJson(310000, 4135000, 315000, 4140000, "urn:ogc:def:crs:EPSG::26912")));
        LoadedRaster raster = zion();
        const double pixelArea = raster.grid.pixelWidth * raster.grid.pixelHeight;
        QVERIFY(applyAreaOfInterest(raster, area.toStdString(), noGo.toStdString()).ok());
        const double area_m2 = static_cast<double>(insidePixels(raster)) * pixelArea;
        const double expected = 20000.0 * 20000.0 - 5000.0 * 5000.0; // the raster covers the whole rectangle
        QVERIFY2(std::abs(area_m2 - expected) / expected < 0.01, qPrintable(QString::number(area_m2)));
        QVERIFY(insideAt(raster, 306000, 4131000));
        QVERIFY(!insideAt(raster, 304000, 4131000)); // west of the area
        QVERIFY(!insideAt(raster, 312500, 4137500)); // in the no-go zone
        // Each is flagged apart, so that messages say which.
        QCOMPARE(flagAt(raster, 304000, 4131000), ClassGrid::outsideArea);
        QCOMPARE(flagAt(raster, 312500, 4137500), ClassGrid::inNoGoZone);
        QVERIFY(insideAt(raster, 316000, 4137500));
        QVERIFY(raster.notes.back().find("area of interest: planning on ") != std::string::npos);
        std::int64_t outsideFlags = 0;
        for (const std::uint8_t flag : raster.grid.outside)
            outsideFlags += flag != 0;
        QCOMPARE(outsideFlags + insidePixels(raster), static_cast<std::int64_t>(raster.grid.values.size()));
        // The polygons themselves are kept for drawing, corner for corner in the planning frame.
        QCOMPARE(raster.area.include.size(), std::size_t{1});
        QCOMPARE(raster.area.exclude.size(), std::size_t{1});
        const std::vector<MapPoint> areaRing{
            {305000, 4130000}, {325000, 4130000}, {325000, 4150000}, {305000, 4150000}, {305000, 4130000}};
        QCOMPARE(raster.area.include.front().size(), std::size_t{1}); // one ring, no hole
        const AreaOutline::Ring& drawn = raster.area.include.front().front();
        QCOMPARE(drawn.size(), areaRing.size());
        for (std::size_t corner = 0; corner < areaRing.size(); ++corner) {
            QCOMPARE(drawn[corner].x, areaRing[corner].x);
            QCOMPARE(drawn[corner].y, areaRing[corner].y);
        }
        QCOMPARE(raster.area.exclude.front().front()[2].x, 315000.0);
        QCOMPARE(raster.area.exclude.front().front()[2].y, 4140000.0);
    }

    // An area drawn partly off the raster is cut to it, and a warning says how much of it was left out.
    void anAreaPartlyOffTheRasterSaysHowMuchIsLeftOut() {
        QTemporaryDir folder;
        const QString area = folder.filePath("area.geojson");
        LoadedRaster raster = zion();
        // 10 km x 5 km whose western half lies west of the raster's edge.
        const double west = raster.grid.originX - 5000.0;
        QVERIFY(writeText(
            area, rectangleJson(west, 4130000, west + 10000.0, 4135000, "urn:ogc:def:crs:EPSG::26912")));
        QVERIFY(applyAreaOfInterest(raster, area.toStdString(), {}).ok());
        const std::string& warning = raster.warnings.back();
        // The part on the raster is counted in whole pixels (50.1 km2 here).
        QVERIFY2(warning.starts_with("area of interest: of the 50") &&
                     warning.find(" km2 in area.geojson, 25 km2 lies off the raster and is left out (") !=
                         std::string::npos,
                 warning.c_str());
        // A polygon that crosses itself (a bow tie over the edge): its western triangle, 12.5 km2, is off.
        LoadedRaster bowTie = zion();
        const QString ring =
            QStringLiteral("[[%1,4130000],[%2,4135000],[%2,4130000],[%1,4135000],[%1,4130000]]")
                .arg(west, 0, 'f', 3)
                .arg(west + 10000.0, 0, 'f', 3);
        QVERIFY(writeText(area, QStringLiteral("{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\","
                                               "\"properties\":{\"name\":\"urn:ogc:def:crs:EPSG::26912\"}},"
                                               "\"features\":[{\"type\":\"Feature\",\"properties\":{},"
                                               "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[%1]}}]}")
                                    .arg(ring)
                                    .toUtf8()));
        QVERIFY(applyAreaOfInterest(bowTie, area.toStdString(), {}).ok());
        QVERIFY2(bowTie.warnings.back().find(", 12.5 km2 lies off the raster and is left out") !=
                     std::string::npos,
                 bowTie.warnings.back().c_str());
        // Over the raster's nodata (here a strip 2 km wide made so): left out too, and said.
        LoadedRaster withNodata = zion();
        withNodata.grid.outside.assign(withNodata.grid.values.size(), 0);
        for (int row = 0; row < withNodata.grid.rows; ++row)
            for (int column = 0; column < withNodata.grid.columns; ++column) {
                const double x = withNodata.grid.originX + (column + 0.5) * withNodata.grid.pixelWidth;
                if (x >= 312000.0 && x < 314000.0)
                    withNodata.grid.outside[withNodata.grid.index(column, row)] = ClassGrid::outsideNodata;
            }
        QVERIFY(
            writeText(area, rectangleJson(310000, 4130000, 320000, 4135000, "urn:ogc:def:crs:EPSG::26912")));
        QVERIFY(applyAreaOfInterest(withNodata, area.toStdString(), {}).ok());
        const QString nodata = QString::fromStdString(withNodata.warnings.back());
        const QRegularExpression said(
            QStringLiteral("^area of interest: of the 50(\\.[0-9])? km2 in area.geojson, "
                           "([0-9.]+) km2 lies over the raster's nodata \\(no "
                           "land cover\\) and is left out$"));
        const QRegularExpressionMatch match = said.match(nodata);
        QVERIFY2(match.hasMatch(), qPrintable(nodata));
        QVERIFY2(std::abs(match.captured(2).toDouble() - 10.0) < 0.2, qPrintable(nodata));
        // Wholly on the raster: no such warning.
        LoadedRaster whole = zion();
        QVERIFY(
            writeText(area, rectangleJson(310000, 4130000, 320000, 4135000, "urn:ogc:def:crs:EPSG::26912")));
        QVERIFY(applyAreaOfInterest(whole, area.toStdString(), {}).ok());
        for (const std::string& each : whole.warnings)
            QVERIFY2(each.find("off the raster") == std::string::npos, each.c_str());
    }

    // Every polygon of a file counts, and drawn polygons written by writeAreaPolygons come back: two no-go
    // zones, the second added to a file holding the first.
    void everyPolygonOfAFileCounts() {
        QTemporaryDir folder;
        LoadedRaster raster = zion();
        const double pixelArea = raster.grid.pixelWidth * raster.grid.pixelHeight;
        const std::int64_t whole = insidePixels(raster);
        const std::string first = folder.filePath("first.geojson").toStdString();
        const std::string both = folder.filePath("both.geojson").toStdString();
        const std::vector<MapPoint> west{
            {310000, 4135000}, {315000, 4135000}, {315000, 4140000}, {310000, 4140000}};
        const std::vector<MapPoint> east{
            {318000, 4143000}, {323000, 4143000}, {323000, 4148000}, {318000, 4148000}};
        QVERIFY(writeAreaPolygons(first, {west}, raster).ok());
        QVERIFY(writeAreaPolygons(both, {east}, raster, first).ok());
        QVERIFY(applyAreaOfInterest(raster, std::string(), both).ok());
        const double cut = static_cast<double>(whole - insidePixels(raster)) * pixelArea;
        QVERIFY2(std::abs(cut - 5e7) / 5e7 < 0.01, qPrintable(QString::number(cut)));
        QVERIFY(!insideAt(raster, 312500, 4137500));
        QVERIFY(!insideAt(raster, 320500, 4145500));
        QVERIFY(insideAt(raster, 316500, 4141500));
        QVERIFY(raster.notes.back().starts_with("no-go zones: planning on "));
        QVERIFY(raster.warnings.empty());
    }

    // No-go zones that miss the raster (in another place, or in another CRS than the file names) leave
    // nothing out, and a warning says so; an area of interest that misses it is an error.
    void noGoZonesOffTheRasterAreAWarning() {
        QTemporaryDir folder;
        const QString paris = folder.filePath("paris.geojson");
        QVERIFY(writeText(paris, rectangleJson(2.2, 48.8, 2.4, 48.9, QString())));
        LoadedRaster raster = zion();
        const std::int64_t whole = insidePixels(raster);
        QVERIFY(applyAreaOfInterest(raster, std::string(), paris.toStdString()).ok());
        QCOMPARE(insidePixels(raster), whole);
        QCOMPARE(raster.warnings.size(), std::size_t{1});
        QVERIFY2(raster.warnings.front().starts_with(
                     "no-go zones: no polygon of paris.geojson lies on the raster"),
                 raster.warnings.front().c_str());
        LoadedRaster again = zion();
        QVERIFY(!applyAreaOfInterest(again, paris.toStdString(), {}).ok());
    }

    // A star drawn in one stroke crosses itself: GDAL alone would leave out its middle, which its outline
    // goes round twice. It is mended to all it encloses, and a warning says so.
    void aPolygonCrossingItselfCoversAllItEncloses() {
        QTemporaryDir folder;
        const QString star = folder.filePath("star.geojson");
        QString ring;
        for (int point = 0; point <= 5; ++point) { // every second corner of a pentagon, radius 8 km
            const double angle = (90.0 + 144.0 * point) * 3.14159265358979 / 180.0;
            ring += QStringLiteral("%1[%2,%3]")
                        .arg(point == 0 ? "" : ",")
                        .arg(315000.0 + 8000.0 * std::cos(angle), 0, 'f', 1)
                        .arg(4135000.0 + 8000.0 * std::sin(angle), 0, 'f', 1);
        }
        QVERIFY(
            writeText(star, QStringLiteral("{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\","
                                           "\"properties\":{\"name\":\"urn:ogc:def:crs:EPSG::26912\"}},"
                                           "\"features\":[{\"type\":\"Feature\",\"properties\":{},"
                                           "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[%1]]}}]}")
                                .arg(ring)
                                .toUtf8()));
        LoadedRaster raster = zion();
        QVERIFY(applyAreaOfInterest(raster, star.toStdString(), {}).ok());
        QVERIFY(insideAt(raster, 315000, 4135000));        // the middle
        QVERIFY(insideAt(raster, 315000, 4135000 + 7000)); // a point
        QVERIFY(!insideAt(raster, 315000 + 7000, 4135000 + 7000));
        // A pentagram of radius R covers 1.1226 R^2 with its middle.
        const double area =
            static_cast<double>(insidePixels(raster)) * raster.grid.pixelWidth * raster.grid.pixelHeight;
        QVERIFY2(std::abs(area - 1.1226 * 64e6) / (1.1226 * 64e6) < 0.03, qPrintable(QString::number(area)));
        QCOMPARE(raster.warnings.size(), std::size_t{1});
        QVERIFY2(raster.warnings.front().starts_with("area of interest: 1 polygon of star.geojson is not a "
                                                     "simple polygon (its outline crosses itself)"),
                 raster.warnings.front().c_str());
        // Its edge as drawn is the star's outline, not the crossing stroke.
        QCOMPARE(raster.area.include.size(), std::size_t{1});
        QCOMPARE(raster.area.include.front().size(), std::size_t{1});
        QCOMPARE(raster.area.include.front().front().size(), std::size_t{11});
    }

    // The same rectangle given in longitude and latitude is taken to the raster's CRS.
    void polygonsInAnotherCrsAreReprojected() {
        QTemporaryDir folder;
        const QString lonLat = folder.filePath("area.geojson");
        // About 305-325 km east, 4130-4150 km north in UTM 12N.
        QVERIFY(writeText(lonLat, rectangleJson(-113.2, 37.32, -113.0, 37.48, QString())));
        LoadedRaster raster = zion();
        QVERIFY(applyAreaOfInterest(raster, lonLat.toStdString(), {}).ok());
        QVERIFY(insideAt(raster, 315000, 4140000));
        QVERIFY(!insideAt(raster, 330000, 4140000));
        QVERIFY(!insideAt(raster, 315000, 4120000));
        // Its edge is kept in the raster's CRS too (metres, not degrees), and no no-go zone was given.
        QCOMPARE(raster.area.include.size(), std::size_t{1});
        QVERIFY(raster.area.exclude.empty());
        for (const MapPoint& corner : raster.area.include.front().front()) {
            QVERIFY2(corner.x > 300000 && corner.x < 330000, qPrintable(QString::number(corner.x)));
            QVERIFY2(corner.y > 4125000 && corner.y < 4155000, qPrintable(QString::number(corner.y)));
        }
    }

    void badAreaFilesAreRefusedNamingTheFile_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("fragment");
        QTest::newRow("not a vector file") << QByteArray("this is not GeoJSON") << "cannot be opened";
        QTest::newRow("points only") << QByteArray(
                                            R"({"type":"FeatureCollection","features":[{"type":"Feature",
            "properties":{},"geometry":{"type":"Point","coordinates":[-113.1,37.4]}}]})")
                                     << "no polygons";
        QTest::newRow("far from the map")
            << rectangleJson(10.0, 45.0, 10.1, 45.1, QString()) << "leaves no pixel";
        // Metres without a "crs" member are read as longitude and latitude: said so, with the fix.
        QTest::newRow("metres read as degrees")
            << rectangleJson(305000, 4130000, 325000, 4150000, QString())
            << "has coordinates such as (305000, 4130000), which are not longitude and latitude, yet the "
               "file's CRS is WGS 84 (a GeoJSON file without a \"crs\" member is read as WGS 84): give the "
               "file its CRS (ogr2ogr -a_srs EPSG:26912";
    }

    void badAreaFilesAreRefusedNamingTheFile() {
        QFETCH(QByteArray, content);
        QFETCH(QString, fragment);
        QTemporaryDir folder;
        const QString path = folder.filePath("area.geojson");
        QVERIFY(writeText(path, content));
        LoadedRaster raster = zion();
        const Status status = applyAreaOfInterest(raster, path.toStdString(), {});
        QVERIFY(!status.ok());
        QVERIFY2(status.error().find("area.geojson") != std::string::npos, status.error().c_str());
        QVERIFY2(status.error().find(fragment.toStdString()) != std::string::npos, status.error().c_str());
        const Status missing = applyAreaOfInterest(raster, folder.filePath("absent.gpkg").toStdString(), {});
        QVERIFY(!missing.ok() && missing.error().find("absent.gpkg") != std::string::npos);
    }

    // A mission names its area files relative to itself; they round-trip and apply when it loads.
    void missionsCarryTheirArea() {
        QTemporaryDir folder;
        QVERIFY(writeText(folder.filePath("area.geojson"),
                          rectangleJson(305000, 4130000, 325000, 4150000, "urn:ogc:def:crs:EPSG::26912")));
        Mission mission;
        mission.rasterPath = test::testDataPath("landcover/nlcd.tif");
        mission.area.includePath = "area.geojson";
        mission.robots.push_back({"one", {315000, 4140000}, {}});
        const std::string path = folder.filePath("mission.json").toStdString();
        QVERIFY(saveMission(mission, path).ok());
        auto loaded = loadMission(path);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.value().area, mission.area);
        auto raster = loadMissionRaster(loaded.value(), path);
        QVERIFY2(raster.ok(), raster.ok() ? "" : raster.error().c_str());
        QVERIFY(!insideAt(raster.value(), 304000, 4140000));
        QVERIFY(insideAt(raster.value(), 315000, 4140000));
    }
};

QTEST_GUILESS_MAIN(AreaOfInterestTest)
#include "test_area_of_interest.moc"
