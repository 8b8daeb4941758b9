// Plan exports read back with OGR (and the JSON ones with QJsonDocument): kinds, counts, properties,
// coordinates within 1e-7 degrees of the plan, CRS of the GeoPackage.

#include "PlanFixture.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/model/AreaOutline.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/RobotColours.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/outlines/OutlineTracer.hpp"
#include "io/AutopilotMission.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/GeoJsonText.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <gdal_priv.h>
#include <map>
#include <ogrsf_frmts.h>
#include <random>

using namespace mcpp;
using namespace mcpp::io;

namespace {

struct DatasetCloser {
    void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};
using Dataset = std::unique_ptr<GDALDataset, DatasetCloser>;

Dataset openVector(const std::string& path) {
    GDALAllRegister();
    return Dataset(GDALDataset::FromHandle(
        GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
}

QJsonObject readJson(const std::string& path) {
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

// The fixture plan with the first robot's path a lawnmower of 12 rows of 8 points, 10 m apart.
Plan lawnmowerPlan() {
    Plan plan = test::makeFixturePlan();
    CoveragePath& lawnmower = plan.paths[0];
    lawnmower.waypoints.clear();
    for (int row = 0; row < 12; ++row)
        for (int step = 0; step < 8; ++step)
            lawnmower.waypoints.push_back(test::makeWaypoint(
                301902.5 + 10.0 * (row % 2 == 0 ? step : 7 - step), 4154077.5 - 10.0 * row, 0, 0.5));
    return plan;
}

// A CSV file's rows by its header's column names; no field here is quoted.
std::vector<std::map<std::string, std::string>> readCsvRows(const std::string& path) {
    std::ifstream input(path);
    const auto split = [](const std::string& line) {
        std::vector<std::string> fields;
        std::size_t from = 0;
        for (std::size_t comma = line.find(','); comma != std::string::npos; comma = line.find(',', from)) {
            fields.push_back(line.substr(from, comma - from));
            from = comma + 1;
        }
        fields.push_back(line.substr(from));
        return fields;
    };
    std::string line;
    std::getline(input, line);
    const std::vector<std::string> header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(input, line)) {
        const std::vector<std::string> fields = split(line);
        std::map<std::string, std::string>& row = rows.emplace_back();
        for (std::size_t column = 0; column < header.size() && column < fields.size(); ++column)
            row[header[column]] = fields[column];
    }
    return rows;
}

GeoReference utm12() {
    return GeoReference::fromDefinition("EPSG:26912").value();
}

// Largest distance in degrees between a line's vertices and the given waypoints taken to WGS84.
double lineError(const OGRLineString& line, const std::vector<Waypoint>& points,
                 const GeoReference& reference) {
    if (static_cast<std::size_t>(line.getNumPoints()) != points.size())
        return 1.0;
    double worst = 0.0;
    for (int i = 0; i < line.getNumPoints(); ++i) {
        const Waypoint& waypoint = points[static_cast<std::size_t>(i)];
        const LonLat expected = reference.toWgs84({waypoint.x, waypoint.y}).value();
        worst = std::max(
            {worst, std::abs(line.getX(i) - expected.longitude), std::abs(line.getY(i) - expected.latitude)});
    }
    return worst;
}

// Area in square metres of a WGS84 geometry, measured back in the plan's CRS.
double areaInCrs(const OGRGeometry& geometry, const GeoReference& reference) {
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference crs;
    crs.SetFromUserInput(reference.wkt().c_str());
    crs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRGeometry> copy(geometry.clone());
    std::unique_ptr<OGRCoordinateTransformation> back(OGRCreateCoordinateTransformation(&wgs84, &crs));
    copy->transform(back.get());
    const auto type = wkbFlatten(copy->getGeometryType());
    if (type == wkbPolygon)
        return copy->toPolygon()->get_Area();
    if (type == wkbMultiPolygon)
        return copy->toMultiPolygon()->get_Area();
    return -1.0;
}

// The largest change of longitude between consecutive vertices of any line or ring of a geometry.
double longestLongitudeStep(const OGRGeometry& geometry) {
    switch (wkbFlatten(geometry.getGeometryType())) {
    case wkbLineString:
    case wkbLinearRing: {
        const OGRSimpleCurve& curve = *geometry.toSimpleCurve();
        double longest = 0.0;
        for (int i = 1; i < curve.getNumPoints(); ++i)
            longest = std::max(longest, std::abs(curve.getX(i) - curve.getX(i - 1)));
        return longest;
    }
    case wkbPolygon: {
        double longest = 0.0;
        for (const OGRLinearRing* ring : *geometry.toPolygon())
            longest = std::max(longest, longestLongitudeStep(*ring));
        return longest;
    }
    case wkbMultiPolygon:
    case wkbMultiLineString:
    case wkbGeometryCollection: {
        double longest = 0.0;
        for (const OGRGeometry* part : *geometry.toGeometryCollection())
            longest = std::max(longest, longestLongitudeStep(*part));
        return longest;
    }
    default:
        return 0.0;
    }
}

} // namespace

class PlanExportTest : public QObject {
    Q_OBJECT

  private:
    Plan plan_ = test::makeFixturePlan();
    GeoReference reference_ = utm12();
    ClassTable classes_;
    QTemporaryDir folder_;

    // The first robot has a name, the second none (it is then "Robot 2").
    // The GeoJSON written with dense paths holds every waypoint of the whole plan's paths (`whole`, or the
    // plan itself), point for point.
    void checkDensePaths(const std::string& path, const Plan* whole = nullptr) {
        ExportSettings dense;
        dense.densePaths = true;
        QVERIFY(writePlanGeoJson(context(dense), path).ok());
        const Plan& reference = whole != nullptr ? *whole : plan_;
        Dataset dataset = openVector(path);
        int paths = 0;
        for (auto& feature : *dataset->GetLayer(0)) {
            if (std::string(feature->GetFieldAsString("kind")) != "path")
                continue;
            const CoveragePath& coverage =
                reference.paths[static_cast<std::size_t>(feature->GetFieldAsInteger("robot") - 1)];
            const OGRLineString& line = *feature->GetGeometryRef()->toLineString();
            QCOMPARE(static_cast<std::size_t>(line.getNumPoints()), coverage.waypoints.size());
            QVERIFY(lineError(line, coverage.waypoints, reference_) < 1e-7);
            ++paths;
        }
        QCOMPARE(paths, 2);
    }

    ExportContext context(ExportSettings settings = {}) const {
        ExportContext exportContext{plan_, reference_, classes_, settings};
        exportContext.robotNames = {"Scout", ""};
        return exportContext;
    }
    static std::string expectedName(int robot) { return robot == 0 ? "Scout" : "Robot 2"; }
    std::string file(const char* name) const { return folder_.filePath(name).toStdString(); }
    std::string writtenGeoPackage(const char* name) const {
        const std::string path = file(name);
        const Status written = writePlanGeoPackage(context(), path);
        return written.ok() ? path : std::string();
    }

  private slots:
    void geoJsonReadsBackWithOgr() {
        const std::string path = file("plan.geojson");
        Status written = writePlanGeoJson(context(), path);
        QVERIFY2(written.ok(), written.error().c_str());
        Dataset dataset = openVector(path);
        QVERIFY(dataset != nullptr);
        QCOMPARE(dataset->GetLayerCount(), 1);
        OGRLayer* layer = dataset->GetLayer(0);
        std::map<std::string, int> kinds;
        for (auto& feature : *layer) {
            const std::string kind = feature->GetFieldAsString("kind");
            ++kinds[kind];
            const OGRGeometry* geometry = feature->GetGeometryRef();
            QVERIFY(geometry != nullptr && geometry->IsValid());
            // Files number robots from 1; the plan indexes them from 0.
            const int robot = feature->GetFieldAsInteger("robot") - 1;
            if (kind != "unreachable")
                QCOMPARE(std::string(feature->GetFieldAsString("robot_name")), expectedName(robot));
            if (kind == "region") {
                const auto& metrics = plan_.metrics.robots[static_cast<std::size_t>(robot)];
                QCOMPARE(feature->GetFieldAsDouble("area_m2"), metrics.areaSquareMetres);
                QCOMPARE(feature->GetFieldAsInteger("cells"), metrics.cells);
                QCOMPARE(feature->GetFieldAsDouble("cost_s"),
                         plan_.regions.costSeconds[static_cast<std::size_t>(robot)]);
                // What covering it takes, as its path says: a region reads in the robot's time, too.
                QCOMPARE(feature->GetFieldAsDouble("time_s"),
                         plan_.paths[static_cast<std::size_t>(robot)].timeSeconds);
                QVERIFY(std::abs(areaInCrs(*geometry, reference_) - metrics.areaSquareMetres) < 0.01);
            } else if (kind == "path") {
                const CoveragePath& coverage = plan_.paths[static_cast<std::size_t>(robot)];
                QCOMPARE(feature->GetFieldAsDouble("length_m"), coverage.lengthMetres);
                QCOMPARE(feature->GetFieldAsDouble("time_s"), coverage.timeSeconds);
                QCOMPARE(feature->GetFieldAsInteger("turns"), coverage.turns);
                QVERIFY(lineError(*geometry->toLineString(), turningPoints(coverage), reference_) < 1e-7);
            } else if (kind == "start") {
                const Waypoint& first = plan_.paths[static_cast<std::size_t>(robot)].waypoints.front();
                const LonLat expected = reference_.toWgs84({first.x, first.y}).value();
                QVERIFY(std::abs(geometry->toPoint()->getX() - expected.longitude) < 1e-7);
                QVERIFY(std::abs(geometry->toPoint()->getY() - expected.latitude) < 1e-7);
            } else if (kind == "unreachable") {
                QCOMPARE(feature->GetFieldAsDouble("area_m2"), 100.0);
                QVERIFY(std::abs(areaInCrs(*geometry, reference_) - 100.0) < 0.01);
            }
        }
        QCOMPARE(kinds["region"], 2);
        QCOMPARE(kinds["path"], 2);
        QCOMPARE(kinds["start"], 2);
        QCOMPARE(kinds["unreachable"], 1);

        // The same file as plain JSON: an RFC 7946 FeatureCollection, counter-clockwise outer rings.
        const QJsonObject root = readJson(path);
        QCOMPARE(root["type"].toString(), QString("FeatureCollection"));
        QVERIFY(!root.contains("crs"));
        const QJsonArray features = root["features"].toArray();
        QCOMPARE(features.size(), 7);
        for (const QJsonValue& value : features) {
            const QJsonObject feature = value.toObject();
            QVERIFY(feature["properties"].toObject().contains("kind"));
            if (feature["properties"].toObject()["kind"].toString() != "region")
                continue;
            const QJsonObject geometry = feature["geometry"].toObject();
            const QString type = geometry["type"].toString();
            QVERIFY(type == "Polygon" || type == "MultiPolygon");
            const QJsonArray polygon = type == "Polygon" ? geometry["coordinates"].toArray()
                                                         : geometry["coordinates"].toArray()[0].toArray();
            const QJsonArray ring = polygon[0].toArray();
            double twiceArea = 0.0;
            for (qsizetype i = 0; i + 1 < ring.size(); ++i) {
                const QJsonArray a = ring[i].toArray(), b = ring[i + 1].toArray();
                twiceArea += a[0].toDouble() * b[1].toDouble() - b[0].toDouble() * a[1].toDouble();
            }
            QVERIFY(twiceArea > 0.0);
        }
    }

    // Readers guess a GeoJSON field's type from its values: reals are written with a decimal point even
    // when whole (the unreachable area is 100 m2), so they read back as reals, and counts as integers.
    void geoJsonFieldsKeepTheirTypes() {
        const std::string path = file("types.geojson");
        QVERIFY(writePlanGeoJson(context(), path).ok());
        Dataset dataset = openVector(path);
        OGRFeatureDefn* definition = dataset->GetLayer(0)->GetLayerDefn();
        for (const char* name : {"cost_s", "area_m2", "length_m", "time_s"})
            QCOMPARE(definition->GetFieldDefn(definition->GetFieldIndex(name))->GetType(), OFTReal);
        for (const char* name : {"robot", "cells", "turns"})
            QCOMPARE(definition->GetFieldDefn(definition->GetFieldIndex(name))->GetType(), OFTInteger);
    }

    // A plan across the antimeridian (UTM zone 60 at 60 degrees north, 180 degrees through robot 1's region
    // and path), in GeoJSON and KML: no feature may run the long way round the globe, from +180 to -180.
    void featuresAreCutAtTheAntimeridian_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("GeoJSON") << "antimeridian.geojson";
        QTest::newRow("KML") << "antimeridian.kml";
    }
    void featuresAreCutAtTheAntimeridian() {
        QFETCH(QString, name);
        const GeoReference zone60 = GeoReference::fromDefinition("EPSG:32660").value();
        const MapPoint antimeridian = zone60.fromWgs84({180.0, 60.0}).value();
        const Plan plan = test::makeFixturePlan(antimeridian.x - 15.0, antimeridian.y + 10.0);
        ExportContext across{plan, zone60, classes_, {}};
        const std::string path = folder_.filePath(name).toStdString();
        const Status written =
            name.endsWith(".kml") ? writePlanKml(across, path) : writePlanGeoJson(across, path);
        QVERIFY2(written.ok(), written.error().c_str());
        Dataset dataset = openVector(path);
        QVERIFY(dataset != nullptr);
        int features = 0;
        for (int layer = 0; layer < dataset->GetLayerCount(); ++layer) {
            for (auto& feature : *dataset->GetLayer(layer)) {
                const OGRGeometry* geometry = feature->GetGeometryRef();
                QVERIFY(geometry != nullptr);
                QVERIFY2(longestLongitudeStep(*geometry) < 1.0, dataset->GetLayer(layer)->GetName());
                OGREnvelope envelope;
                geometry->getEnvelope(&envelope);
                QVERIFY(envelope.MinX >= -180.0 && envelope.MaxX <= 180.0);
                ++features;
            }
        }
        QCOMPARE(features, 7);
    }

    void regionOfTwoCellsIsOnePolygon() {
        const std::string path = file("dissolve.geojson");
        QVERIFY(writePlanGeoJson(context(), path).ok());
        Dataset dataset = openVector(path);
        for (auto& feature : *dataset->GetLayer(0)) {
            if (std::string(feature->GetFieldAsString("kind")) != "region" ||
                feature->GetFieldAsInteger("robot") != 1)
                continue;
            // NW + NE dissolved into one 20 x 10 m rectangle: one polygon, no hole, no inner edge.
            const OGRGeometry* geometry = feature->GetGeometryRef();
            QCOMPARE(wkbFlatten(geometry->getGeometryType()), wkbPolygon);
            QCOMPARE(geometry->toPolygon()->getNumInteriorRings(), 0);
            QVERIFY(geometry->toPolygon()->getExteriorRing()->getNumPoints() <= 7);
        }
    }

    void geoPackageIsInTheRasterCrs() {
        const std::string path = file("plan.gpkg");
        ExportSettings everything;
        everything.densePaths = true;
        everything.cellPolygons = true;
        Status written = writePlanGeoPackage(context(everything), path);
        QVERIFY2(written.ok(), written.error().c_str());
        Dataset dataset = openVector(path);
        QVERIFY(dataset != nullptr);
        const std::map<std::string, GIntBig> counts{
            {"regions", 2}, {"paths", 2}, {"starts", 2}, {"cells", 4}, {"unreachable", 1}};
        for (const auto& [name, count] : counts) {
            OGRLayer* layer = dataset->GetLayerByName(name.c_str());
            QVERIFY2(layer != nullptr, name.c_str());
            QCOMPARE(layer->GetFeatureCount(), count);
            QVERIFY(layer->GetSpatialRef() != nullptr);
            QCOMPARE(std::string(layer->GetSpatialRef()->GetAuthorityCode(nullptr)), std::string("26912"));
        }
        OGRLayer* paths = dataset->GetLayerByName("paths");
        for (auto& feature : *paths) {
            const CoveragePath& coverage =
                plan_.paths[static_cast<std::size_t>(feature->GetFieldAsInteger("robot") - 1)];
            const OGRLineString* line = feature->GetGeometryRef()->toLineString();
            QCOMPARE(static_cast<std::size_t>(line->getNumPoints()), coverage.waypoints.size());
            for (int i = 0; i < line->getNumPoints(); ++i) {
                QCOMPARE(line->getX(i), coverage.waypoints[static_cast<std::size_t>(i)].x);
                QCOMPARE(line->getY(i), coverage.waypoints[static_cast<std::size_t>(i)].y);
            }
        }
        for (auto& feature : *dataset->GetLayerByName("cells")) {
            const int index = feature->GetFieldAsInteger("cell");
            const Cell& cell = plan_.cells.cell(index);
            QCOMPARE(feature->GetFieldAsInteger("level"), cell.level);
            QCOMPARE(feature->GetFieldAsInteger("class"), cell.classValue);
            QCOMPARE(feature->GetFieldAsDouble("fov"), cell.size / 2);
            QCOMPARE(feature->GetFieldAsDouble("speed"), cell.speedMetresPerSecond);
            const int owner = plan_.regions.robotOfCell[static_cast<std::size_t>(index)];
            if (owner >= 0)
                QCOMPARE(feature->GetFieldAsInteger("robot"), owner + 1);
            else
                QVERIFY(!feature->IsFieldSetAndNotNull(feature->GetFieldIndex("robot")));
            QCOMPARE(feature->GetGeometryRef()->toPolygon()->get_Area(), cell.size * cell.size);
        }
        // Writing again replaces the file; by default without cells and with turning points only.
        QVERIFY(writePlanGeoPackage(context(), path).ok());
        Dataset small = openVector(path);
        QVERIFY(small->GetLayerByName("cells") == nullptr);
        for (auto& feature : *small->GetLayerByName("paths")) {
            const CoveragePath& coverage =
                plan_.paths[static_cast<std::size_t>(feature->GetFieldAsInteger("robot") - 1)];
            const OGRLineString* line = feature->GetGeometryRef()->toLineString();
            QCOMPARE(static_cast<std::size_t>(line->getNumPoints()), turningPoints(coverage).size());
            QVERIFY(std::abs(line->get_Length() - coverage.lengthMetres) <= 1e-9 * coverage.lengthMetres);
        }
        for (auto& feature : *small->GetLayerByName("regions")) {
            const OGRGeometry* geometry = feature->GetGeometryRef();
            QVERIFY(geometry->IsValid());
            const double area = geometry->toMultiPolygon()->get_Area();
            QVERIFY(std::abs(area - feature->GetFieldAsDouble("area_m2")) <= 1e-6 * area);
            QCOMPARE(
                feature->GetFieldAsDouble("time_s"),
                plan_.paths[static_cast<std::size_t>(feature->GetFieldAsInteger("robot") - 1)].timeSeconds);
        }
    }

    // Above 2 000 parts KML leaves its missions folder out, which would slow Google Earth down, and says so,
    // naming the count and where the parts are.
    void kmlSaysWhenItLeavesTheMissionPartsOut() {
        Plan plan = test::makeFixturePlan();
        CoveragePath& zigzag = plan.paths[0];
        zigzag.waypoints.clear();
        for (int row = 0; row < 9000; ++row)
            for (int side = 0; side < 2; ++side)
                zigzag.waypoints.push_back(test::makeWaypoint(
                    301902.5 + 70.0 * (row % 2 == 0 ? side : 1 - side), 4154077.5 - 10.0 * row, 0, 0.5));
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.cruiseSpeedMetresPerSecond = 2.0;
        drone.maxWaypoints = 12;
        ExportContext exportContext{plan, reference_, classes_, ExportSettings{}};
        exportContext.vehicles = {drone, VehicleSettings{}};
        std::size_t parts = 0;
        for (const CoveragePath& path : plan.paths)
            parts += autopilotMissionOf(exportContext, path.robot).parts.size();
        QVERIFY2(parts > kmlMostMissionParts, qPrintable(QString::number(parts)));
        const std::string kml = file("many.kml");
        QVERIFY(writePlanKml(exportContext, kml).ok());
        Dataset kmlFile = openVector(kml);
        QVERIFY(kmlFile->GetLayerByName("paths") != nullptr);
        QVERIFY(kmlFile->GetLayerByName("missions") == nullptr);
        QCOMPARE(kmlMissionPartsNote(exportContext, kml),
                 "many.kml leaves out the " + std::to_string(parts) +
                     " waypoint file parts (more than 2000 take long to write and to open): a GeoPackage "
                     "export holds them all in its missions layer");
    }

    // The missions layer holds every waypoint file part as its line, point for point, the parts of a robot
    // joining up, with its items and time and whether it fits the vehicle's flight time (a drone on a
    // lawnmower whose far rows lie beyond one flight's reach; a rover without a flight time beside it).
    void missionsLayerHoldsEachWaypointFilePart() {
        Plan plan = lawnmowerPlan();
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.cruiseSpeedMetresPerSecond = 2.0;
        drone.maxWaypoints = 12;
        drone.flightTimeSeconds = 120.0; // 12 s up, 20 s down: 88 m out and back at 2 m/s
        ExportContext exportContext{plan, reference_, classes_, ExportSettings{}};
        exportContext.vehicles = {drone, VehicleSettings{}};
        const std::string path = file("missions.gpkg");
        const Status written = writePlanGeoPackage(exportContext, path);
        QVERIFY2(written.ok(), written.error().c_str());
        Dataset dataset = openVector(path);
        OGRLayer* missions = dataset->GetLayerByName("missions");
        QVERIFY(missions != nullptr);
        QCOMPARE(std::string(missions->GetSpatialRef()->GetAuthorityCode(nullptr)), std::string("26912"));
        // A true-or-false field, as QGIS shows it.
        const OGRFeatureDefn* definition = missions->GetLayerDefn();
        QCOMPARE(definition->GetFieldDefn(definition->GetFieldIndex("fits_flight"))->GetSubType(),
                 OFSTBoolean);
        std::size_t features = 0;
        int fitting = 0;
        int tooLong = 0;
        for (auto& feature : *missions) {
            ++features;
            const int robot = feature->GetFieldAsInteger("robot") - 1;
            const AutopilotMission& mission = autopilotMissionOf(exportContext, robot);
            const auto part = static_cast<std::size_t>(feature->GetFieldAsInteger("part") - 1);
            QVERIFY(part < mission.parts.size());
            QCOMPARE(static_cast<std::size_t>(feature->GetFieldAsInteger("parts")), mission.parts.size());
            const MissionPart& piece = mission.parts[part];
            QCOMPARE(feature->GetFieldAsInteger("items"), piece.items);
            QCOMPARE(feature->GetFieldAsDouble("part_time_s"), piece.seconds);
            // The files batch mode writes: robot_1_part_2.plan and .waypoints (robot_1_part_02 of 12);
            // robot_2.plan when whole.
            std::string number = std::to_string(part + 1);
            number.insert(0, std::to_string(mission.parts.size()).size() - number.size(), '0');
            const std::string stem =
                "robot_" + std::to_string(robot + 1) + (mission.parts.size() > 1 ? "_part_" + number : "");
            QCOMPARE(std::string(feature->GetFieldAsString("file")), stem);
            const OGRLineString* line = feature->GetGeometryRef()->toLineString();
            QCOMPARE(static_cast<std::size_t>(line->getNumPoints()), piece.last - piece.first + 1);
            double farthest = 0.0;
            for (int i = 0; i < line->getNumPoints(); ++i) {
                const Waypoint& point = mission.points[piece.first + static_cast<std::size_t>(i)];
                QCOMPARE(line->getX(i), point.x);
                QCOMPARE(line->getY(i), point.y);
                farthest = std::max(farthest,
                                    std::hypot(point.x - mission.points[0].x, point.y - mission.points[0].y));
            }
            QCOMPARE(feature->GetFieldAsDouble("farthest_m"), farthest);
            if (part > 0) // each part begins where the one before it ended
                QCOMPARE(piece.first, mission.parts[part - 1].last);
            const int fits = feature->GetFieldIndex("fits_flight");
            if (robot == 1) {
                QVERIFY(!feature->IsFieldSetAndNotNull(fits));
                QVERIFY(!feature->IsFieldSetAndNotNull(feature->GetFieldIndex("flight_time_s")));
                continue;
            }
            QCOMPARE(feature->GetFieldAsDouble("flight_time_s"), 120.0);
            QCOMPARE(feature->GetFieldAsInteger(fits), piece.seconds <= 120.0 ? 1 : 0);
            (piece.seconds <= 120.0 ? fitting : tooLong) += 1;
        }
        QCOMPARE(features, autopilotMissionOf(exportContext, 0).parts.size() +
                               autopilotMissionOf(exportContext, 1).parts.size());
        // Both kinds of flight are there: near rows fit, far ones do not.
        QVERIFY2(fitting > 0 && tooLong > 0,
                 qPrintable(QStringLiteral("%1 fit, %2 do not").arg(fitting).arg(tooLong)));
        // KML holds the parts too once some mission is split, for Google Earth: in degrees, named by their
        // files, in the robot's colour.
        const std::string kml = file("missions.kml");
        QVERIFY(writePlanKml(exportContext, kml).ok());
        Dataset kmlFile = openVector(kml);
        OGRLayer* flights = kmlFile->GetLayerByName("missions");
        QVERIFY(flights != nullptr);
        const AutopilotMission& drone0 = autopilotMissionOf(exportContext, 0);
        std::size_t kmlParts = 0;
        for (auto& feature : *flights) { // the drone's parts first, in order
            QVERIFY(std::string(feature->GetStyleString()).find("PEN(c:#") == 0);
            if (kmlParts == drone0.parts.size())
                break;
            const MissionPart& piece = drone0.parts[kmlParts];
            std::string number = std::to_string(kmlParts + 1);
            number.insert(0, std::to_string(drone0.parts.size()).size() - number.size(), '0');
            QCOMPARE(std::string(feature->GetFieldAsString("name")), "robot_1_part_" + number);
            QCOMPARE(feature->GetFieldAsInteger("fits_flight"), piece.seconds <= 120.0 ? 1 : 0);
            const std::vector<Waypoint> points(
                drone0.points.begin() + static_cast<std::ptrdiff_t>(piece.first),
                drone0.points.begin() + static_cast<std::ptrdiff_t>(piece.last) + 1);
            QVERIFY(lineError(*feature->GetGeometryRef()->toLineString(), points, reference_) < 1e-7);
            ++kmlParts;
        }
        QCOMPARE(kmlParts, drone0.parts.size());
        QVERIFY(kmlMissionPartsNote(exportContext, kml).empty()); // all the parts are in it
        // report.csv counts the same flights: the drone's too long, its longest and all of them in one.
        const std::string csv = file("missions.csv");
        QVERIFY(writeReportCsv(exportContext, csv).ok());
        const std::vector<std::map<std::string, std::string>> rows = readCsvRows(csv);
        QCOMPARE(rows.size(), std::size_t{2});
        const AutopilotMission& flown = autopilotMissionOf(exportContext, 0);
        double total = 0.0;
        double longest = 0.0;
        for (const MissionPart& piece : flown.parts) {
            total += piece.seconds;
            longest = std::max(longest, piece.seconds);
        }
        QCOMPARE(rows[0].at("flight_time_s"), std::string("120"));
        QCOMPARE(rows[0].at("mission_parts_over_flight_time"), std::to_string(tooLong));
        QCOMPARE(std::stod(rows[0].at("mission_longest_part_s")), longest);
        QVERIFY(std::abs(std::stod(rows[0].at("mission_flights_s")) - total) <= 1e-9 * total);
        QVERIFY(longest > 120.0);
        // The rover without a flight time: none over.
        QCOMPARE(rows[1].at("flight_time_s"), std::string("0"));
        QCOMPARE(rows[1].at("mission_parts_over_flight_time"), std::string("0"));
    }

    // The summary's field time: the last robot done, its flights and turnarounds; a robot without a path
    // neither counts nor hides it.
    void fieldTimeNoteNamesTheLastRobotDone() {
        Plan plan = lawnmowerPlan();
        plan.paths[1].waypoints.clear();
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.cruiseSpeedMetresPerSecond = 2.0;
        drone.maxWaypoints = 12;
        drone.turnaroundSeconds = 300.0;
        ExportContext exportContext{plan, reference_, classes_, ExportSettings{}};
        exportContext.vehicles = {drone, drone};
        const AutopilotMission& mission = autopilotMissionOf(exportContext, 0);
        QVERIFY(mission.parts.size() > 1);
        const MissionFlights flights = missionFlights(mission, drone);
        const std::string note = fieldTimeNote(exportContext);
        QCOMPARE(note, "the last robot, " + exportContext.robotName(0) + ", done in the field after " +
                           formatDuration(flights.fieldSeconds) + ", its " +
                           std::to_string(mission.parts.size()) +
                           " flights and the turnarounds between them included");
        // Flights beyond one battery are named: the time counts them as flown.
        ExportContext batteries{plan, reference_, classes_, ExportSettings{}};
        drone.flightTimeSeconds = 120.0; // the far rows lie out of reach
        batteries.vehicles = {drone, drone};
        const std::size_t over = missionFlights(autopilotMissionOf(batteries, 0), drone).overFlightTime;
        QVERIFY(over > 0);
        const std::string caveat =
            " included (" + std::to_string(over) +
            " of them longer than one battery allows, counted as flown: see the warnings)";
        const std::string limited = fieldTimeNote(batteries);
        QVERIFY2(limited.ends_with(caveat), limited.c_str());
        // A rover's parts without turnarounds: nothing beyond the plan's time to say.
        ExportContext rovers{plan, reference_, classes_, ExportSettings{}};
        VehicleSettings rover;
        rover.maxWaypoints = 12;
        rovers.vehicles = {rover, rover};
        QVERIFY(autopilotMissionOf(rovers, 0).parts.size() > 1);
        QCOMPARE(fieldTimeNote(rovers), std::string());
    }

    // A drone's trips and turnarounds beside a rover's one part leave them done far apart in the field,
    // though their paths take the same time: the note says so, naming the first done.
    void fieldTimeNoteSaysWhenRobotsAreDoneFarApart() {
        Plan plan = lawnmowerPlan();
        plan.paths[1] = plan.paths[0]; // the same path for both
        plan.paths[1].robot = 1;
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.cruiseSpeedMetresPerSecond = 2.0;
        drone.maxWaypoints = 12;
        drone.turnaroundSeconds = 300.0;
        VehicleSettings rover;
        rover.cruiseSpeedMetresPerSecond = 2.0;
        ExportContext fleet{plan, reference_, classes_, ExportSettings{}};
        fleet.vehicles = {drone, rover};
        const MissionFlights flown = missionFlights(autopilotMissionOf(fleet, 0), drone);
        const MissionFlights driven = missionFlights(autopilotMissionOf(fleet, 1), rover);
        QVERIFY(flown.fieldSeconds > 1.1 * driven.fieldSeconds);
        const std::string note = fieldTimeNote(fleet);
        QVERIFY2(note.ends_with(
                     "; the first, " + fleet.robotName(1) + ", after " + formatDuration(driven.fieldSeconds) +
                     ": their paths take about as long, but the trips to and from where they take off "
                     "and the turnarounds between flights come on top"),
                 note.c_str());
        // Two drones alike are done together: nothing more to say.
        ExportContext drones{plan, reference_, classes_, ExportSettings{}};
        drones.vehicles = {drone, drone};
        const std::string together = fieldTimeNote(drones);
        QVERIFY2(!together.empty() && together.find("the first") == std::string::npos, together.c_str());
    }

    // A plan simulated over time adds what each robot took over from others: here robot 1 took the 20 m
    // cell east of the split one (so the traced grid is cropped away from the map's north-west corner).
    // GeoJSON, GeoPackage and KML carry it; a plan without a timeline has no such layer.
    void takenOverCellsAreTheirOwnLayer() {
        QVERIFY(!openVector(writtenGeoPackage("static.gpkg"))->GetLayerByName("taken_over"));
        RobotTimeline first;
        first.cellsTakenOver = {3};
        RobotTimeline second;
        second.robot = 1;
        plan_.layers.push_back(std::make_shared<TimelineLayer>(TimelineLayer::Summary{},
                                                               std::vector<RobotTimeline>{first, second},
                                                               std::vector<int>{0, 0, -1, 1}));
        const double originX = plan_.cells.frame().originX;
        const double originY = plan_.cells.frame().originY;

        Dataset geoPackage = openVector(writtenGeoPackage("simulated.gpkg"));
        OGRLayer* layer = geoPackage->GetLayerByName("taken_over");
        QVERIFY(layer != nullptr);
        QCOMPARE(layer->GetFeatureCount(), GIntBig{1});
        std::unique_ptr<OGRFeature> part(layer->GetNextFeature());
        QCOMPARE(part->GetFieldAsInteger("robot"), 1);
        QCOMPARE(part->GetFieldAsInteger("cells"), 1);
        QCOMPARE(part->GetFieldAsDouble("area_m2"), 400.0);
        OGREnvelope box;
        part->GetGeometryRef()->getEnvelope(&box);
        QCOMPARE(box.MinX, originX + 20.0);
        QCOMPARE(box.MaxX, originX + 40.0);
        QCOMPARE(box.MinY, originY - 20.0);
        QCOMPARE(box.MaxY, originY);
        QCOMPARE(part->GetGeometryRef()->toMultiPolygon()->get_Area(), 400.0);

        const std::string geoJson = file("simulated.geojson");
        QVERIFY(writePlanGeoJson(context(), geoJson).ok());
        Dataset json = openVector(geoJson);
        int found = 0;
        for (auto& feature : *json->GetLayer(0)) {
            if (std::string(feature->GetFieldAsString("kind")) != "taken_over")
                continue;
            ++found;
            QCOMPARE(feature->GetFieldAsInteger("robot"), 1);
            QCOMPARE(std::string(feature->GetFieldAsString("robot_name")), expectedName(0));
            QVERIFY(std::abs(areaInCrs(*feature->GetGeometryRef(), reference_) - 400.0) <
                    0.01); // 1e-7 degrees
        }
        QCOMPARE(found, 1);

        const std::string kml = file("simulated.kml");
        QVERIFY(writePlanKml(context(), kml).ok());
        Dataset kmlFile = openVector(kml);
        QVERIFY(kmlFile->GetLayerByName("taken_over") != nullptr);
        QCOMPARE(kmlFile->GetLayerByName("taken_over")->GetFeatureCount(), GIntBig{1});
        plan_.layers.clear();
    }

    // The area the plan was asked for goes with it: a layer for the area of interest (here a 100 m square
    // with a 20 m hole) and one for the no-go zones, in the CRS as given, each polygon with its area; GeoJSON
    // and KML carry them too. A ring of two corners is no polygon; a plan without an area has neither layer.
    void areaPolygonsAreTheirOwnLayers() {
        Dataset plain = openVector(writtenGeoPackage("no-area.gpkg"));
        QVERIFY(plain->GetLayerByName("area_of_interest") == nullptr);
        QVERIFY(plain->GetLayerByName("no_go_zones") == nullptr);
        const double x = plan_.cells.frame().originX;
        const double y = plan_.cells.frame().originY;
        const auto square = [](double left, double bottom, double side) {
            return AreaOutline::Ring{
                {left, bottom}, {left + side, bottom}, {left + side, bottom + side}, {left, bottom + side}};
        };
        AreaOutline area;
        area.include.push_back({square(x - 10.0, y - 90.0, 100.0), square(x + 30.0, y - 50.0, 20.0)});
        area.exclude.push_back({square(x + 60.0, y - 80.0, 10.0)});
        area.exclude.push_back({{{x, y}, {x + 5.0, y}, {x, y}}}); // two corners: no polygon, left out
        ExportContext withArea = context();
        withArea.area = &area;

        const std::string geoPackagePath = file("area.gpkg");
        QVERIFY(writePlanGeoPackage(withArea, geoPackagePath).ok());
        Dataset geoPackage = openVector(geoPackagePath);
        OGRLayer* include = geoPackage->GetLayerByName("area_of_interest");
        OGRLayer* exclude = geoPackage->GetLayerByName("no_go_zones");
        QVERIFY(include != nullptr && exclude != nullptr);
        QCOMPARE(include->GetFeatureCount(), GIntBig{1});
        QCOMPARE(exclude->GetFeatureCount(), GIntBig{1});
        std::unique_ptr<OGRFeature> kept(include->GetNextFeature());
        const OGRPolygon* polygon = kept->GetGeometryRef()->toPolygon();
        QCOMPARE(polygon->getNumInteriorRings(), 1);
        QCOMPARE(polygon->get_Area(), 9600.0);
        QCOMPARE(kept->GetFieldAsDouble("area_m2"), 9600.0);
        OGREnvelope box;
        polygon->getEnvelope(&box);
        QCOMPARE(box.MinX, x - 10.0);
        QCOMPARE(box.MaxY, y + 10.0);
        std::unique_ptr<OGRFeature> zone(exclude->GetNextFeature());
        QCOMPARE(zone->GetFieldAsDouble("area_m2"), 100.0);

        const std::string geoJson = file("area.geojson");
        QVERIFY(writePlanGeoJson(withArea, geoJson).ok());
        Dataset json = openVector(geoJson);
        std::map<std::string, double> areas;
        for (auto& feature : *json->GetLayer(0)) {
            const std::string kind = feature->GetFieldAsString("kind");
            if (kind == "area_of_interest" || kind == "no_go_zone") {
                QVERIFY(std::abs(areaInCrs(*feature->GetGeometryRef(), reference_) -
                                 feature->GetFieldAsDouble("area_m2")) < 0.01); // 1e-7 degrees
                areas[kind] = feature->GetFieldAsDouble("area_m2");
            }
        }
        QCOMPARE(areas, (std::map<std::string, double>{{"area_of_interest", 9600.0}, {"no_go_zone", 100.0}}));

        const std::string kml = file("area.kml");
        QVERIFY(writePlanKml(withArea, kml).ok());
        Dataset kmlFile = openVector(kml);
        QVERIFY(kmlFile->GetLayerByName("area_of_interest") != nullptr);
        QVERIFY(kmlFile->GetLayerByName("no_go_zones") != nullptr);
        QCOMPARE(kmlFile->GetLayerByName("no_go_zones")->GetFeatureCount(), GIntBig{1});
    }

    void geoPackageInFeetKeepsFeet() {
        const GeoReference feet = GeoReference::fromDefinition("EPSG:2227").value();
        const Plan plan =
            test::makeFixturePlan(1828803.6576, 640081.28); // 6,000,000 ft and 2,100,000 ft in metres
        const std::string path = file("feet.gpkg");
        QVERIFY(writePlanGeoPackage(ExportContext{plan, feet, classes_, {}}, path).ok());
        Dataset dataset = openVector(path);
        OGRLayer* starts = dataset->GetLayerByName("starts");
        starts->ResetReading();
        std::unique_ptr<OGRFeature> feature(starts->GetNextFeature());
        QVERIFY(feature != nullptr);
        const Waypoint& first = plan.paths[0].waypoints.front();
        QVERIFY(std::abs(feature->GetGeometryRef()->toPoint()->getX() - first.x / feet.metresPerUnit()) <
                1e-6);
        QVERIFY(std::abs(first.x / feet.metresPerUnit() - (6000000.0 + 2.5 * 3937.0 / 1200.0)) < 1e-3);
    }

    void kmlReadsBack() {
        const std::string path = file("plan.kml");
        Status written = writePlanKml(context(), path);
        QVERIFY2(written.ok(), written.error().c_str());
        Dataset dataset = openVector(path);
        QVERIFY(dataset != nullptr);
        OGRLayer* paths = dataset->GetLayerByName("paths");
        QVERIFY(paths != nullptr);
        QCOMPARE(paths->GetFeatureCount(), GIntBig{2});
        int robot = 0;
        for (auto& feature : *paths) {
            const OGRGeometry* geometry = feature->GetGeometryRef();
            const OGRLineString* line =
                wkbFlatten(geometry->getGeometryType()) == wkbLineString
                    ? geometry->toLineString()
                    : geometry->toGeometryCollection()->getGeometryRef(0)->toLineString();
            QVERIFY(lineError(*line, turningPoints(plan_.paths[static_cast<std::size_t>(robot++)]),
                              reference_) < 1e-7);
        }
        QCOMPARE(dataset->GetLayerByName("regions")->GetFeatureCount(), GIntBig{2});
        QCOMPARE(dataset->GetLayerByName("starts")->GetFeatureCount(), GIntBig{2});
        QCOMPARE(dataset->GetLayerByName("unreachable")->GetFeatureCount(), GIntBig{1});
        QVERIFY(dataset->GetLayerByName("missions") == nullptr); // no mission in parts: the paths say it all
        // Each robot's features are drawn in its colour, as on plan.png, its region see-through.
        const auto stylesOf = [&](const char* layer) {
            std::vector<std::string> styles;
            for (auto& feature : *dataset->GetLayerByName(layer))
                styles.emplace_back(feature->GetStyleString() != nullptr ? feature->GetStyleString() : "");
            return styles;
        };
        const auto colour = [](int number, const char* alpha) {
            char text[16];
            std::snprintf(text, sizeof text, "#%06X%s", robotColourRgb(number), alpha);
            return std::string(text);
        };
        for (int shown = 0; shown < 2; ++shown) {
            const auto index = static_cast<std::size_t>(shown);
            const std::string line = stylesOf("paths")[index];
            const std::string region = stylesOf("regions")[index];
            const std::string start = stylesOf("starts")[index];
            QVERIFY2(line.find("PEN(c:" + colour(shown, "FF")) != std::string::npos, line.c_str());
            QVERIFY2(region.find("BRUSH(fc:" + colour(shown, "55")) != std::string::npos, region.c_str());
            QVERIFY2(start.find("SYMBOL(c:" + colour(shown, "FF")) != std::string::npos, start.c_str());
        }
    }

    void gpxHasOneRoutePerRobot() {
        const std::string path = file("plan.gpx");
        ExportSettings all;
        all.mergeCollinear = false;
        Status written = writePlanGpx(context(all), path);
        QVERIFY2(written.ok(), written.error().c_str());
        Dataset dataset = openVector(path);
        QVERIFY(dataset != nullptr);
        OGRLayer* routes = dataset->GetLayerByName("routes");
        QVERIFY(routes != nullptr);
        QCOMPARE(routes->GetFeatureCount(), GIntBig{2});
        int robot = 0;
        for (auto& feature : *routes) {
            QCOMPARE(std::string(feature->GetFieldAsString("name")), expectedName(robot));
            QCOMPARE(feature->GetFieldAsInteger("number"), robot + 1);
            QVERIFY(lineError(*feature->GetGeometryRef()->toLineString(),
                              plan_.paths[static_cast<std::size_t>(robot)].waypoints, reference_) < 1e-7);
            ++robot;
        }
        // Merged: robot 0's straight run of four points becomes two.
        QVERIFY(writePlanGpx(context(), path).ok());
        Dataset merged = openVector(path);
        OGRLayer* mergedRoutes = merged->GetLayerByName("routes");
        mergedRoutes->ResetReading();
        std::unique_ptr<OGRFeature> first(mergedRoutes->GetNextFeature());
        QVERIFY(first != nullptr);
        QCOMPARE(first->GetGeometryRef()->toLineString()->getNumPoints(), 5);
    }

    // report.json says a plan's messages as the run does: map points with their degrees, robots by name.
    void reportMessagesGivePointsInDegreesAndRobotsByName() {
        const Plan fixture = plan_;
        plan_.issues = {
            {IssueSeverity::Warning, "cut-off", "robot 1 cannot reach land round (301910, 4154075)"},
            {IssueSeverity::Information, "far", "far from (1, 2)"}};
        const ClassGrid grid = test::filledGrid(4, 2, 301900.0, 4154080.0, 10.0, 1);
        ExportContext withGrid = context();
        withGrid.grid = &grid;
        const std::string path = file("report-people.json");
        QVERIFY(writeReportJson(withGrid, path).ok());
        plan_ = fixture;
        const QJsonObject report = readJson(path);
        const QString warning = report["warnings"].toArray()[0].toString();
        QVERIFY2(warning.startsWith("robot 1 cannot reach land round (301910, 4154075; longitude -113.24"),
                 qPrintable(warning));
        QVERIFY2(warning.endsWith(" (robot 1 is Scout)"), qPrintable(warning));
        const QJsonArray issues = report["issues"].toArray();
        QCOMPARE(issues[0].toObject()["message"].toString(), warning);
        // A pair of numbers far from the map is not its point: left as it is.
        QCOMPARE(issues[1].toObject()["message"].toString(), QString("far from (1, 2)"));
    }

    void reportJsonAndCsv() {
        const std::string path = file("report.json");
        QVERIFY(writeReportJson(context(), path).ok());
        const QJsonObject report = readJson(path);
        QCOMPARE(report["planner"].toString(), QString("fixture"));
        QCOMPARE(report["makespan_s"].toDouble(), 80.0);
        QCOMPARE(report["lower_bound_s"].toDouble(), 66.65);
        QCOMPARE(report["ratio"].toDouble(), 80.0 / 66.65);
        QCOMPARE(report["covered_fraction"].toDouble(), 600.0 / 700.0);
        QCOMPARE(report["unreachable_area_m2"].toDouble(), 100.0);
        QCOMPARE(report["repeated_fraction"].toDouble(), 0.05);
        const QJsonArray robots = report["robots"].toArray();
        QCOMPARE(robots.size(), 2);
        const QJsonObject second = robots[1].toObject();
        for (const char* key : {"robot", "cells", "area_m2", "length_m", "time_s", "turns"})
            QVERIFY2(second.contains(key), key);
        QCOMPARE(second["robot"].toInt(), 2);
        QCOMPARE(second["name"].toString(), QString("Robot 2"));
        QCOMPARE(robots[0].toObject()["name"].toString(), QString("Scout"));
        QCOMPARE(second["area_m2"].toDouble(), 400.0);
        QCOMPARE(second["time_s"].toDouble(), 33.33);
        QCOMPARE(robots[0].toObject()["mission_items"].toInt(), 7);
        QCOMPARE(robots[0].toObject()["mission_parts"].toInt(), 1);
        QCOMPARE(robots[0].toObject()["max_waypoints"].toInt(), 700);
        QCOMPARE(robots[0].toObject()["vehicle"].toString(), QString("rover"));
        const QJsonObject timings = report["timings_ms"].toObject();
        QCOMPARE(timings.size(), 3);
        QCOMPARE(timings["allocation"].toDouble(), 2.25);
        const QJsonArray issues = report["issues"].toArray();
        QCOMPARE(issues.size(), 1);
        QCOMPARE(issues[0].toObject()["code"].toString(), QString("fixture"));
        QCOMPARE(issues[0].toObject()["severity"].toString(), QString("warning"));
        QCOMPARE(report["warnings"].toArray()[0].toString(), QString("fixture warning"));

        const std::string csv = file("report.csv");
        QVERIFY(writeReportCsv(context(), csv).ok());
        std::ifstream input(csv);
        std::string header, line;
        std::getline(input, header);
        QCOMPARE(header, std::string("robot,name,cells,area_m2,length_m,time_s,turns,cost_s,mission_items,"
                                     "mission_parts,turn_time_s,connector_time_s,flight_time_s,"
                                     "mission_flights_s,mission_longest_part_s,"
                                     "mission_parts_over_flight_time,turnaround_s,mission_field_s,"
                                     "camera_trigger_m,mission_photos,covered_area_m2"));
        std::getline(input, line);
        // Home, the first speed and five turning points (the straight top run's two inner points go).
        // No flight time: one part of the whole time, none over, no turnarounds; no camera. Its two cells
        // are wholly passable: it covers its region's 200 m2.
        QCOMPARE(line, std::string("1,Scout,2,200,40,80,3,80,7,1,0,0,0,80,80,0,0,80,0,0,200"));
        QCOMPARE(robots[0].toObject()["covered_area_m2"].toDouble(), 200.0);
        QCOMPARE(robots[0].toObject()["mission_photos"].toInt(), 0);

        // A photo every 15 m along the 40 m path: one at the start, at 15 and 30 m, and one at the stop;
        // the camera's two items on top of the mission's.
        ExportSettings camera;
        camera.vehicle.cameraTriggerMetres = 15.0;
        QVERIFY(writeReportJson(context(camera), path).ok());
        const QJsonObject photographed = readJson(path)["robots"].toArray()[0].toObject();
        QCOMPARE(photographed["camera_trigger_m"].toDouble(), 15.0);
        QCOMPARE(photographed["mission_photos"].toInt(), 4);
        QCOMPARE(photographed["mission_items"].toInt(), 9);
    }

    void turningPointsDropOnlyCollinearPoints() {
        // A zigzag with straight runs, a U-turn back along itself, a repeated point and a class change
        // in a straight run: only points strictly between two collinear neighbours go.
        CoveragePath path;
        const std::vector<std::pair<double, double>> points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2},
                                                            {2, 2}, {1, 2}, {2, 2}, {3, 2}, {3, 2}, {3, 3},
                                                            {3, 4}, {4, 5}, {5, 6}, {6, 6}};
        for (std::size_t i = 0; i < points.size(); ++i) {
            path.waypoints.push_back(test::makeWaypoint(points[i].first, points[i].second, 0, 1.0));
        }
        const std::vector<Waypoint> kept = turningPoints(path);
        const std::vector<std::pair<double, double>> expected{{0, 0}, {3, 0}, {3, 2}, {1, 2}, {3, 2},
                                                              {3, 2}, {3, 4}, {5, 6}, {6, 6}};
        QCOMPARE(kept.size(), expected.size());
        for (std::size_t i = 0; i < kept.size(); ++i) {
            QCOMPARE(kept[i].x, expected[i].first);
            QCOMPARE(kept[i].y, expected[i].second);
        }
        // Same length as the dense path.
        const auto length = [](const std::vector<Waypoint>& line) {
            double total = 0.0;
            for (std::size_t i = 1; i < line.size(); ++i)
                total += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
            return total;
        };
        QVERIFY(std::abs(length(kept) - length(path.waypoints)) < 1e-12);
    }

    void densePathsOnRequest() { checkDensePaths(file("dense.geojson")); }

    // A dense path of a million points, as one feature, was more than GDAL's GeoJSON reader takes (and QGIS
    // with it): it is written in parts, which follow on from each other and together are the path, and the
    // file opens with GDAL's defaults. A path of fewer points stays one feature, without part numbers.
    void aDensePathOfAMillionPointsOpensInGdal() {
        const Plan fixture = plan_;
        std::vector<Waypoint>& long_ = plan_.paths[0].waypoints;
        long_.clear();
        constexpr int points = 1'200'001;
        for (int i = 0; i < points; ++i) // a zigzag inside the first cell
            long_.push_back(
                test::makeWaypoint(301901.0 + (i % 2) * 8.0, 4154079.0 - (i % 8000) * 0.001, 0, 0.5));
        const std::string path = file("long-dense.geojson");
        ExportSettings dense;
        dense.densePaths = true;
        QVERIFY(writePlanGeoJson(context(dense), path).ok());
        Dataset dataset = openVector(path);
        QVERIFY2(dataset != nullptr, CPLGetLastErrorMsg());
        std::vector<std::unique_ptr<OGRLineString>> parts;
        int shortPaths = 0;
        for (auto& feature : *dataset->GetLayer(0)) {
            if (std::string(feature->GetFieldAsString("kind")) != "path")
                continue;
            if (feature->GetFieldAsInteger("robot") == 2) {
                QVERIFY(!feature->IsFieldSetAndNotNull(feature->GetFieldIndex("part")));
                ++shortPaths;
                continue;
            }
            QCOMPARE(feature->GetFieldAsInteger("part"), static_cast<int>(parts.size()) + 1);
            QCOMPARE(feature->GetFieldAsInteger("parts"), 12);
            QCOMPARE(feature->GetFieldAsDouble("length_m"), plan_.paths[0].lengthMetres);
            parts.emplace_back(feature->GetGeometryRef()->toLineString()->clone());
            QVERIFY(parts.back()->getNumPoints() <= internal::mostSegmentsInAGeoJsonPath + 1);
        }
        QCOMPARE(shortPaths, 1);
        QCOMPARE(parts.size(), std::size_t{12});
        OGRLineString joined;
        for (const auto& part : parts) {
            if (joined.getNumPoints() > 0) { // each part begins where the one before it ended
                QCOMPARE(part->getX(0), joined.getX(joined.getNumPoints() - 1));
                QCOMPARE(part->getY(0), joined.getY(joined.getNumPoints() - 1));
            }
            joined.addSubLineString(part.get(), joined.getNumPoints() > 0 ? 1 : 0);
        }
        QVERIFY(lineError(joined, long_, reference_) < 1e-7);
        plan_ = fixture;
    }

    // A path whose straight runs were merged (large plans) still exports every sub-cell centre on request.
    void densePathsOfMergedRuns() {
        const Plan whole = plan_;
        for (CoveragePath& coverage : plan_.paths)
            mergeStraightRuns(coverage, plan_.cells);
        QVERIFY(plan_.paths.front().runsMerged());
        checkDensePaths(file("dense-merged.geojson"), &whole);
        plan_ = whole;
    }

    void regionRasterAgreesWithRegionPolygons() {
        const std::string raster = file("regions.tif");
        Status written = writeRegionRaster(context(), raster);
        QVERIFY2(written.ok(), written.error().c_str());
        GDALAllRegister();
        Dataset dataset(GDALDataset::FromHandle(
            GDALOpenEx(raster.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
        QVERIFY(dataset != nullptr);
        // Sub-cells of 5 m over the fixture's 4 x 2 bottom cells of 10 m.
        QCOMPARE(dataset->GetRasterXSize(), 8);
        QCOMPARE(dataset->GetRasterYSize(), 4);
        double transform[6];
        QCOMPARE(dataset->GetGeoTransform(transform), CE_None);
        QCOMPARE(transform[0], 301900.0);
        QCOMPARE(transform[1], 5.0);
        QCOMPARE(transform[3], 4154080.0);
        QCOMPARE(transform[5], -5.0);
        QCOMPARE(std::string(dataset->GetSpatialRef()->GetAuthorityCode(nullptr)), std::string("26912"));
        GDALRasterBand* band = dataset->GetRasterBand(1);
        int hasNodata = 0;
        QCOMPARE(band->GetNoDataValue(&hasNodata), 0.0);
        QVERIFY(hasNodata);
        QVERIFY(band->GetColorTable() != nullptr);
        QCOMPARE(band->GetColorTable()->GetColorEntry(1)->c1, short{0xe6});
        std::vector<std::uint8_t> values(32);
        QCOMPARE(band->RasterIO(GF_Read, 0, 0, 8, 4, values.data(), 8, 4, GDT_Byte, 0, 0, nullptr), CE_None);
        // NW, NE of robot 1; SW unreachable; SE blocked; the 20 m cell of robot 2.
        const std::vector<std::uint8_t> expected{1,   1,   1, 1, 2, 2, 2, 2, //
                                                 1,   1,   1, 1, 2, 2, 2, 2, //
                                                 255, 255, 0, 0, 2, 2, 2, 2, //
                                                 255, 255, 0, 0, 2, 2, 2, 2};
        QCOMPARE(values, expected);

        // Pixel for pixel: the centre of each pixel lies in the region polygon of the robot it names.
        const std::string vector = file("regions.gpkg");
        QVERIFY(writePlanGeoPackage(context(), vector).ok());
        Dataset regions = openVector(vector);
        std::map<int, std::unique_ptr<OGRGeometry>> regionOf;
        for (auto& feature : *regions->GetLayerByName("regions"))
            regionOf[feature->GetFieldAsInteger("robot")].reset(feature->GetGeometryRef()->clone());
        for (int row = 0; row < 4; ++row) {
            for (int column = 0; column < 8; ++column) {
                const OGRPoint centre(transform[0] + (column + 0.5) * transform[1],
                                      transform[3] + (row + 0.5) * transform[5]);
                const int value = values[static_cast<std::size_t>(row * 8 + column)];
                for (const auto& [robot, geometry] : regionOf)
                    QCOMPARE(geometry->Contains(&centre), robot == value);
            }
        }
    }

    void tracedOutlinesAreValidSimpleFeatures() {
        // Random label grids, traced, as OGR polygons: GEOS finds every one valid, areas as pixel counts.
        for (unsigned seed = 1; seed <= 30; ++seed) {
            std::mt19937 random(seed);
            LabelGrid grid;
            grid.columns = 6 + static_cast<int>(seed % 11);
            grid.rows = 5 + static_cast<int>(seed % 7);
            for (int i = 0; i < grid.columns * grid.rows; ++i)
                grid.labels.push_back(static_cast<std::int32_t>(random() % (2 + seed % 3)) - 1);
            for (const OutlinePolygon& outline : traceOutlines(grid)) {
                OGRPolygon polygon;
                std::vector<const OutlineRing*> rings{&outline.exterior};
                for (const OutlineRing& hole : outline.holes)
                    rings.push_back(&hole);
                for (const OutlineRing* ring : rings) {
                    auto* linear = new OGRLinearRing;
                    for (const GridVertex& vertex : *ring)
                        linear->addPoint(vertex.column, -vertex.row);
                    linear->closeRings();
                    polygon.addRingDirectly(linear);
                }
                QVERIFY2(polygon.IsValid(), ("seed " + std::to_string(seed)).c_str());
                QCOMPARE(polygon.get_Area(), static_cast<double>(outline.pixels));
            }
        }
    }

    void cancelledWritersLeaveNoFile() {
        // Cancelled (here before the first feature or row): the writer fails naming the file and neither the
        // file nor its temporary copy remains; an older file of that name is left as it was.
        const std::atomic<bool> cancel{true};
        ExportContext cancelled = context();
        cancelled.cancelRequested = &cancel;
        const QDir folder(folder_.path());
        for (const auto& [name, write] :
             std::vector<std::pair<std::string, Status (*)(const ExportContext&, const std::string&)>>{
                 {"cancel.gpkg", writePlanGeoPackage},
                 {"cancel.geojson", writePlanGeoJson},
                 {"cancel.kml", writePlanKml},
                 {"cancel.tif", writeRegionRaster}}) {
            const QStringList before = folder.entryList(QDir::Files | QDir::Hidden);
            const Status status = write(cancelled, file(name.c_str()));
            QVERIFY2(!status.ok(), name.c_str());
            QVERIFY2(status.error().find("cancelled") != std::string::npos, status.error().c_str());
            QCOMPARE(folder.entryList(QDir::Files | QDir::Hidden), before);
        }
        QVERIFY(writePlanGeoJson(context(), file("kept.geojson")).ok());
        const QByteArray kept = [&] {
            QFile f(QString::fromStdString(file("kept.geojson")));
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        QVERIFY(!writePlanGeoJson(cancelled, file("kept.geojson")).ok());
        QFile again(QString::fromStdString(file("kept.geojson")));
        QVERIFY(again.open(QIODevice::ReadOnly));
        QCOMPARE(again.readAll(), kept);
    }

    void noCrsCannotGoToWgs84ButGeoPackageWorks() {
        const GeoReference none;
        const ExportContext local{plan_, none, classes_, {}};
        Status geojson = writePlanGeoJson(local, file("local.geojson"));
        QVERIFY(!geojson.ok());
        QVERIFY(geojson.error().find("local.geojson") != std::string::npos);
        QVERIFY(!QFile::exists(QString::fromStdString(file("local.geojson"))));
        QVERIFY(writePlanGeoPackage(local, file("local.gpkg")).ok());
    }
};

QTEST_GUILESS_MAIN(PlanExportTest)
#include "test_plan_export.moc"
