#pragma once

#include "io/PlanExport.hpp"
#include "io/Result.hpp"

#include <functional>
#include <string>
#include <vector>

namespace mcpp::io {

// One way to write a plan to a file. Batch mode's outputs and the window's Export menu both come from
// exportFormats(), so a format is added (or renamed) in one place.
struct ExportFormat {
    std::string key;       // stable name: "geojson", "qgc-plan"...
    std::string label;     // menu text: "GeoJSON"
    std::string extension; // without the dot
    std::string filter;    // file-dialog filter: "GeoJSON (*.geojson *.json)"
    bool perRobot = false; // one file per robot
    // Written in WGS84 longitude and latitude, so impossible for a map without a CRS.
    bool needsLongitudeLatitude = false;
    // An autopilot file: a mission above the robot's item limit is written in parts (missionPartPath).
    bool splitByItemLimit = false;
    // Batch mode: whether it writes this format unasked, under which name (whole-plan formats; per-robot
    // files are robot_<i>.<extension>), and whether a failure ends the run (else it is a warning). Every
    // format can be asked for by its key (--outputs).
    bool inBatchOutputs = false;
    std::string batchFileName;
    bool requiredInBatch = false;
    // Whether the plan has what the format writes (a detection raster needs a detection layer); empty: any.
    std::function<bool(const Plan& plan)> appliesTo;
    // robot is ignored by whole-plan formats.
    std::function<Status(const ExportContext& context, int robot, const std::string& path)> write;
    // What the user should know of a whole-plan file written to path (what it leaves out, and where that is);
    // empty, or no function, when nothing.
    std::function<std::string(const ExportContext& context, const std::string& path)> noteOf;
};

// Every format, in menu order.
[[nodiscard]] const std::vector<ExportFormat>& exportFormats();
// Whether the format can write this plan.
[[nodiscard]] bool formatApplies(const ExportFormat& format, const Plan& plan);
// "geojson, gpkg, ...": every key, in menu order, for messages.
[[nodiscard]] std::string exportFormatKeys();
// Batch mode's file name for the format: plan.geojson, or robot_<n>.plan for a per-robot format.
[[nodiscard]] std::string batchOutputName(const ExportFormat& format);
// The format with this key, or nullptr.
[[nodiscard]] const ExportFormat* findExportFormat(const std::string& key);
// Batch mode's name for a robot's file of a per-robot format in a plan of `robots`: robot_<n>.<extension>, n
// its number from 1 as in the "robot" fields of plan.geojson and report.json, padded to the width of the
// last (robot_02.csv of 12).
[[nodiscard]] std::string robotFileName(int robot, int robots, const ExportFormat& format);

} // namespace mcpp::io
