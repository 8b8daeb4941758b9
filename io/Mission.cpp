#include "io/Mission.hpp"

#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/LegendReader.hpp"
#include "io/internal/TextFiles.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace mcpp::io {

namespace {

using internal::JsonValue;

constexpr const char* formatName = "mcpp-mission";
constexpr int currentVersion = 1;

std::string typeName(const QJsonValue& value) {
    switch (value.type()) {
    case QJsonValue::Null:
        return "null";
    case QJsonValue::Bool:
        return "a boolean";
    case QJsonValue::Double:
        return "a number";
    case QJsonValue::String:
        return "a string";
    case QJsonValue::Array:
        return "an array";
    case QJsonValue::Object:
        return "an object";
    case QJsonValue::Undefined:
        break;
    }
    return "nothing";
}

// Reads one mission file, stopping at the first problem with a message "<file>: <json path>: <what>".
class MissionReader {
  public:
    explicit MissionReader(std::string file) : file_(std::move(file)) {}

    [[nodiscard]] bool failed() const { return !error_.empty(); }
    [[nodiscard]] const std::string& error() const { return error_; }

    bool fail(const std::string& path, const std::string& what) {
        if (error_.empty())
            error_ = file_ + ": " + path + ": " + what;
        return false;
    }
    bool wrongType(const std::string& path, const QJsonValue& value, const std::string& expected) {
        return fail(path, "expected " + expected + ", found " + typeName(value));
    }

    bool onlyKeys(const QJsonObject& object, const std::string& path, const std::set<std::string>& allowed) {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const std::string key = it.key().toStdString();
            if (allowed.count(key) == 0)
                return fail(join(path, key), "unknown key");
        }
        return true;
    }

    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }
    static std::string index(const std::string& path, qsizetype position) {
        return path + "[" + std::to_string(position) + "]";
    }

    bool object(const QJsonValue& value, const std::string& path, QJsonObject& out) {
        if (!value.isObject())
            return wrongType(path, value, "an object");
        out = value.toObject();
        return true;
    }
    bool string(const QJsonValue& value, const std::string& path, std::string& out) {
        if (!value.isString())
            return wrongType(path, value, "a string");
        out = value.toString().toStdString();
        return true;
    }
    bool boolean(const QJsonValue& value, const std::string& path, bool& out) {
        if (!value.isBool())
            return wrongType(path, value, "true or false");
        out = value.toBool();
        return true;
    }
    bool number(const QJsonValue& value, const std::string& path, double& out) {
        if (!value.isDouble() || !std::isfinite(value.toDouble()))
            return wrongType(path, value, "a number");
        out = value.toDouble();
        return true;
    }
    bool integer(const QJsonValue& value, const std::string& path, int& out) {
        const double number = value.toDouble();
        if (!value.isDouble() || number != std::floor(number) || std::abs(number) > 2147483647.0) {
            return wrongType(path, value, "an integer");
        }
        out = static_cast<int>(number);
        return true;
    }

    // Optional members: absent leaves `out` as it is.
    template <typename T, typename Read>
    bool optional(const QJsonObject& object, const std::string& path, const char* key, T& out, Read read) {
        const QJsonValue value = object.value(QLatin1String(key));
        if (value.isUndefined())
            return true;
        return (this->*read)(value, join(path, key), out);
    }
    template <typename T, typename Read>
    bool required(const QJsonObject& object, const std::string& path, const char* key, T& out, Read read) {
        const QJsonValue value = object.value(QLatin1String(key));
        if (value.isUndefined())
            return fail(join(path, key), "missing");
        return (this->*read)(value, join(path, key), out);
    }

  private:
    std::string file_;
    std::string error_;
};

bool readClass(MissionReader& reader, const QJsonValue& value, const std::string& path,
               LandCoverClass& entry) {
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path, {"value", "name", "color", "speed_mps", "fov_m", "passable"}))
        return false;
    int classValue = 0;
    std::string color = "#808080";
    if (!reader.required(object, path, "value", classValue, &MissionReader::integer) ||
        !reader.optional(object, path, "name", entry.name, &MissionReader::string) ||
        !reader.optional(object, path, "color", color, &MissionReader::string) ||
        !reader.required(object, path, "speed_mps", entry.speedMetresPerSecond, &MissionReader::number) ||
        !reader.required(object, path, "fov_m", entry.fieldOfViewMetres, &MissionReader::number) ||
        !reader.optional(object, path, "passable", entry.passable, &MissionReader::boolean)) {
        return false;
    }
    entry.value = classValue;
    const auto rgb = internal::parseColor(color);
    if (!rgb || color.size() != 7)
        return reader.fail(MissionReader::join(path, "color"), "expected a colour \"#rrggbb\"");
    entry.colorRgb = *rgb;
    if (entry.speedMetresPerSecond < 0.0)
        return reader.fail(MissionReader::join(path, "speed_mps"), "must be >= 0");
    return true;
}

bool readClasses(MissionReader& reader, const QJsonValue& value, Mission& mission) {
    const std::string path = "classes";
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path, {"preset", "missing_as_obstacles", "table"}))
        return false;
    if (!reader.optional(object, path, "preset", mission.preset, &MissionReader::string) ||
        !reader.optional(object, path, "missing_as_obstacles", mission.missingClassesAsObstacles,
                         &MissionReader::boolean)) {
        return false;
    }
    if (!mission.preset.empty()) {
        if (auto preset = presetClassTable(mission.preset); !preset)
            return reader.fail("classes.preset", preset.error());
    }
    const QJsonValue table = object.value(QLatin1String("table"));
    if (table.isUndefined())
        return true;
    if (!table.isArray())
        return reader.wrongType("classes.table", table, "an array of classes");
    const QJsonArray rows = table.toArray();
    std::set<std::int32_t> seen;
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const std::string rowPath = MissionReader::index("classes.table", i);
        LandCoverClass entry;
        if (!readClass(reader, rows.at(i), rowPath, entry))
            return false;
        if (!seen.insert(entry.value).second) {
            return reader.fail(rowPath + ".value", "class " + std::to_string(entry.value) + " appears twice");
        }
        mission.classes.set(entry);
    }
    if (const auto problem = mission.classes.validate())
        return reader.fail("classes.table", *problem);
    return true;
}

bool readRobot(MissionReader& reader, const QJsonValue& value, const std::string& path, RobotSpec& robot) {
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path, {"name", "start", "start_crs"}))
        return false;
    if (!reader.optional(object, path, "name", robot.name, &MissionReader::string) ||
        !reader.optional(object, path, "start_crs", robot.startCrs, &MissionReader::string)) {
        return false;
    }
    const QJsonValue start = object.value(QLatin1String("start"));
    const std::string startPath = path + ".start";
    if (start.isUndefined())
        return reader.fail(startPath, "missing");
    const QJsonArray coordinates = start.toArray();
    if (!start.isArray() || coordinates.size() != 2 || !coordinates.at(0).isDouble() ||
        !coordinates.at(1).isDouble() || !std::isfinite(coordinates.at(0).toDouble()) ||
        !std::isfinite(coordinates.at(1).toDouble())) {
        return reader.fail(startPath, "expected an array of two numbers");
    }
    robot.start = {coordinates.at(0).toDouble(), coordinates.at(1).toDouble()};
    if (!robot.startCrs.empty()) {
        internal::QuietGdalErrors quiet;
        if (!internal::spatialReferenceFromDefinition(robot.startCrs)) {
            return reader.fail(path + ".start_crs", "\"" + robot.startCrs + "\" is not a CRS GDAL knows");
        }
    }
    return true;
}

bool readPlanner(MissionReader& reader, const QJsonValue& value, PlannerSettings& settings) {
    const std::string path = "planner";
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path,
                         {"name", "purity_tolerance", "blocked_threshold", "closed_tour",
                          "rebalance_iterations", "snap_starts_to_free_cells"})) {
        return false;
    }
    if (!reader.optional(object, path, "name", settings.planner, &MissionReader::string) ||
        !reader.optional(object, path, "purity_tolerance", settings.purityTolerance,
                         &MissionReader::number) ||
        !reader.optional(object, path, "blocked_threshold", settings.blockedThreshold,
                         &MissionReader::number) ||
        !reader.optional(object, path, "closed_tour", settings.closedTour, &MissionReader::boolean) ||
        !reader.optional(object, path, "rebalance_iterations", settings.rebalanceIterations,
                         &MissionReader::integer) ||
        !reader.optional(object, path, "snap_starts_to_free_cells", settings.snapStartsToFreeCells,
                         &MissionReader::boolean)) {
        return false;
    }
    const auto planners = availablePlanners();
    if (std::find(planners.begin(), planners.end(), settings.planner) == planners.end()) {
        std::string known;
        for (const auto& name : planners)
            known += (known.empty() ? "" : ", ") + name;
        return reader.fail("planner.name",
                           "unknown planner \"" + settings.planner + "\" (available: " + known + ")");
    }
    if (settings.purityTolerance < 0.0 || settings.purityTolerance >= 1.0) {
        return reader.fail("planner.purity_tolerance", "must be in [0, 1)");
    }
    if (settings.blockedThreshold < 0.0 || settings.blockedThreshold > 1.0) {
        return reader.fail("planner.blocked_threshold", "must be in [0, 1]");
    }
    if (settings.rebalanceIterations < 0)
        return reader.fail("planner.rebalance_iterations", "must be >= 0");
    return true;
}

bool readExports(MissionReader& reader, const QJsonValue& value, ExportSettings& exports) {
    const std::string path = "exports";
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path, {"altitude_m", "cruise_speed_mps", "merge_collinear"}))
        return false;
    if (!reader.optional(object, path, "altitude_m", exports.altitudeMetres, &MissionReader::number) ||
        !reader.optional(object, path, "cruise_speed_mps", exports.cruiseSpeedMetresPerSecond,
                         &MissionReader::number) ||
        !reader.optional(object, path, "merge_collinear", exports.mergeCollinear, &MissionReader::boolean)) {
        return false;
    }
    if (exports.cruiseSpeedMetresPerSecond < 0.0)
        return reader.fail("exports.cruise_speed_mps", "must be >= 0");
    return true;
}

std::string lineAndColumn(const std::string& text, qsizetype offset) {
    int line = 1;
    int column = 1;
    for (qsizetype i = 0; i < offset && i < static_cast<qsizetype>(text.size()); ++i) {
        if (text[static_cast<std::size_t>(i)] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

} // namespace

Result<Mission> loadMission(const std::string& path) {
    auto contents = internal::readWholeFile(path);
    if (!contents)
        return Result<Mission>::failure(contents.error());
    const std::string& text = contents.value();
    if (internal::trimmed(text).empty())
        return Result<Mission>::failure(path + ": file is empty");
    QJsonParseError parseError;
    const QJsonDocument document =
        QJsonDocument::fromJson(QByteArray(text.data(), static_cast<qsizetype>(text.size())), &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        return Result<Mission>::failure(path + ": " + lineAndColumn(text, parseError.offset) +
                                        ": invalid JSON: " + parseError.errorString().toStdString());
    }
    MissionReader reader(path);
    if (!document.isObject()) {
        return Result<Mission>::failure(path + ": expected a JSON object with \"format\": \"" + formatName +
                                        "\"");
    }
    const QJsonObject root = document.object();
    Mission mission;
    std::string format;
    const auto fail = [&]() { return Result<Mission>::failure(reader.error()); };
    if (!reader.required(root, "", "format", format, &MissionReader::string))
        return fail();
    if (format != formatName) {
        reader.fail("format", "expected \"" + std::string(formatName) + "\", found \"" + format + "\"");
        return fail();
    }
    if (!reader.required(root, "", "version", mission.version, &MissionReader::integer))
        return fail();
    if (mission.version < 1 || mission.version > currentVersion) {
        reader.fail("version", "version " + std::to_string(mission.version) +
                                   " is not supported (this mcpp reads version " +
                                   std::to_string(currentVersion) + ")");
        return fail();
    }
    if (!reader.onlyKeys(root, "",
                         {"format", "version", "raster", "classes", "robots", "planner", "exports"}))
        return fail();

    QJsonObject raster;
    const QJsonValue rasterValue = root.value(QLatin1String("raster"));
    if (rasterValue.isUndefined()) {
        reader.fail("raster", "missing");
        return fail();
    }
    if (!reader.object(rasterValue, "raster", raster) ||
        !reader.onlyKeys(raster, "raster", {"path", "band"}) ||
        !reader.required(raster, "raster", "path", mission.rasterPath, &MissionReader::string) ||
        !reader.optional(raster, "raster", "band", mission.band, &MissionReader::integer)) {
        return fail();
    }
    if (mission.rasterPath.empty())
        reader.fail("raster.path", "must name the land-cover raster");
    if (mission.band < 1)
        reader.fail("raster.band", "must be >= 1");
    if (reader.failed())
        return fail();

    if (const QJsonValue classes = root.value(QLatin1String("classes")); !classes.isUndefined()) {
        if (!readClasses(reader, classes, mission))
            return fail();
    }

    const QJsonValue robots = root.value(QLatin1String("robots"));
    if (robots.isUndefined()) {
        reader.fail("robots", "missing");
        return fail();
    }
    if (!robots.isArray()) {
        reader.wrongType("robots", robots, "an array of robots");
        return fail();
    }
    const QJsonArray robotArray = robots.toArray();
    if (robotArray.isEmpty()) {
        reader.fail("robots", "expected at least one robot");
        return fail();
    }
    for (qsizetype i = 0; i < robotArray.size(); ++i) {
        RobotSpec robot;
        if (!readRobot(reader, robotArray.at(i), MissionReader::index("robots", i), robot))
            return fail();
        mission.robots.push_back(robot);
    }

    if (const QJsonValue planner = root.value(QLatin1String("planner")); !planner.isUndefined()) {
        if (!readPlanner(reader, planner, mission.settings))
            return fail();
    }
    if (const QJsonValue exports = root.value(QLatin1String("exports")); !exports.isUndefined()) {
        if (!readExports(reader, exports, mission.exports))
            return fail();
    }
    return mission;
}

std::string missionToJson(const Mission& mission) {
    JsonValue root = JsonValue::object();
    root.add("format", formatName);
    root.add("version", currentVersion);
    JsonValue& raster = root.add("raster", JsonValue::object());
    raster.add("path", mission.rasterPath);
    raster.add("band", mission.band);

    JsonValue& classes = root.add("classes", JsonValue::object());
    classes.add("preset", mission.preset);
    classes.add("missing_as_obstacles", mission.missingClassesAsObstacles);
    JsonValue& table = classes.add("table", JsonValue::array());
    for (const LandCoverClass& entry : mission.classes.classes()) {
        JsonValue& row = table.push(JsonValue::object());
        row.add("value", static_cast<int>(entry.value));
        row.add("name", entry.name);
        row.add("color", internal::formatColor(entry.colorRgb));
        row.add("speed_mps", entry.speedMetresPerSecond);
        row.add("fov_m", entry.fieldOfViewMetres);
        row.add("passable", entry.passable);
    }

    JsonValue& robots = root.add("robots", JsonValue::array());
    for (const RobotSpec& robot : mission.robots) {
        JsonValue& item = robots.push(JsonValue::object());
        item.add("name", robot.name);
        JsonValue& start = item.add("start", JsonValue::array());
        start.push(robot.start.x);
        start.push(robot.start.y);
        if (!robot.startCrs.empty())
            item.add("start_crs", robot.startCrs);
    }

    JsonValue& planner = root.add("planner", JsonValue::object());
    planner.add("name", mission.settings.planner);
    planner.add("purity_tolerance", mission.settings.purityTolerance);
    planner.add("blocked_threshold", mission.settings.blockedThreshold);
    planner.add("closed_tour", mission.settings.closedTour);
    planner.add("rebalance_iterations", mission.settings.rebalanceIterations);
    planner.add("snap_starts_to_free_cells", mission.settings.snapStartsToFreeCells);

    JsonValue& exports = root.add("exports", JsonValue::object());
    exports.add("altitude_m", mission.exports.altitudeMetres);
    exports.add("cruise_speed_mps", mission.exports.cruiseSpeedMetresPerSecond);
    exports.add("merge_collinear", mission.exports.mergeCollinear);
    return root.toText();
}

Status saveMission(const Mission& mission, const std::string& path) {
    if (mission.version != currentVersion) {
        return Status::failure(path + ": cannot write mission version " + std::to_string(mission.version) +
                               " (this mcpp writes " + std::to_string(currentVersion) + ")");
    }
    return internal::writeFileAtomically(path, missionToJson(mission));
}

Result<MapPoint> robotStartInPlanningFrame(const RobotSpec& robot, const GeoReference& georeference) {
    if (robot.startCrs.empty())
        return georeference.fromCrsUnits(robot.start);
    auto start = georeference.fromCrs(robot.startCrs, robot.start);
    if (!start)
        return Result<MapPoint>::failure("robot \"" + robot.name + "\" start: " + start.error());
    return start;
}

std::string resolveRasterPath(const Mission& mission, const std::string& missionPath) {
    namespace fs = std::filesystem;
    const fs::path raster(mission.rasterPath);
    if (raster.empty() || raster.is_absolute() || mission.rasterPath.rfind("/vsi", 0) == 0)
        return mission.rasterPath;
    return (fs::path(missionPath).parent_path() / raster).lexically_normal().string();
}

} // namespace mcpp::io
