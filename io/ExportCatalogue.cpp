#include "io/ExportCatalogue.hpp"

#include "core/model/DetectionLayer.hpp"

#include <algorithm>

namespace mcpp::io {
namespace {

using Writer = std::function<Status(const ExportContext&, int, const std::string&)>;

Writer wholePlan(Status (*write)(const ExportContext&, const std::string&)) {
    return
        [write](const ExportContext& context, int, const std::string& path) { return write(context, path); };
}

Writer picture(ImageFormat format) {
    return [format](const ExportContext& context, int, const std::string& path) {
        if (!context.drawImage)
            return Status::failure(path + ": this program was built without a map renderer");
        return context.drawImage(context, format, path);
    };
}

ExportFormat format(std::string key, std::string label, std::string extension, std::string filter,
                    Writer write) {
    ExportFormat result;
    result.key = std::move(key);
    result.label = std::move(label);
    result.extension = std::move(extension);
    result.filter = std::move(filter);
    result.write = std::move(write);
    return result;
}

ExportFormat inBatch(ExportFormat result, std::string fileName, bool required) {
    result.inBatchOutputs = true;
    result.batchFileName = std::move(fileName);
    result.requiredInBatch = required;
    return result;
}

// Written by batch mode only when --outputs names it.
ExportFormat onRequestInBatch(ExportFormat result, std::string fileName) {
    result.batchFileName = std::move(fileName);
    return result;
}

ExportFormat inLongitudeLatitude(ExportFormat result) {
    result.needsLongitudeLatitude = true;
    return result;
}

ExportFormat splitByItemLimit(ExportFormat result) {
    result.splitByItemLimit = true;
    return result;
}

ExportFormat onlyWithDetection(ExportFormat result) {
    result.appliesTo = [](const Plan& plan) { return detectionLayerOf(plan) != nullptr; };
    return result;
}

ExportFormat withNote(ExportFormat result, std::string (*noteOf)(const ExportContext&, const std::string&)) {
    result.noteOf = noteOf;
    return result;
}

ExportFormat perRobot(ExportFormat result) {
    result.perRobot = true;
    return result;
}

std::vector<ExportFormat> makeCatalogue() {
    return {
        inBatch(inLongitudeLatitude(format("geojson", "GeoJSON", "geojson", "GeoJSON (*.geojson *.json)",
                                           wholePlan(writePlanGeoJson))),
                "plan.geojson", true),
        inBatch(format("gpkg", "GeoPackage", "gpkg", "GeoPackage (*.gpkg)", wholePlan(writePlanGeoPackage)),
                "plan.gpkg", false),
        inBatch(format("regions-tif", "Regions raster (GeoTIFF)", "tif", "GeoTIFF (*.tif *.tiff)",
                       wholePlan(writeRegionRaster)),
                "regions.tif", false),
        inBatch(onlyWithDetection(format("detection-tif", "Detection raster (GeoTIFF)", "tif",
                                         "GeoTIFF (*.tif *.tiff)", wholePlan(writeDetectionRaster))),
                "detection.tif", true),
        onRequestInBatch(
            withNote(inLongitudeLatitude(format("kml", "KML", "kml", "KML (*.kml)", wholePlan(writePlanKml))),
                     kmlMissionPartsNote),
            "plan.kml"),
        onRequestInBatch(
            inLongitudeLatitude(format("gpx", "GPX", "gpx", "GPX (*.gpx)", wholePlan(writePlanGpx))),
            "plan.gpx"),
        inBatch(splitByItemLimit(inLongitudeLatitude(
                    perRobot(format("qgc-plan", "QGroundControl plan per robot", "plan",
                                    "QGroundControl plan (*.plan)", writeQGroundControlPlan)))),
                {}, true),
        inBatch(splitByItemLimit(inLongitudeLatitude(
                    perRobot(format("qgc-wpl", "Waypoint list (QGC WPL) per robot", "waypoints",
                                    "Waypoint list (*.waypoints *.txt)", writeWaypointList)))),
                {}, true),
        inBatch(inLongitudeLatitude(perRobot(format("waypoint-csv", "Waypoint CSV per robot", "csv",
                                                    "CSV (*.csv)", writeWaypointCsv))),
                {}, true),
        inBatch(format("report-json", "Report (JSON)", "json", "JSON (*.json)", wholePlan(writeReportJson)),
                "report.json", true),
        inBatch(format("report-csv", "Report (CSV)", "csv", "CSV (*.csv)", wholePlan(writeReportCsv)),
                "report.csv", false),
        inBatch(format("png", "Map image (PNG)", "png", "PNG image (*.png)", picture(ImageFormat::Png)),
                "plan.png", true),
        onRequestInBatch(
            format("svg", "Map drawing (SVG)", "svg", "SVG drawing (*.svg)", picture(ImageFormat::Svg)),
            "plan.svg"),
    };
}

} // namespace

const std::vector<ExportFormat>& exportFormats() {
    static const std::vector<ExportFormat> catalogue = makeCatalogue();
    return catalogue;
}

bool formatApplies(const ExportFormat& format, const Plan& plan) {
    return !format.appliesTo || format.appliesTo(plan);
}

std::string exportFormatKeys() {
    std::string keys;
    for (const ExportFormat& format : exportFormats())
        keys += (keys.empty() ? "" : ", ") + format.key;
    return keys;
}

std::string batchOutputName(const ExportFormat& format) {
    return format.perRobot ? "robot_<n>." + format.extension : format.batchFileName;
}

const ExportFormat* findExportFormat(const std::string& key) {
    const auto& catalogue = exportFormats();
    const auto found = std::find_if(catalogue.begin(), catalogue.end(),
                                    [&](const ExportFormat& candidate) { return candidate.key == key; });
    return found == catalogue.end() ? nullptr : &*found;
}

std::string robotFileName(int robot, int robots, const ExportFormat& format) {
    return robotFileStem(robot, robots) + "." + format.extension;
}

} // namespace mcpp::io
