#include "core/model/RobotColours.hpp"
#include "core/model/SortieLayer.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/DatasetFile.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/GeoJsonText.hpp"
#include "io/internal/LegendReader.hpp"
#include "io/internal/PlanGeometry.hpp"
#include "io/internal/TextFiles.hpp"
#include "io/internal/TransformationLoan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ogrsf_frmts.h>
#include <optional>

namespace mcpp::io {

namespace {

using internal::DatasetPointer;
using internal::PlanFeatures;
using internal::QuietGdalErrors;

// An OGR file written under a temporary name and moved into place when complete (internal::DatasetFile).
class VectorFileWriter {
  public:
    VectorFileWriter(std::string path, const char* driverName, const ExportContext& context)
        : file_(std::move(path)), driverName_(driverName), context_(context) {}

    [[nodiscard]] const std::string& path() const { return file_.path(); }

    Status open(const char* const* creationOptions = nullptr) {
        return file_.create(driverName_, 0, 0, 0, GDT_Unknown, creationOptions);
    }

    Result<OGRLayer*> layer(const char* name, const OGRSpatialReference* crs, OGRwkbGeometryType type,
                            const char* const* options = nullptr) {
        // GDAL 3.6 takes a non-const CRS pointer but only reads it.
        OGRLayer* created = file_.dataset().CreateLayer(name, const_cast<OGRSpatialReference*>(crs), type,
                                                        const_cast<char**>(options));
        if (created == nullptr)
            return Result<OGRLayer*>::failure(file_.path() + ": cannot create layer " + name +
                                              QuietGdalErrors::detail());
        return created;
    }

    Status field(OGRLayer* layer, const char* name, OGRFieldType type, OGRFieldSubType subType = OFSTNone) {
        OGRFieldDefn definition(name, type);
        definition.SetSubType(subType);
        if (layer->CreateField(&definition) != OGRERR_NONE) {
            return Status::failure(file_.path() + ": cannot add field " + name + QuietGdalErrors::detail());
        }
        return {};
    }

    Status add(OGRLayer* layer, OGRFeature& feature) {
        if (context_.cancelled())
            return Status::failure(file_.path() + ": cancelled");
        if (layer->CreateFeature(&feature) != OGRERR_NONE) {
            return Status::failure(file_.path() + ": cannot write a feature to " + layer->GetName() +
                                   QuietGdalErrors::detail());
        }
        return {};
    }

    GDALDataset& dataset() { return file_.dataset(); }
    Status commit() { return file_.commit(Sync::BySystem); } // exports: the mission makes them again

  private:
    internal::DatasetFile file_;
    const char* driverName_;
    const ExportContext& context_;
};

struct Fields {
    std::vector<std::pair<const char*, OGRFieldType>> definitions;
};

Status createFields(VectorFileWriter& writer, OGRLayer* layer, const Fields& fields) {
    for (const auto& [name, type] : fields.definitions) {
        if (Status status = writer.field(layer, name, type); !status)
            return status;
    }
    return {};
}

// A transformation from the plan's CRS to WGS84 longitude, latitude, borrowed from its georeference.
Result<std::unique_ptr<internal::TransformationLoan>> toWgs84(const GeoReference& georeference,
                                                              const std::string& path) {
    using Loan = std::unique_ptr<internal::TransformationLoan>;
    if (!georeference.hasCrs()) {
        return Result<Loan>::failure(
            path + ": the map has no CRS, so the plan cannot be written in longitude and latitude");
    }
    auto loan = std::make_unique<internal::TransformationLoan>(georeference);
    if (loan->get() == nullptr)
        return Result<Loan>::failure(path + ": no transformation to WGS84" + QuietGdalErrors::detail());
    return loan;
}

// Into WGS84, every coordinate finite (the GeoJSON text would otherwise hold "inf").
bool transformed(OGRGeometry& geometry, OGRCoordinateTransformation& transformation) {
    if (geometry.IsEmpty())
        return true;
    if (geometry.transform(&transformation) != OGRERR_NONE)
        return false;
    // transform() hands the geometry the transformation's own CRS object, which the next writer to borrow
    // the transformation would share across threads; the layers carry the CRS.
    geometry.assignSpatialReference(nullptr);
    OGREnvelope envelope;
    geometry.getEnvelope(&envelope);
    return std::isfinite(envelope.MinX) && std::isfinite(envelope.MaxX) && std::isfinite(envelope.MinY) &&
           std::isfinite(envelope.MaxY);
}

Status transformAll(PlanFeatures& features, OGRCoordinateTransformation& transformation,
                    const std::string& path) {
    const auto fail = [&](const char* what) {
        return Status::failure(path + ": cannot transform " + std::string(what) + " to WGS84" +
                               QuietGdalErrors::detail());
    };
    for (auto& region : features.regions) {
        if (!transformed(*region.geometry, transformation))
            return fail("a region");
    }
    for (auto& line : features.paths) {
        if (!transformed(*line.geometry, transformation))
            return fail("a path");
    }
    for (auto& start : features.starts) {
        if (!transformed(*start.geometry, transformation))
            return fail("a start");
    }
    for (auto& charger : features.chargers) {
        if (!transformed(*charger.geometry, transformation))
            return fail("a charger");
    }
    for (auto& part : features.unreachable) {
        if (!transformed(*part.geometry, transformation))
            return fail("an unreachable area");
    }
    for (auto& part : features.takenOver) {
        if (!transformed(*part.geometry, transformation))
            return fail("an area taken over");
    }
    for (auto& polygon : features.area) {
        if (!transformed(*polygon.geometry, transformation))
            return fail(polygon.noGoZone ? "a no-go zone" : "the area of interest");
    }
    return {};
}

// Whether a geometry in WGS84 spans more than 180 degrees of longitude: it crosses the antimeridian.
bool spansHalfTheGlobe(const OGRGeometry& geometry) {
    OGREnvelope envelope;
    geometry.getEnvelope(&envelope);
    return envelope.MaxX - envelope.MinX > 180.0;
}

// RFC 7946 (and KML readers) want features that cross the antimeridian cut in two there, each part on its
// own side, rather than one running the long way round the globe.
void cutAtTheAntimeridian(PlanFeatures& features) {
    const char* const options[] = {"WRAPDATELINE=YES", nullptr};
    const auto cut = [&](std::unique_ptr<OGRGeometry>& geometry) {
        if (!geometry || geometry->IsEmpty() || !spansHalfTheGlobe(*geometry))
            return;
        std::unique_ptr<OGRGeometry> wrapped(
            OGRGeometryFactory::transformWithOptions(geometry.get(), nullptr, const_cast<char**>(options)));
        if (wrapped)
            geometry = std::move(wrapped);
    };
    for (auto& region : features.regions)
        cut(region.geometry);
    for (auto& line : features.paths)
        cut(line.geometry);
    for (auto& part : features.unreachable)
        cut(part.geometry);
    for (auto& part : features.takenOver)
        cut(part.geometry);
    for (auto& polygon : features.area)
        cut(polygon.geometry);
}

Result<PlanFeatures> featuresInWgs84(const ExportContext& context, const std::string& path) {
    auto features = internal::buildPlanFeatures(context);
    if (!features)
        return Result<PlanFeatures>::failure(path + ": " + features.error());
    auto transformation = toWgs84(context.georeference, path);
    if (!transformation)
        return Result<PlanFeatures>::failure(transformation.error());
    if (Status status = transformAll(features.value(), *transformation.value()->get(), path); !status) {
        return Result<PlanFeatures>::failure(status.error());
    }
    cutAtTheAntimeridian(features.value());
    return features;
}

// Every layer names a robot by its number from 1 and its name.
void setRobotFields(OGRFeature& feature, const ExportContext& context, int robot) {
    feature.SetField("robot", robotNumber(robot));
    feature.SetField("robot_name", context.robotName(robot).c_str());
}

// A robot's colour as plan.png and regions.tif give it, "#e6194b", with `alpha` appended where given.
std::string robotColourText(int robot, std::optional<unsigned> alpha = std::nullopt) {
    std::string text = internal::formatColor(robotColourRgb(robot));
    if (alpha) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%02x", *alpha);
        text += hex;
    }
    return text;
}

// How KML readers draw a robot's features, in OGR's feature style language (LIBKML writes each as the
// placemark's style): regions filled see-through with the robot's colour so the ground shows, paths and
// start markers in that colour. Without them Google Earth draws every robot alike.
std::string regionStyle(int robot) {
    constexpr unsigned seeThrough = 0x55;
    return "BRUSH(fc:" + robotColourText(robot, seeThrough) + ");PEN(c:" + robotColourText(robot) + ",w:2px)";
}
std::string pathStyle(int robot) {
    return "PEN(c:" + robotColourText(robot) + ",w:2px)";
}
std::string startStyle(int robot) {
    return "SYMBOL(c:" + robotColourText(robot) + ",s:1.3)";
}

// The layers GeoPackage and KML share. KML readers show a feature's "name" and style, so `named` adds them.
Status writeRegionLayer(VectorFileWriter& writer, const ExportContext& context,
                        std::vector<internal::RegionFeature>& regions, const OGRSpatialReference* crs,
                        bool named) {
    auto layer = writer.layer("regions", crs, wkbMultiPolygon);
    if (!layer)
        return Status::failure(layer.error());
    Fields fields{{{"robot", OFTInteger},
                   {"robot_name", OFTString},
                   {"time_s", OFTReal},
                   {"cost_s", OFTReal},
                   {"area_m2", OFTReal},
                   {"cells", OFTInteger}}};
    if (named)
        fields.definitions.insert(fields.definitions.begin(), {"name", OFTString});
    if (Status status = createFields(writer, layer.value(), fields); !status)
        return status;
    for (auto& region : regions) {
        OGRFeature feature(layer.value()->GetLayerDefn());
        if (named) {
            feature.SetField("name", (context.robotName(region.robot) + " region").c_str());
            feature.SetStyleString(regionStyle(region.robot).c_str());
        }
        setRobotFields(feature, context, region.robot);
        feature.SetField("time_s", region.timeSeconds);
        feature.SetField("cost_s", region.costSeconds);
        feature.SetField("area_m2", region.areaSquareMetres);
        feature.SetField("cells", region.cells);
        feature.SetGeometryDirectly(region.geometry.release());
        if (Status status = writer.add(layer.value(), feature); !status)
            return status;
    }
    return {};
}

Status writePathLayer(VectorFileWriter& writer, const ExportContext& context,
                      std::vector<internal::PathFeature>& paths, const OGRSpatialReference* crs, bool named) {
    auto layer = writer.layer("paths", crs, wkbLineString);
    if (!layer)
        return Status::failure(layer.error());
    Fields fields{{{"robot", OFTInteger},
                   {"robot_name", OFTString},
                   {"length_m", OFTReal},
                   {"time_s", OFTReal},
                   {"turns", OFTInteger}}};
    if (named)
        fields.definitions.insert(fields.definitions.begin(), {"name", OFTString});
    if (Status status = createFields(writer, layer.value(), fields); !status)
        return status;
    for (auto& line : paths) {
        OGRFeature feature(layer.value()->GetLayerDefn());
        if (named) {
            feature.SetField("name", (context.robotName(line.robot) + " path").c_str());
            feature.SetStyleString(pathStyle(line.robot).c_str());
        }
        setRobotFields(feature, context, line.robot);
        feature.SetField("length_m", line.lengthMetres);
        feature.SetField("time_s", line.timeSeconds);
        feature.SetField("turns", line.turns);
        feature.SetGeometryDirectly(line.geometry.release());
        if (Status status = writer.add(layer.value(), feature); !status)
            return status;
    }
    return {};
}

// The robots' starts, or (`chargers`) the chargers their sorties fly from.
Status writeStartLayer(VectorFileWriter& writer, const ExportContext& context,
                       std::vector<internal::StartFeature>& starts, const OGRSpatialReference* crs,
                       bool named, bool chargers = false) {
    auto layer = writer.layer(chargers ? "chargers" : "starts", crs, wkbPoint);
    if (!layer)
        return Status::failure(layer.error());
    Fields fields{{{"robot", OFTInteger}, {"robot_name", OFTString}}};
    if (named)
        fields.definitions.insert(fields.definitions.begin(), {"name", OFTString});
    if (Status status = createFields(writer, layer.value(), fields); !status)
        return status;
    for (auto& start : starts) {
        OGRFeature feature(layer.value()->GetLayerDefn());
        if (named) {
            feature.SetField("name",
                             (context.robotName(start.robot) + (chargers ? " charger" : " start")).c_str());
            feature.SetStyleString(startStyle(start.robot).c_str());
        }
        setRobotFields(feature, context, start.robot);
        feature.SetGeometryDirectly(start.geometry.release());
        if (Status status = writer.add(layer.value(), feature); !status)
            return status;
    }
    return {};
}

// A layer of polygons with their area on the ground, those of `features` that `keep` takes; in KML each is
// named `featureName`.
template <typename Feature, typename Keep>
Status writeAreaPolygonLayer(VectorFileWriter& writer, const char* layerName, const char* featureName,
                             std::vector<Feature>& features, Keep keep, const OGRSpatialReference* crs,
                             bool named) {
    auto layer = writer.layer(layerName, crs, wkbPolygon);
    if (!layer)
        return Status::failure(layer.error());
    Fields fields{{{"area_m2", OFTReal}}};
    if (named)
        fields.definitions.insert(fields.definitions.begin(), {"name", OFTString});
    if (Status status = createFields(writer, layer.value(), fields); !status)
        return status;
    for (auto& part : features) {
        if (!keep(part))
            continue;
        OGRFeature feature(layer.value()->GetLayerDefn());
        if (named)
            feature.SetField("name", featureName);
        feature.SetField("area_m2", part.areaSquareMetres);
        feature.SetGeometryDirectly(part.geometry.release());
        if (Status status = writer.add(layer.value(), feature); !status)
            return status;
    }
    return {};
}

Status writeUnreachableLayer(VectorFileWriter& writer, std::vector<internal::UnreachableFeature>& parts,
                             const OGRSpatialReference* crs, bool named) {
    return writeAreaPolygonLayer(
        writer, "unreachable", "unreachable", parts, [](const auto&) { return true; }, crs, named);
}

// What each robot took over from others' first regions, for plans simulated over time.
Status writeTakenOverLayer(VectorFileWriter& writer, const ExportContext& context,
                           std::vector<internal::TakenOverFeature>& parts, const OGRSpatialReference* crs,
                           bool named) {
    auto layer = writer.layer("taken_over", crs, wkbMultiPolygon);
    if (!layer)
        return Status::failure(layer.error());
    Fields fields{
        {{"robot", OFTInteger}, {"robot_name", OFTString}, {"area_m2", OFTReal}, {"cells", OFTInteger}}};
    if (named)
        fields.definitions.insert(fields.definitions.begin(), {"name", OFTString});
    if (Status status = createFields(writer, layer.value(), fields); !status)
        return status;
    for (auto& part : parts) {
        OGRFeature feature(layer.value()->GetLayerDefn());
        if (named) {
            feature.SetField("name", (context.robotName(part.robot) + " took over").c_str());
            feature.SetStyleString(regionStyle(part.robot).c_str());
        }
        setRobotFields(feature, context, part.robot);
        feature.SetField("area_m2", part.areaSquareMetres);
        feature.SetField("cells", part.cells);
        feature.SetGeometryDirectly(part.geometry.release());
        if (Status status = writer.add(layer.value(), feature); !status)
            return status;
    }
    return {};
}

// The area of interest's polygons and the no-go zones', a layer for each that has any.
Status writeAreaLayers(VectorFileWriter& writer, std::vector<internal::AreaFeature>& polygons,
                       const OGRSpatialReference* crs, bool named) {
    struct AreaLayer {
        const char* name;
        const char* featureName;
        bool noGoZones;
    };
    constexpr AreaLayer layers[] = {{"area_of_interest", "area of interest", false},
                                    {"no_go_zones", "no-go zone", true}};
    for (const AreaLayer& areaLayer : layers) {
        const auto inLayer = [&](const internal::AreaFeature& polygon) {
            return polygon.noGoZone == areaLayer.noGoZones;
        };
        if (std::none_of(polygons.begin(), polygons.end(), inLayer))
            continue;
        if (Status status = writeAreaPolygonLayer(writer, areaLayer.name, areaLayer.featureName, polygons,
                                                  inLayer, crs, named);
            !status)
            return status;
    }
    return {};
}

// The name batch mode gives the part's .plan and .waypoints files, without the extension: "robot_2" for a
// mission in one part, "robot_2_part_3" for its third part (of a plan of `robots`).
std::string partFileStem(int robot, int robots, std::size_t part, std::size_t parts) {
    return missionFilePath(robotFileStem(robot, robots), part, parts);
}

// A part's waypoints as a line in the plan's CRS.
std::unique_ptr<OGRLineString> missionPartLine(const ExportContext& context, const AutopilotMission& mission,
                                               const MissionPart& piece) {
    const double metresPerUnit = context.georeference.metresPerUnit();
    auto line = std::make_unique<OGRLineString>();
    line->setNumPoints(static_cast<int>(piece.last - piece.first + 1));
    for (std::size_t point = piece.first; point <= piece.last; ++point)
        line->setPoint(static_cast<int>(point - piece.first), mission.points[point].x / metresPerUnit,
                       mission.points[point].y / metresPerUnit);
    return line;
}

// One waypoint file's part as a feature of the missions layer: what it holds and takes, and its line.
void setMissionPart(OGRFeature& feature, const ExportContext& context, int robot,
                    const AutopilotMission& mission, std::size_t part) {
    const MissionPart& piece = mission.parts[part];
    setRobotFields(feature, context, robot);
    feature.SetField("part", static_cast<int>(part + 1));
    feature.SetField("parts", static_cast<int>(mission.parts.size()));
    feature.SetField("items", piece.items);
    feature.SetField(
        "file",
        partFileStem(robot, static_cast<int>(context.plan.paths.size()), part, mission.parts.size()).c_str());
    if (piece.seconds > 0.0)
        feature.SetField("part_time_s", piece.seconds);
    feature.SetField("farthest_m", farthestFromHome(mission, piece));
    if (const VehicleSettings& vehicle = context.vehicle(robot); vehicle.flightTimeSeconds > 0.0) {
        feature.SetField("flight_time_s", vehicle.flightTimeSeconds);
        if (piece.seconds > 0.0)
            feature.SetField("fits_flight", exceedsFlightTime(piece, vehicle) ? 0 : 1);
    }
    feature.SetGeometryDirectly(missionPartLine(context, mission, piece).release());
}

// LIBKML's writing slows down steeply with the fields of many placemarks (8 s for 1 129 parts of 12 fields,
// 0.6 s with 2): there a part carries its file name, its time and whether it fits a flight.
void setKmlMissionPart(OGRFeature& feature, const ExportContext& context, int robot,
                       const AutopilotMission& mission, std::size_t part) {
    const MissionPart& piece = mission.parts[part];
    feature.SetField(
        "name",
        partFileStem(robot, static_cast<int>(context.plan.paths.size()), part, mission.parts.size()).c_str());
    if (piece.seconds > 0.0)
        feature.SetField("part_time_s", piece.seconds);
    if (const VehicleSettings& vehicle = context.vehicle(robot);
        vehicle.flightTimeSeconds > 0.0 && piece.seconds > 0.0)
        feature.SetField("fits_flight", exceedsFlightTime(piece, vehicle) ? 0 : 1);
    feature.SetStyleString(pathStyle(robot).c_str());
    feature.SetGeometryDirectly(missionPartLine(context, mission, piece).release());
}

// Each robot's waypoint files as lines, one per part (a flight, for a battery), with what it holds and
// takes: a user sees on the map which flights fit and where those that do not go. For KML (`toWgs84`
// given) each part is named by its file and drawn in its robot's colour, with its time and fit alone.
Status writeMissionLayer(VectorFileWriter& writer, const ExportContext& context,
                         const OGRSpatialReference* crs, OGRCoordinateTransformation* toWgs84 = nullptr) {
    auto layer = writer.layer("missions", crs, wkbLineString);
    if (!layer)
        return Status::failure(layer.error());
    const Fields fields = toWgs84 != nullptr ? Fields{{{"name", OFTString}, {"part_time_s", OFTReal}}}
                                             : Fields{{{"robot", OFTInteger},
                                                       {"robot_name", OFTString},
                                                       {"part", OFTInteger},
                                                       {"parts", OFTInteger},
                                                       {"file", OFTString},
                                                       {"items", OFTInteger},
                                                       {"part_time_s", OFTReal},
                                                       {"farthest_m", OFTReal},
                                                       {"flight_time_s", OFTReal}}};
    if (Status status = createFields(writer, layer.value(), fields); !status)
        return status;
    if (Status status = writer.field(layer.value(), "fits_flight", OFTInteger, OFSTBoolean); !status)
        return status;
    for (const CoveragePath& path : context.plan.paths) {
        const AutopilotMission& mission = autopilotMissionOf(context, path.robot);
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            OGRFeature feature(layer.value()->GetLayerDefn());
            if (toWgs84 == nullptr) {
                setMissionPart(feature, context, path.robot, mission, part);
            } else {
                setKmlMissionPart(feature, context, path.robot, mission, part);
                if (!transformed(*feature.GetGeometryRef(), *toWgs84))
                    return Status::failure(writer.path() + ": cannot transform a mission part to WGS84" +
                                           QuietGdalErrors::detail());
            }
            if (Status status = writer.add(layer.value(), feature); !status)
                return status;
        }
    }
    return {};
}

// A polygon per cell with its land cover and robot: asked for explicitly, as it is big on large maps.
Status writeCellLayer(VectorFileWriter& writer, const ExportContext& context,
                      const OGRSpatialReference* crs) {
    const double metresPerUnit = context.georeference.metresPerUnit();
    auto cells = writer.layer("cells", crs, wkbPolygon);
    if (!cells)
        return Status::failure(cells.error());
    if (Status status = createFields(writer, cells.value(),
                                     {{{"cell", OFTInteger},
                                       {"level", OFTInteger},
                                       {"class", OFTInteger},
                                       {"fov", OFTReal},
                                       {"speed", OFTReal},
                                       {"free_sub_cells", OFTInteger},
                                       {"robot", OFTInteger}}});
        !status) {
        return status;
    }
    const CellGraph& graph = context.plan.cells;
    const auto& owner = context.plan.regions.robotOfCell;
    for (std::size_t index = 0; index < graph.size(); ++index) {
        const Cell& cell = graph.cell(static_cast<int>(index));
        OGRFeature feature(cells.value()->GetLayerDefn());
        feature.SetField("cell", static_cast<int>(index));
        feature.SetField("level", int{cell.level});
        feature.SetField("class", static_cast<int>(cell.classValue));
        feature.SetField("fov", cell.fieldOfView());
        feature.SetField("speed", internal::decimalDouble(cell.speedMetresPerSecond));
        feature.SetField("free_sub_cells", cell.freeSubCellCount());
        if (index < owner.size() && owner[index] >= 0)
            feature.SetField("robot", robotNumber(owner[index]));
        feature.SetGeometryDirectly(internal::cellSquare(graph, cell, metresPerUnit).release());
        if (Status status = writer.add(cells.value(), feature); !status)
            return status;
    }

    return {};
}

struct MissionParts {
    std::size_t count = 0; // of all robots' waypoint files
    bool split = false;    // some robot's mission is in several
};

MissionParts missionPartsOf(const ExportContext& context) {
    MissionParts parts;
    for (const CoveragePath& line : context.plan.paths) {
        const std::size_t robotParts = autopilotMissionOf(context, line.robot).parts.size();
        parts.count += robotParts;
        parts.split = parts.split || robotParts > 1;
    }
    return parts;
}

} // namespace

Status writePlanGeoJson(const ExportContext& context, const std::string& path) {
    QuietGdalErrors quiet;
    auto features = featuresInWgs84(context, path);
    if (!features)
        return Status::failure(features.error());
    const std::optional<std::string> text = internal::planGeoJsonText(context, features.value());
    if (!text)
        return Status::failure(path + ": cancelled");
    return internal::writeFileAtomically(path, *text, Sync::BySystem);
}

Status writePlanGeoPackage(const ExportContext& context, const std::string& path) {
    QuietGdalErrors quiet;
    auto features = internal::buildPlanFeatures(context);
    if (!features)
        return Status::failure(path + ": " + features.error());
    std::unique_ptr<OGRSpatialReference> crs;
    if (context.georeference.hasCrs())
        crs = internal::spatialReferenceFromDefinition(context.georeference.wkt());

    VectorFileWriter writer(path, "GPKG", context);
    if (Status status = writer.open(); !status)
        return status;
    writer.dataset().StartTransaction();

    PlanFeatures& planFeatures = features.value();
    if (Status status = writeRegionLayer(writer, context, planFeatures.regions, crs.get(), false); !status)
        return status;
    if (Status status = writePathLayer(writer, context, planFeatures.paths, crs.get(), false); !status)
        return status;
    if (Status status = writeStartLayer(writer, context, planFeatures.starts, crs.get(), false); !status)
        return status;
    if (!planFeatures.chargers.empty())
        if (Status status = writeStartLayer(writer, context, planFeatures.chargers, crs.get(), false, true);
            !status)
            return status;

    if (context.settings.cellPolygons) {
        if (Status status = writeCellLayer(writer, context, crs.get()); !status)
            return status;
    }
    if (Status status = writeUnreachableLayer(writer, planFeatures.unreachable, crs.get(), false); !status)
        return status;
    if (Status status = writeMissionLayer(writer, context, crs.get()); !status)
        return status;
    if (planFeatures.simulatedOverTime) {
        if (Status status = writeTakenOverLayer(writer, context, planFeatures.takenOver, crs.get(), false);
            !status)
            return status;
    }
    if (Status status = writeAreaLayers(writer, planFeatures.area, crs.get(), false); !status)
        return status;
    if (writer.dataset().CommitTransaction() != OGRERR_NONE) {
        return Status::failure(path + ": cannot commit" + QuietGdalErrors::detail());
    }
    return writer.commit();
}

Status writePlanKml(const ExportContext& context, const std::string& path) {
    QuietGdalErrors quiet;
    auto features = featuresInWgs84(context, path);
    if (!features)
        return Status::failure(features.error());
    const bool libkml = GetGDALDriverManager()->GetDriverByName("LIBKML") != nullptr;
    VectorFileWriter writer(path, libkml ? "LIBKML" : "KML", context);
    if (Status status = writer.open(); !status)
        return status;
    const auto wgs84 = internal::wgs84SpatialReference();

    PlanFeatures& planFeatures = features.value();
    if (Status status = writeRegionLayer(writer, context, planFeatures.regions, wgs84.get(), true); !status)
        return status;
    if (Status status = writePathLayer(writer, context, planFeatures.paths, wgs84.get(), true); !status)
        return status;
    if (Status status = writeStartLayer(writer, context, planFeatures.starts, wgs84.get(), true); !status)
        return status;
    if (!planFeatures.chargers.empty())
        if (Status status = writeStartLayer(writer, context, planFeatures.chargers, wgs84.get(), true, true);
            !status)
            return status;
    if (!planFeatures.unreachable.empty()) {
        if (Status status = writeUnreachableLayer(writer, planFeatures.unreachable, wgs84.get(), true);
            !status)
            return status;
    }
    if (!planFeatures.takenOver.empty()) {
        if (Status status = writeTakenOverLayer(writer, context, planFeatures.takenOver, wgs84.get(), true);
            !status)
            return status;
    }
    if (Status status = writeAreaLayers(writer, planFeatures.area, wgs84.get(), true); !status)
        return status;
    // Split missions' parts, each flight on its own in Google Earth; a whole mission is its path already.
    // Up to a few thousand: LIBKML's writing slows down steeply with the placemarks (1 s for 1 129 parts).
    if (const MissionParts parts = missionPartsOf(context);
        parts.split && parts.count <= kmlMostMissionParts) {
        auto transformation = toWgs84(context.georeference, path);
        if (!transformation)
            return Status::failure(transformation.error());
        if (Status status = writeMissionLayer(writer, context, wgs84.get(), transformation.value()->get());
            !status)
            return status;
    }
    return writer.commit();
}

std::string kmlMissionPartsNote(const ExportContext& context, const std::string& path) {
    const MissionParts parts = missionPartsOf(context);
    if (!parts.split || parts.count <= kmlMostMissionParts)
        return {};
    return std::filesystem::path(path).filename().string() + " leaves out the " +
           std::to_string(parts.count) + " waypoint file parts (more than " +
           std::to_string(kmlMostMissionParts) +
           " take long to write and to open): a GeoPackage export holds them all in its missions layer";
}

namespace {

// A waypoint at the charger a robot's sorties fly from, where it is not at the robot's start.
Status addGpxCharger(VectorFileWriter& writer, OGRLayer& layer, const ExportContext& context, int robot,
                     MapPoint start, OGRCoordinateTransformation& transformation) {
    const RobotSorties* sorties = sortiesOfRobot(context.plan, robot);
    if (sorties == nullptr || !sorties->chargerAwayFrom(start))
        return {};
    const double metresPerUnit = context.georeference.metresPerUnit();
    OGRPoint charger(sorties->charger.x / metresPerUnit, sorties->charger.y / metresPerUnit);
    if (charger.transform(&transformation) != OGRERR_NONE)
        return Status::failure(writer.path() + ": cannot transform a charger to WGS84" +
                               QuietGdalErrors::detail());
    OGRFeature feature(layer.GetLayerDefn());
    feature.SetField("name", (context.robotName(robot) + " charger").c_str());
    feature.SetGeometry(&charger);
    return writer.add(&layer, feature);
}

} // namespace

Status writePlanGpx(const ExportContext& context, const std::string& path) {
    QuietGdalErrors quiet;
    auto transformation = toWgs84(context.georeference, path);
    if (!transformation)
        return Status::failure(transformation.error());
    VectorFileWriter writer(path, "GPX", context);
    if (Status status = writer.open(); !status)
        return status;
    const auto wgs84 = internal::wgs84SpatialReference();
    const double metresPerUnit = context.georeference.metresPerUnit();

    auto starts = writer.layer("waypoints", wgs84.get(), wkbPoint);
    if (!starts)
        return Status::failure(starts.error());
    auto routes = writer.layer("routes", wgs84.get(), wkbLineString);
    if (!routes)
        return Status::failure(routes.error());
    // GPX wants every <wpt> before the first <rte>: starts first, then the routes.
    for (int pass = 0; pass < 2; ++pass) {
        for (const CoveragePath& coverage : context.plan.paths) {
            CoveragePath whole;
            const std::vector<Waypoint> waypoints = exportedWaypoints(
                pathForWaypointFiles(coverage, context.plan.cells, context.settings.mergeCollinear, whole),
                context.plan.cells, context.settings.mergeCollinear);
            if (waypoints.empty())
                continue;
            const std::string name = context.robotName(coverage.robot);
            if (pass == 0) {
                const MapPoint start =
                    coverage.takeOff ? *coverage.takeOff : MapPoint{waypoints.front().x, waypoints.front().y};
                OGRPoint home(start.x / metresPerUnit, start.y / metresPerUnit);
                if (home.transform(transformation.value()->get()) != OGRERR_NONE) {
                    return Status::failure(path + ": cannot transform a start to WGS84" +
                                           QuietGdalErrors::detail());
                }
                OGRFeature startFeature(starts.value()->GetLayerDefn());
                startFeature.SetField("name", (name + " start").c_str());
                startFeature.SetGeometry(&home);
                if (Status status = writer.add(starts.value(), startFeature); !status)
                    return status;
                if (Status status = addGpxCharger(writer, *starts.value(), context, coverage.robot, start,
                                                  *transformation.value()->get());
                    !status)
                    return status;
                continue;
            }
            OGRLineString route;
            for (const Waypoint& waypoint : waypoints)
                route.addPoint(waypoint.x / metresPerUnit, waypoint.y / metresPerUnit);
            if (route.transform(transformation.value()->get()) != OGRERR_NONE) {
                return Status::failure(path + ": cannot transform " + name + "'s route to WGS84" +
                                       QuietGdalErrors::detail());
            }
            OGRFeature routeFeature(routes.value()->GetLayerDefn());
            routeFeature.SetField("name", name.c_str());
            routeFeature.SetField("number", robotNumber(coverage.robot));
            routeFeature.SetGeometry(&route);
            if (Status status = writer.add(routes.value(), routeFeature); !status)
                return status;
        }
    }
    return writer.commit();
}

} // namespace mcpp::io
