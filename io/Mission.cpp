#include "io/Mission.hpp"

#include "core/decomposition/FieldOfViewRounding.hpp"
#include "core/model/BatteryEndurance.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/NameSuggestion.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/SpeedEventCheck.hpp"
#include "core/parameters/NumberText.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/AutopilotMission.hpp"
#include "io/ClassTableSources.hpp"
#include "io/GeoReference.hpp"
#include "io/LoadedRaster.hpp"
#include "io/internal/ClassTableJson.hpp"
#include "io/internal/EventsJson.hpp"
#include "io/internal/GdalSupport.hpp"
#include "io/internal/JsonValue.hpp"
#include "io/internal/LegendReader.hpp"
#include "io/internal/ProductRecognition.hpp"
#include "io/internal/TextFiles.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string_view>

namespace mcpp::io {

namespace {

// Seconds too few for a flight but a likely number of minutes (25 for 25 min): what to write for that many
// minutes, after `lead`; empty otherwise.
std::string minutesMeantHint(double seconds, const std::string& lead) {
    if (!(seconds >= 1.0) || !(seconds < 60.0))
        return {};
    return lead + formatQuantity(60.0 * seconds) + " for " + formatDuration(60.0 * seconds);
}

using internal::JsonValue;

constexpr const char* formatName = "mcpp-mission";
constexpr int currentVersion = 2;

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

    // "\"classes\", as \"classes\": {\"fov_m\": ...}"; a home ending in [] is an array of objects, each
    // holding the key ("robots[]": each robot). Two homes, "exports|robots[]": the key is every robot's in
    // the first, an object, and one robot's own in the second, an array of robots.
    static std::string placeOf(const std::string& home, const std::string& key) {
        if (const std::size_t bar = home.find('|'); bar != std::string::npos) {
            const std::string array = home.substr(bar + 1, home.size() - bar - 3); // "robots[]": "robots"
            return placeOf(home.substr(0, bar), key) + " for every robot, or in an entry of \"" + array +
                   "\", as \"" + array + "\": [{\"" + key + "\": ...}], for that robot alone";
        }
        if (home.size() > 2 && home.ends_with("[]")) {
            const std::string array = home.substr(0, home.size() - 2);
            return "each of \"" + array + "\", as \"" + array + "\": [{\"" + key + "\": ...}]";
        }
        return "\"" + home + "\", as \"" + home + "\": {\"" + key + "\": ...}";
    }

    // belongsIn: keys of an inner object (e.g. "preset" of "classes"), named there when given out of place.
    bool onlyKeys(const QJsonObject& object, const std::string& path, const std::set<std::string>& allowed,
                  const std::map<std::string, std::string>& belongsIn = {}) {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const std::string key = it.key().toStdString();
            if (allowed.count(key) == 0) {
                if (const auto home = belongsIn.find(key); home != belongsIn.end())
                    return fail(join(path, key), "unknown key " +
                                                     std::string(path.empty() ? "at the top level" : "here") +
                                                     ": it belongs in " + placeOf(home->second, key));
                auto meant = commonNameFor(key, allowed);
                if (!meant)
                    meant = closestName(key, {allowed.begin(), allowed.end()});
                return fail(join(path, key),
                            "unknown key" + (meant ? ": did you mean \"" + *meant + "\"?" : std::string()));
            }
        }
        return true;
    }

    // What other tools call a key that is ours under another name ("position" for a robot's "start").
    static std::optional<std::string> commonNameFor(const std::string& key,
                                                    const std::set<std::string>& allowed) {
        static const std::map<std::string, std::string> ours = {
            {"position", "start"}, {"location", "start"}, {"coordinates", "start"}, {"coords", "start"},
            {"pos", "start"},      {"xy", "start"},       {"origin", "start"},      {"home", "start"},
            {"robot", "robots"},   {"fleet", "robots"},   {"vehicles", "robots"},   {"drones", "robots"}};
        const auto found = ours.find(lowercase(key));
        if (found == ours.end() || allowed.count(found->second) == 0)
            return std::nullopt;
        return found->second;
    }

    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }
    static std::string index(const std::string& path, qsizetype position) {
        return path + "[" + std::to_string(position) + "]";
    }

    // The unit a key's name ends in ("altitude_m": metres) and the ways users write it; none for others.
    struct KeyUnit {
        std::string name;
        std::set<std::string> spellings; // lower case
    };
    static KeyUnit unitOfKey(std::string_view path) {
        if (path.ends_with("_mps"))
            return {"metres per second", {"m/s", "mps", "metres per second", "meters per second"}};
        if (path.ends_with("_m"))
            return {"metres", {"m", "metre", "metres", "meter", "meters"}};
        if (path.ends_with("_s"))
            return {"seconds", {"s", "sec", "secs", "second", "seconds"}};
        return {};
    }

    // The number a text begins with ("+48", "12.5") and what follows it, trimmed and in lower case.
    static std::optional<std::pair<double, std::string>> leadingNumber(std::string_view text) {
        text = trimmedText(text);
        if (text.starts_with('+'))
            text.remove_prefix(1);
        double number = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
        if (error != std::errc() || !std::isfinite(number))
            return std::nullopt;
        std::string rest(
            trimmedText(std::string_view(end, static_cast<std::size_t>(text.data() + text.size() - end))));
        std::transform(rest.begin(), rest.end(), rest.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        return std::pair{number, rest};
    }

    // A number written as text, with or without a unit ("48 m", "20 min"): what to write instead, in the
    // unit the key's name ends in; none for other text.
    static std::optional<std::string> numberInTextHint(const std::string& path, const std::string& text) {
        const KeyUnit unit = unitOfKey(path);
        const std::string expected = "expected a number" +
                                     (unit.name.empty() ? std::string() : " of " + unit.name) +
                                     ", found the text \"" + text + "\": ";
        if (unit.name == "seconds")
            if (const auto seconds = parseDuration(text)) {
                // A flight time of a few seconds, a bare number, is minutes: the seconds would be refused.
                const bool bare = leadingNumber(text) && leadingNumber(text)->second.empty();
                const std::string minutes =
                    bare && path.ends_with("flight_time_s") ? minutesMeantHint(*seconds, "write ") : "";
                return expected + (minutes.empty() ? "write " + formatQuantity(*seconds) + " for " +
                                                         formatDuration(*seconds)
                                                   : minutes);
            }
        const auto number = leadingNumber(text);
        if (!number)
            return std::nullopt;
        const auto& [value, rest] = *number;
        if (!rest.empty() && unit.spellings.count(rest) == 0)
            return expected + (unit.name.empty() ? "give it as a number, without quotes"
                                                 : "give it in " + unit.name + ", without quotes or a unit");
        return expected + "write " + formatQuantity(value, 12) +
               (unit.name.empty() ? " without quotes"
                                  : ", without quotes or a unit (the key's name gives it)");
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
        if (value.isString()) {
            if (const auto hint = numberInTextHint(path, value.toString().toStdString()))
                return fail(path, *hint);
        }
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

    bool vehicleType(const QJsonValue& value, const std::string& path, VehicleType& out) {
        std::string key;
        if (!string(value, path, key))
            return false;
        const auto type = vehicleTypeFromKey(key);
        if (!type)
            return fail(path, "\"" + key + "\" is not a vehicle type (rover, multirotor, fixed-wing)");
        out = *type;
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
    bool optional(const QJsonObject& object, const std::string& path, const char* key, std::optional<T>& out,
                  Read read) {
        const QJsonValue value = object.value(QLatin1String(key));
        if (value.isUndefined())
            return true;
        T readValue{};
        if (!(this->*read)(value, join(path, key), readValue))
            return false;
        out = readValue;
        return true;
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

// A field a class row must give unless the preset has a row for its value to take it from.
bool requiredUnlessPreset(MissionReader& reader, const QJsonObject& object, const std::string& path,
                          const char* key, double& out, const std::string& presetName, bool inPreset,
                          std::int32_t classValue) {
    if (inPreset || object.contains(QLatin1String(key)))
        return reader.optional(object, path, key, out, &MissionReader::number);
    return reader.fail(
        MissionReader::join(path, key),
        presetName.empty()
            ? std::string("missing: a class row gives it unless classes.preset names a preset with a row "
                          "for the class's value")
            : "missing, and the preset " + presetName + " has no class " + std::to_string(classValue) +
                  " to take it from");
}

// A class row; where the preset has a row for its value, the fields it leaves out are the preset's.
bool readClass(MissionReader& reader, const QJsonValue& value, const std::string& path,
               const std::string& presetName, const ClassTable* preset, LandCoverClass& entry) {
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(
            object, path,
            {"value", "name", "color", "speed_mps", "fov_m", "passable", "detection_probability"}))
        return false;
    int classValue = 0;
    if (!reader.required(object, path, "value", classValue, &MissionReader::integer))
        return false;
    const LandCoverClass* presetRow = preset != nullptr ? preset->find(classValue) : nullptr;
    if (presetRow != nullptr)
        entry = *presetRow;
    std::optional<std::string> color;
    if (!reader.optional(object, path, "name", entry.name, &MissionReader::string) ||
        !reader.optional(object, path, "color", color, &MissionReader::string) ||
        !requiredUnlessPreset(reader, object, path, "speed_mps", entry.speedMetresPerSecond, presetName,
                              presetRow != nullptr, classValue) ||
        !requiredUnlessPreset(reader, object, path, "fov_m", entry.fieldOfViewMetres, presetName,
                              presetRow != nullptr, classValue) ||
        !reader.optional(object, path, "passable", entry.passable, &MissionReader::boolean)) {
        return false;
    }
    entry.value = classValue;
    // A speed given to a class the preset makes an obstacle asks to cross it.
    if (presetRow != nullptr && !presetRow->passable && entry.speedMetresPerSecond > 0.0 &&
        object.contains(QLatin1String("speed_mps")) && !object.contains(QLatin1String("passable")))
        entry.passable = true;
    // Ticking passable alone beside the preset's obstacle leaves its speed of 0: still an obstacle. (The
    // window writes whole rows, so a file it saved never meets this.)
    if (presetRow != nullptr && entry.passable && object.contains(QLatin1String("passable")) &&
        !object.contains(QLatin1String("speed_mps")) && !(entry.speedMetresPerSecond > 0.0))
        return reader.fail(MissionReader::join(path, "passable"),
                           "true, but the preset " + presetName + " gives class " +
                               std::to_string(classValue) +
                               (entry.name.empty() ? std::string() : " (" + entry.name + ")") +
                               " a speed of " + formatQuantity(entry.speedMetresPerSecond) +
                               " m/s, which keeps it an obstacle: give speed_mps too");
    if (color) {
        const auto rgb = internal::parseColor(*color);
        if (!rgb || color->size() != 7)
            return reader.fail(MissionReader::join(path, "color"), "expected a colour \"#rrggbb\"");
        entry.colorRgb = *rgb;
    }
    if (entry.speedMetresPerSecond < 0.0)
        return reader.fail(MissionReader::join(path, "speed_mps"), "must be >= 0");
    if (object.contains("detection_probability")) {
        double probability = 0.0;
        if (!reader.required(object, path, "detection_probability", probability, &MissionReader::number))
            return false;
        if (!(probability >= 0.0 && probability <= 1.0))
            return reader.fail(MissionReader::join(path, "detection_probability"),
                               "must be a probability from 0 to 1, got " +
                                   internal::formatShortest(probability));
        entry.detectionProbability = probability;
    }
    return true;
}

bool readClasses(MissionReader& reader, const QJsonValue& value, Mission& mission) {
    const std::string path = "classes";
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path, {"preset", "missing_as_obstacles", "fov_m", "table"}))
        return false;
    if (!reader.optional(object, path, "preset", mission.preset, &MissionReader::string) ||
        !reader.optional(object, path, "missing_as_obstacles", mission.missingClassesAsObstacles,
                         &MissionReader::boolean) ||
        !reader.optional(object, path, "fov_m", mission.fieldOfViewMetres, &MissionReader::number)) {
        return false;
    }
    if (mission.fieldOfViewMetres &&
        !(*mission.fieldOfViewMetres > 0.0 && *mission.fieldOfViewMetres <= kMaximumFieldOfViewMetres))
        return reader.fail("classes.fov_m", "must be a field of view of more than 0 m, up to " +
                                                formatQuantity(kMaximumFieldOfViewMetres) + " m, not " +
                                                internal::formatShortest(*mission.fieldOfViewMetres));
    std::optional<ClassTable> preset;
    if (!mission.preset.empty()) {
        auto named = presetClassTable(mission.preset);
        if (!named)
            return reader.fail("classes.preset", named.error());
        preset = std::move(named.value());
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
        if (!readClass(reader, rows.at(i), rowPath, mission.preset, preset ? &*preset : nullptr, entry))
            return false;
        if (!rows.at(i).toObject().contains(QLatin1String("color")))
            mission.classesWithoutColour.insert(entry.value);
        if (!seen.insert(entry.value).second) {
            return reader.fail(rowPath + ".value", "class " + std::to_string(entry.value) + " appears twice");
        }
        mission.classes.set(entry);
    }
    if (const auto problem = mission.classes.validate())
        return reader.fail("classes.table", *problem);
    return true;
}

// The autopilot settings a robot or the exports may give; absent ones stay unset.
bool readVehicle(MissionReader& reader, const QJsonObject& object, const std::string& path,
                 VehicleOverrides& vehicle) {
    if (!reader.optional(object, path, "vehicle", vehicle.type, &MissionReader::vehicleType) ||
        !reader.optional(object, path, "altitude_m", vehicle.altitudeMetres, &MissionReader::number) ||
        !reader.optional(object, path, "cruise_speed_mps", vehicle.cruiseSpeedMetresPerSecond,
                         &MissionReader::number) ||
        !reader.optional(object, path, "max_waypoints", vehicle.maxWaypoints, &MissionReader::integer) ||
        !reader.optional(object, path, "flight_time_s", vehicle.flightTimeSeconds, &MissionReader::number) ||
        !reader.optional(object, path, "turnaround_s", vehicle.turnaroundSeconds, &MissionReader::number) ||
        !reader.optional(object, path, "camera_trigger_m", vehicle.cameraTriggerMetres,
                         &MissionReader::number)) {
        return false;
    }
    if (vehicle.altitudeMetres && (*vehicle.altitudeMetres < 0.0 || *vehicle.altitudeMetres > 10000.0))
        return reader.fail(MissionReader::join(path, "altitude_m"), "must be between 0 and 10000 m");
    if (vehicle.cruiseSpeedMetresPerSecond &&
        (*vehicle.cruiseSpeedMetresPerSecond < 0.0 || *vehicle.cruiseSpeedMetresPerSecond > 1000.0)) {
        return reader.fail(MissionReader::join(path, "cruise_speed_mps"),
                           "must be between 0 (land-cover speeds) and 1000 m/s");
    }
    if (vehicle.maxWaypoints && !isWorkableItemLimit(*vehicle.maxWaypoints)) {
        return reader.fail(MissionReader::join(path, "max_waypoints"),
                           "must be 0 (no limit) or at least " + std::to_string(minimumMaxWaypoints) +
                               " mission items, not " + std::to_string(*vehicle.maxWaypoints));
    }
    if (vehicle.flightTimeSeconds)
        if (const auto problem = flightTimeProblem(*vehicle.flightTimeSeconds))
            return reader.fail(MissionReader::join(path, "flight_time_s"),
                               *problem + minutesMeantHint(*vehicle.flightTimeSeconds, ": write "));
    if (vehicle.turnaroundSeconds)
        if (const auto problem = turnaroundProblem(*vehicle.turnaroundSeconds))
            return reader.fail(MissionReader::join(path, "turnaround_s"), *problem);
    if (vehicle.cameraTriggerMetres)
        if (const auto problem = cameraTriggerProblem(*vehicle.cameraTriggerMetres))
            return reader.fail(MissionReader::join(path, "camera_trigger_m"), *problem);
    return true;
}

void writeVehicle(JsonValue& object, const VehicleOverrides& vehicle) {
    if (vehicle.type)
        object.add("vehicle", vehicleTypeKey(*vehicle.type));
    if (vehicle.altitudeMetres)
        object.add("altitude_m", *vehicle.altitudeMetres);
    if (vehicle.cruiseSpeedMetresPerSecond)
        object.add("cruise_speed_mps", *vehicle.cruiseSpeedMetresPerSecond);
    if (vehicle.maxWaypoints)
        object.add("max_waypoints", *vehicle.maxWaypoints);
    if (vehicle.flightTimeSeconds)
        object.add("flight_time_s", *vehicle.flightTimeSeconds);
    if (vehicle.turnaroundSeconds)
        object.add("turnaround_s", *vehicle.turnaroundSeconds);
    if (vehicle.cameraTriggerMetres)
        object.add("camera_trigger_m", *vehicle.cameraTriggerMetres);
}

bool readEvent(MissionReader& reader, const QJsonValue& value, const std::string& path,
               std::size_t robotCount, SpeedEvent& event) {
    QJsonObject object;
    if (!reader.object(value, path, object) ||
        !reader.onlyKeys(object, path, {"time_s", "robot", "speed_factor"}) ||
        !reader.required(object, path, "time_s", event.timeSeconds, &MissionReader::number) ||
        !reader.required(object, path, "robot", event.robot, &MissionReader::integer) ||
        !reader.required(object, path, "speed_factor", event.speedFactor, &MissionReader::number))
        return false;
    if (const auto wrong = speedEventProblem(event, robotCount))
        return reader.fail(MissionReader::join(path, wrong->field), wrong->detail);
    return true;
}

bool readEvents(MissionReader& reader, const QJsonValue& value, Mission& mission) {
    if (!value.isArray())
        return reader.wrongType("events", value, "an array of events");
    const QJsonArray events = value.toArray();
    for (qsizetype i = 0; i < events.size(); ++i) {
        SpeedEvent event;
        if (!readEvent(reader, events.at(i), MissionReader::index("events", i), mission.robots.size(), event))
            return false;
        mission.events.push_back(event);
    }
    return true;
}

// A point as [x, y], two finite numbers.
bool readPoint(MissionReader& reader, const QJsonObject& object, const std::string& path, const char* key,
               MapPoint& point) {
    const QJsonValue value = object.value(QLatin1String(key));
    const QJsonArray coordinates = value.toArray();
    if (!value.isArray() || coordinates.size() != 2 || !coordinates.at(0).isDouble() ||
        !coordinates.at(1).isDouble() || !std::isfinite(coordinates.at(0).toDouble()) ||
        !std::isfinite(coordinates.at(1).toDouble())) {
        return reader.fail(MissionReader::join(path, key), "expected an array of two numbers");
    }
    point = {coordinates.at(0).toDouble(), coordinates.at(1).toDouble()};
    return true;
}

bool readRobot(MissionReader& reader, const QJsonValue& value, const std::string& path, RobotSpec& robot) {
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path,
                         {"name", "start", "start_crs", "vehicle", "altitude_m", "cruise_speed_mps",
                          "max_waypoints", "flight_time_s", "turnaround_s", "camera_trigger_m", "battery_s",
                          "charger"}))
        return false;
    if (!reader.optional(object, path, "battery_s", robot.batterySeconds, &MissionReader::number))
        return false;
    if (robot.batterySeconds)
        if (const auto problem = BatteryEndurance::problem(*robot.batterySeconds))
            return reader.fail(MissionReader::join(path, "battery_s"), *problem);
    if (!reader.optional(object, path, "name", robot.name, &MissionReader::string) ||
        !reader.optional(object, path, "start_crs", robot.startCrs, &MissionReader::string) ||
        !readVehicle(reader, object, path, robot.vehicle)) {
        return false;
    }
    if (object.value(QLatin1String("start")).isUndefined())
        return reader.fail(path + ".start", "missing");
    if (!readPoint(reader, object, path, "start", robot.start))
        return false;
    if (!object.value(QLatin1String("charger")).isUndefined() &&
        !readPoint(reader, object, path, "charger", robot.charger.emplace()))
        return false;
    if (!robot.startCrs.empty()) {
        internal::QuietGdalErrors quiet;
        if (!internal::spatialReferenceFromDefinition(robot.startCrs)) {
            return reader.fail(path + ".start_crs", "\"" + robot.startCrs + "\" is not a CRS GDAL knows" +
                                                        epsgSpellingHint(robot.startCrs));
        }
    }
    return true;
}

// One parameter from JSON, typed by its declaration.
bool readParameter(MissionReader& reader, const QJsonValue& value, const std::string& path,
                   const ParameterSpec& spec, ParameterValues& values) {
    ParameterValue parameter;
    switch (spec.type) {
    case ParameterType::Boolean:
        if (!value.isBool())
            return reader.wrongType(path, value, "true or false");
        parameter = value.toBool();
        break;
    case ParameterType::Integer: {
        int whole = 0;
        if (!reader.integer(value, path, whole))
            return false;
        parameter = whole;
        break;
    }
    case ParameterType::Real: {
        double real = 0.0;
        if (!spec.automatic.empty() && value.isString()) {
            if (value.toString().compare(QString::fromStdString(spec.automatic), Qt::CaseInsensitive) != 0)
                return reader.fail(path, "expected " + spec.expected() + ", got \"" +
                                             value.toString().toStdString() + "\"");
            real = automaticParameterValue;
        } else if (!reader.number(value, path, real))
            return false;
        parameter = real;
        break;
    }
    case ParameterType::Choice: {
        std::string word;
        if (!reader.string(value, path, word))
            return false;
        parameter = word;
        break;
    }
    }
    if (const auto problem = spec.problemWith(parameter))
        return reader.fail(path, *problem);
    values.set(spec.key, parameter);
    return true;
}

// Version 2: {"name": ..., "parameters": {...}}. Version 1 kept mcpp-mlct's parameters beside the name.
bool readPlanner(MissionReader& reader, const QJsonValue& value, int version, PlannerChoice& choice) {
    const std::string path = "planner";
    QJsonObject object;
    if (!reader.object(value, path, object) ||
        !reader.optional(object, path, "name", choice.planner, &MissionReader::string))
        return false;
    const auto description = findPlannerDescription(choice.planner);
    if (!description)
        return reader.fail("planner.name", unknownPlannerMessage(choice.planner));
    QJsonObject given = object;
    std::string parametersPath = path;
    if (version >= 2) {
        if (!reader.onlyKeys(object, path, {"name", "parameters"}))
            return false;
        given = {};
        if (const QJsonValue parameters = object.value(QLatin1String("parameters"));
            !parameters.isUndefined())
            if (!reader.object(parameters, "planner.parameters", given))
                return false;
        parametersPath = "planner.parameters";
    }
    ParameterValues values;
    for (auto it = given.begin(); it != given.end(); ++it) {
        const std::string key = it.key().toStdString();
        if (version < 2 && key == "name")
            continue;
        const std::string keyPath = MissionReader::join(parametersPath, key);
        const ParameterSpec* spec = findParameter(description->parameters, key);
        if (spec == nullptr)
            return reader.fail(keyPath, "unknown parameter of planner " + choice.planner + " " +
                                            knownParametersNote(key, description->parameters));
        if (!readParameter(reader, it.value(), keyPath, *spec, values))
            return false;
    }
    choice.parameters = resolveParameters(description->parameters, values);
    return true;
}

bool readExports(MissionReader& reader, const QJsonValue& value, ExportSettings& exports) {
    const std::string path = "exports";
    QJsonObject object;
    if (!reader.object(value, path, object))
        return false;
    if (!reader.onlyKeys(object, path,
                         {"vehicle", "altitude_m", "cruise_speed_mps", "max_waypoints", "flight_time_s",
                          "turnaround_s", "camera_trigger_m", "speed_tolerance",
                          "speed_changes_at_turns_only", "merge_collinear", "dense_paths", "cell_polygons"}))
        return false;
    VehicleOverrides vehicle;
    if (!readVehicle(reader, object, path, vehicle))
        return false;
    exports.vehicle = vehicle.over(exports.vehicle);
    if (!reader.optional(object, path, "speed_tolerance", exports.speedTolerance, &MissionReader::number) ||
        !reader.optional(object, path, "speed_changes_at_turns_only", exports.speedChangesAtTurnsOnly,
                         &MissionReader::boolean) ||
        !reader.optional(object, path, "merge_collinear", exports.mergeCollinear, &MissionReader::boolean) ||
        !reader.optional(object, path, "dense_paths", exports.densePaths, &MissionReader::boolean) ||
        !reader.optional(object, path, "cell_polygons", exports.cellPolygons, &MissionReader::boolean)) {
        return false;
    }
    if (exports.speedTolerance < 0.0 || exports.speedTolerance >= 1.0)
        return reader.fail("exports.speed_tolerance",
                           "must be from 0 (every change) up to, not including, 1");
    return true;
}

JsonValue jsonOf(const ParameterValue& value) {
    if (const auto* flag = std::get_if<bool>(&value))
        return JsonValue(*flag);
    if (const auto* whole = std::get_if<int>(&value))
        return JsonValue(*whole);
    if (const auto* real = std::get_if<double>(&value))
        return JsonValue(*real);
    return JsonValue(std::get<std::string>(value));
}

// The planner's parameters in the order it declares them (then any others, by key), for a readable file.
std::vector<std::pair<std::string, ParameterValue>> orderedParameters(const PlannerChoice& choice) {
    std::vector<std::pair<std::string, ParameterValue>> ordered;
    if (const auto description = findPlannerDescription(choice.planner))
        for (const ParameterSpec& spec : description->parameters)
            if (const ParameterValue* value = choice.parameters.find(spec.key))
                ordered.emplace_back(spec.key,
                                     spec.isAutomatic(*value) ? ParameterValue(spec.automatic) : *value);
    for (const auto& parameter : choice.parameters.all())
        if (std::none_of(ordered.begin(), ordered.end(),
                         [&](const auto& entry) { return entry.first == parameter.first; }))
            ordered.emplace_back(parameter.first, parameter.second);
    return ordered;
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
    return parseMission(contents.value(), path);
}

Result<Mission> parseMission(const std::string& text, const std::string& path) {
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
    if (!reader.onlyKeys(
            root, "",
            {"format", "version", "raster", "area", "classes", "robots", "events", "planner", "exports"},
            {{"preset", "classes"},
             {"missing_as_obstacles", "classes"},
             {"table", "classes"},
             {"fov_m", "classes"},
             {"start", "robots[]"},
             {"start_crs", "robots[]"},
             {"charger", "robots[]"},
             {"battery_s", "robots[]"},
             {"vehicle", "exports|robots[]"},
             {"altitude_m", "exports|robots[]"},
             {"cruise_speed_mps", "exports|robots[]"},
             {"flight_time_s", "exports|robots[]"},
             {"turnaround_s", "exports|robots[]"},
             {"camera_trigger_m", "exports|robots[]"},
             {"max_waypoints", "exports|robots[]"},
             {"path", "raster"},
             {"band", "raster"},
             {"include", "area"},
             {"exclude", "area"},
             {"parameters", "planner"}}))
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

    if (const QJsonValue area = root.value(QLatin1String("area")); !area.isUndefined()) {
        QJsonObject object;
        if (!reader.object(area, "area", object) ||
            !reader.onlyKeys(object, "area", {"include", "exclude"}) ||
            !reader.optional(object, "area", "include", mission.area.includePath, &MissionReader::string) ||
            !reader.optional(object, "area", "exclude", mission.area.excludePath, &MissionReader::string))
            return fail();
    }
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

    if (const QJsonValue events = root.value(QLatin1String("events")); !events.isUndefined()) {
        if (!readEvents(reader, events, mission))
            return fail();
    }
    if (const QJsonValue planner = root.value(QLatin1String("planner")); !planner.isUndefined()) {
        if (!readPlanner(reader, planner, mission.version, mission.planner))
            return fail();
    }
    if (const QJsonValue exports = root.value(QLatin1String("exports")); !exports.isUndefined()) {
        if (!readExports(reader, exports, mission.exports))
            return fail();
    }
    mission.version = currentVersion; // read in the file's version, held and written in this one
    return mission;
}

std::string missionToJson(const Mission& mission) {
    JsonValue root = JsonValue::object();
    root.add("format", formatName);
    root.add("version", currentVersion);
    JsonValue& raster = root.add("raster", JsonValue::object());
    raster.add("path", mission.rasterPath);
    raster.add("band", mission.band);
    if (!mission.area.empty()) {
        JsonValue& area = root.add("area", JsonValue::object());
        if (!mission.area.includePath.empty())
            area.add("include", mission.area.includePath);
        if (!mission.area.excludePath.empty())
            area.add("exclude", mission.area.excludePath);
    }

    JsonValue& classes = root.add("classes", JsonValue::object());
    classes.add("preset", mission.preset);
    classes.add("missing_as_obstacles", mission.missingClassesAsObstacles);
    if (mission.fieldOfViewMetres)
        classes.add("fov_m", *mission.fieldOfViewMetres);
    internal::addClassRows(classes.add("table", JsonValue::array()), mission.classes,
                           mission.classesWithoutColour);

    JsonValue& robots = root.add("robots", JsonValue::array());
    for (const RobotSpec& robot : mission.robots) {
        JsonValue& item = robots.push(JsonValue::object());
        item.add("name", robot.name);
        JsonValue& start = item.add("start", JsonValue::array());
        start.push(robot.start.x);
        start.push(robot.start.y);
        if (!robot.startCrs.empty())
            item.add("start_crs", robot.startCrs);
        writeVehicle(item, robot.vehicle);
        if (robot.batterySeconds)
            item.add("battery_s", *robot.batterySeconds);
        if (robot.charger) {
            JsonValue& charger = item.add("charger", JsonValue::array());
            charger.push(robot.charger->x);
            charger.push(robot.charger->y);
        }
    }

    if (!mission.events.empty())
        internal::addEvents(root, mission.events);

    JsonValue& planner = root.add("planner", JsonValue::object());
    planner.add("name", mission.planner.planner);
    JsonValue& parameters = planner.add("parameters", JsonValue::object());
    for (const auto& [key, value] : orderedParameters(mission.planner))
        parameters.add(key, jsonOf(value));

    JsonValue& exports = root.add("exports", JsonValue::object());
    exports.add("vehicle", vehicleTypeKey(mission.exports.vehicle.type));
    exports.add("altitude_m", mission.exports.vehicle.altitudeMetres);
    exports.add("cruise_speed_mps", mission.exports.vehicle.cruiseSpeedMetresPerSecond);
    exports.add("max_waypoints", mission.exports.vehicle.maxWaypoints);
    exports.add("flight_time_s", mission.exports.vehicle.flightTimeSeconds);
    exports.add("turnaround_s", mission.exports.vehicle.turnaroundSeconds);
    exports.add("camera_trigger_m", mission.exports.vehicle.cameraTriggerMetres);
    exports.add("speed_tolerance", mission.exports.speedTolerance);
    exports.add("speed_changes_at_turns_only", mission.exports.speedChangesAtTurnsOnly);
    exports.add("merge_collinear", mission.exports.mergeCollinear);
    exports.add("dense_paths", mission.exports.densePaths);
    exports.add("cell_polygons", mission.exports.cellPolygons);
    return root.toText();
}

Status saveMission(const Mission& mission, const std::string& path) {
    if (mission.version != currentVersion) {
        return Status::failure(path + ": cannot write mission version " + std::to_string(mission.version) +
                               " (this mcpp writes " + std::to_string(currentVersion) + ")");
    }
    return internal::writeFileAtomically(path, missionToJson(mission));
}

std::string resolveMissionPath(const std::string& written, const std::string& missionPath) {
    namespace fs = std::filesystem;
    const fs::path path(written);
    if (path.empty() || path.is_absolute() || written.rfind("/vsi", 0) == 0)
        return written;
    return (fs::path(missionPath).parent_path() / path).lexically_normal().string();
}

std::string resolveRasterPath(const Mission& mission, const std::string& missionPath) {
    return resolveMissionPath(mission.rasterPath, missionPath);
}

std::vector<std::string> robotNames(const Mission& mission) {
    std::vector<std::string> names;
    names.reserve(mission.robots.size());
    for (const RobotSpec& robot : mission.robots)
        names.push_back(robot.name);
    return names;
}

std::vector<double> plannerBatteries(const Mission& mission) {
    const auto planner = findPlannerDescription(mission.planner.planner);
    return planner && planner->fliesOnBatteries() ? robotBatteries(mission) : std::vector<double>{};
}

std::vector<double> robotRecharges(const Mission& mission) {
    std::vector<double> recharges;
    for (const VehicleSettings& vehicle : robotVehicles(mission))
        recharges.push_back(vehicle.turnaroundSeconds);
    return recharges;
}

std::vector<double> plannerRecharges(const Mission& mission) {
    const auto planner = findPlannerDescription(mission.planner.planner);
    return planner && planner->fliesOnBatteries() ? robotRecharges(mission) : std::vector<double>{};
}

double vehicleBatterySeconds(const VehicleSettings& vehicle) {
    if (!(vehicle.flightTimeSeconds > 0.0))
        return 0.0;
    const double travel = vehicle.flightTimeSeconds - climbAndDescentSeconds(vehicle);
    return travel >= BatteryEndurance::minimumSeconds ? travel : 0.0;
}

std::vector<double> robotBatteries(const Mission& mission) {
    const std::vector<VehicleSettings> vehicles = robotVehicles(mission);
    std::vector<double> batteries;
    for (std::size_t robot = 0; robot < mission.robots.size(); ++robot)
        batteries.push_back(
            mission.robots[robot].batterySeconds.value_or(vehicleBatterySeconds(vehicles[robot])));
    return batteries;
}

std::vector<double> robotCruiseSpeeds(const Mission& mission) {
    std::vector<double> speeds;
    for (const VehicleSettings& vehicle : robotVehicles(mission))
        speeds.push_back(vehicle.cruiseSpeedMetresPerSecond);
    return speeds;
}

double fleetCruiseSpeed(const Mission& mission) {
    const std::vector<VehicleSettings> vehicles = robotVehicles(mission);
    if (vehicles.empty())
        return mission.exports.vehicle.cruiseSpeedMetresPerSecond;
    const double speed = vehicles.front().cruiseSpeedMetresPerSecond;
    for (const VehicleSettings& vehicle : vehicles)
        if (vehicle.cruiseSpeedMetresPerSecond != speed)
            return 0.0;
    return speed;
}

namespace {

std::string robotLabel(const Mission& mission, std::size_t robot) {
    const std::string& name = mission.robots[robot].name;
    return name.empty() ? "Robot " + std::to_string(robot + 1) : name;
}

// "north", "north and south", "north, south and east", five at most named.
std::string namedRobots(const Mission& mission, const std::vector<std::size_t>& robots) {
    constexpr std::size_t named = 5;
    std::string text;
    const std::size_t shown = std::min(robots.size(), named);
    for (std::size_t i = 0; i < shown; ++i)
        text += (i == 0                                     ? ""
                 : i + 1 == shown && robots.size() <= named ? " and "
                                                            : ", ") +
                robotLabel(mission, robots[i]);
    return robots.size() > named ? text + " and " + std::to_string(robots.size() - named) + " more" : text;
}

// Robots that cruise at speeds of their own, each named with its speed: each is timed at it.
std::string mixedCruiseSpeedsNote(const Mission& mission, const std::vector<VehicleSettings>& vehicles) {
    std::string speeds;
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot) {
        const double speed = vehicles[robot].cruiseSpeedMetresPerSecond;
        speeds += (speeds.empty() ? "" : ", ") + robotLabel(mission, robot) + " " +
                  (speed > 0.0 ? formatQuantity(speed, 4) + " m/s" : "the land cover's");
    }
    return "the robots' cruise speeds differ (" + speeds +
           "): robots with a cruise speed drive at it over every passable class, the others at the class "
           "table's speeds, and each is timed at its own";
}

// Beside robots of speeds of their own, an aircraft left at the land cover's would crawl unnoticed.
std::optional<std::string> aircraftWithoutCruiseSpeedNote(const Mission& mission,
                                                          const std::vector<VehicleSettings>& vehicles) {
    std::vector<std::size_t> withoutCruiseSpeed;
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot)
        if (isAircraft(vehicles[robot].type) && !(vehicles[robot].cruiseSpeedMetresPerSecond > 0.0))
            withoutCruiseSpeed.push_back(robot);
    if (withoutCruiseSpeed.empty())
        return std::nullopt;
    const bool one = withoutCruiseSpeed.size() == 1;
    return namedRobots(mission, withoutCruiseSpeed) + (one ? " is an aircraft" : " are aircraft") +
           " without a cruise speed, so " + (one ? "it flies" : "they fly") +
           " at the class table's speeds, which are a ground robot's in the presets: give " +
           (one ? "it" : "them") + " one (robots[].cruise_speed_mps, or Plan > Robot vehicles in the window)";
}

// The fastest a vehicle of the type plausibly works at, with a margin above what such vehicles survey at
// (multirotors up to about 20 m/s, aeroplanes about 40 m/s, field robots at walking to car speeds).
double plausibleTopSpeed(VehicleType type) {
    switch (type) {
    case VehicleType::Multirotor:
        return 30.0;
    case VehicleType::FixedWing:
        return 60.0;
    case VehicleType::Rover:
        break;
    }
    return 20.0;
}

// Cruise speeds beyond what such a vehicle works at, most often a speed in km/h or knots given as m/s.
std::optional<std::string> implausibleCruiseSpeedNote(const Mission& mission,
                                                      const std::vector<VehicleSettings>& vehicles) {
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot) {
        const VehicleSettings& vehicle = vehicles[robot];
        const double speed = vehicle.cruiseSpeedMetresPerSecond;
        if (!(speed > plausibleTopSpeed(vehicle.type)))
            continue;
        const std::string who = fleetCruiseSpeed(mission) > 0.0 ? "every robot" : robotLabel(mission, robot);
        return who + " cruises at " + formatQuantity(speed, 4) + " m/s (" + formatQuantity(speed * 3.6, 4) +
               " km/h), faster than a " + vehicleTypeKey(vehicle.type) + " works at (up to about " +
               formatQuantity(plausibleTopSpeed(vehicle.type), 4) +
               " m/s): cruise speeds are in metres per second (" + formatQuantity(speed / 3.6, 4) +
               " m/s is " + formatQuantity(speed, 4) +
               " km/h); the turns of a fast vehicle take long, and its "
               "times mean little";
    }
    return std::nullopt;
}

// A shared cruise speed replaces the class table's speeds; robots of different ones drive each at its own.
void applyCruiseSpeed(const Mission& mission, const std::vector<VehicleSettings>& vehicles,
                      PlanningProblem& problem) {
    if (auto fast = implausibleCruiseSpeedNote(mission, vehicles))
        problem.notes.push_back({IssueSeverity::Warning, "implausible-cruise-speed", std::move(*fast)});
    const double cruise = fleetCruiseSpeed(mission);
    if (cruise > 0.0) {
        std::vector<LandCoverClass> classes = problem.classes.classes();
        for (LandCoverClass& landCover : classes)
            if (landCover.isTraversable())
                landCover.speedMetresPerSecond = cruise;
        problem.classes = ClassTable(std::move(classes));
        problem.notes.push_back(
            {IssueSeverity::Information, "cruise-speed",
             "every robot cruises at " + formatQuantity(cruise, 4) +
                 " m/s: the plan uses that speed over every passable class, not the class table's speeds"});
        return;
    }
    if (std::any_of(vehicles.begin(), vehicles.end(), [](const VehicleSettings& vehicle) {
            return vehicle.cruiseSpeedMetresPerSecond > 0.0;
        })) {
        for (const VehicleSettings& vehicle : vehicles) // robotCruiseSpeeds, from the vehicles at hand
            problem.robotSpeeds.push_back(vehicle.cruiseSpeedMetresPerSecond);
        problem.notes.push_back(
            {IssueSeverity::Information, "cruise-speeds-differ", mixedCruiseSpeedsNote(mission, vehicles)});
        if (auto slow = aircraftWithoutCruiseSpeedNote(mission, vehicles))
            problem.notes.push_back({IssueSeverity::Warning, "aircraft-at-ground-speeds", std::move(*slow)});
    } else if (std::any_of(vehicles.begin(), vehicles.end(),
                           [](const VehicleSettings& vehicle) { return isAircraft(vehicle.type); }))
        problem.notes.push_back(
            {IssueSeverity::Warning, "aircraft-at-ground-speeds",
             "aircraft fly at the class table's speeds, which are a ground robot's in the presets: give "
             "them a cruise speed (--cruise-speed, exports.cruise_speed_mps) for flight times"});
}

// The presets give a ground robot's fields of view: a drone's camera sees much farther, and passes that close
// make it fly many times the flights it needs. Said where every robot flies (a rover beside drones needs
// the table as it is: fields of view are the classes', not the robots') and the FOV of every passable class
// on the map (present) is one preset's.
std::optional<std::string> aircraftAtPresetFieldsOfViewNote(const std::vector<VehicleSettings>& vehicles,
                                                            const ClassTable& classes,
                                                            const std::vector<std::int32_t>& present,
                                                            std::optional<double> smallest) {
    if (vehicles.empty() ||
        !std::all_of(vehicles.begin(), vehicles.end(),
                     [](const VehicleSettings& vehicle) { return isAircraft(vehicle.type); }))
        return std::nullopt;
    if (!smallest)
        return std::nullopt;
    std::vector<const LandCoverClass*> passable;
    for (const std::int32_t value : present)
        if (const LandCoverClass* landCover = classes.find(value); landCover && landCover->isTraversable())
            passable.push_back(landCover);
    for (const PresetInfo& preset : classTablePresets()) {
        const Result<ClassTable> table = presetClassTable(preset.name);
        if (!table.ok())
            continue;
        const bool asInPreset =
            std::all_of(passable.begin(), passable.end(), [&](const LandCoverClass* landCover) {
                const LandCoverClass* row = table.value().find(landCover->value);
                return row != nullptr && row->fieldOfViewMetres == landCover->fieldOfViewMetres;
            });
        if (asInPreset)
            return "aircraft see as far as the class table's fields of view, which are preset " +
                   preset.name + "'s, a ground robot's (the smallest " + formatQuantity(*smallest, 4) +
                   " m, so passes as close as that): scale them to the camera's footprint on the ground "
                   "(--fov or a mission's classes.fov_m for one footprint over every class, --fov-scale, or "
                   "in the window select the classes, Edit selected…, Scale FOVs)";
    }
    return std::nullopt;
}

// "every aircraft at 150 m", or the robots and their altitudes, five at most: "north 0 m, south 2 m".
std::string namedAltitudes(const Mission& mission, const std::vector<VehicleSettings>& vehicles,
                           const std::vector<std::size_t>& robots) {
    const auto aircraft = std::count_if(vehicles.begin(), vehicles.end(), [](const VehicleSettings& vehicle) {
        return isAircraft(vehicle.type);
    });
    const double first = vehicles[robots.front()].altitudeMetres;
    const bool oneAltitude = std::all_of(robots.begin(), robots.end(), [&](std::size_t robot) {
        return vehicles[robot].altitudeMetres == first;
    });
    if (oneAltitude && static_cast<std::size_t>(aircraft) == robots.size() && robots.size() > 1)
        return "every aircraft at " + formatQuantity(first, 4) + " m";
    constexpr std::size_t named = 5;
    std::string text;
    for (std::size_t i = 0; i < robots.size() && i < named; ++i)
        text += (text.empty() ? "" : ", ") + robotLabel(mission, robots[i]) + " " +
                formatQuantity(vehicles[robots[i]].altitudeMetres, 4) + " m";
    return robots.size() > named ? text + " and " + std::to_string(robots.size() - named) + " more" : text;
}

// Aircraft altitudes a user most likely did not mean: at the height of home, or above what drones may fly
// without a permit in most countries.
void noteAircraftAltitudes(const Mission& mission, const std::vector<VehicleSettings>& vehicles,
                           std::vector<PlanIssue>& notes) {
    std::vector<std::size_t> low;
    std::vector<std::size_t> high;
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot) {
        if (fliesTooLow(vehicles[robot]))
            low.push_back(robot);
        else if (fliesAbovePermitFreeHeight(vehicles[robot]))
            high.push_back(robot);
    }
    if (!low.empty())
        notes.push_back({IssueSeverity::Warning, "altitude-too-low",
                         "aircraft flying lower than " + formatQuantity(lowestSurveyAltitudeMetres, 4) +
                             " m above home, into trees and roofs (" +
                             namedAltitudes(mission, vehicles, low) +
                             "): give a survey altitude (--altitude, exports.altitude_m)"});
    if (!high.empty())
        notes.push_back({IssueSeverity::Warning, "altitude-above-120m",
                         "aircraft flying higher than " +
                             formatQuantity(highestAltitudeWithoutPermitMetres, 4) + " m (" +
                             std::to_string(highestAltitudeWithoutPermitFeet) +
                             " ft) above home, above what most countries allow drones without a permit (" +
                             namedAltitudes(mission, vehicles, high) + ")"});
    // Autopilots fly a .plan's altitudes above home unless told to follow terrain, and the land cover holds
    // no heights: over hills rising above the start, an aircraft flies lower than set, or into them.
    if (std::any_of(vehicles.begin(), vehicles.end(),
                    [](const VehicleSettings& vehicle) { return isAircraft(vehicle.type); }))
        notes.push_back({IssueSeverity::Information, "altitude-above-home",
                         "aircraft fly at their altitude above home (where they take off), not above the "
                         "ground under them: the map holds no heights, so where the land rises above home "
                         "they fly that much lower; check the terrain along the paths before flying"});
}

// Photos farther apart than the footprint the plan spaces its passes by (the smallest field of view of a
// class robots cover) miss the ground between them along the path.
void notePhotosFartherThanFootprint(const Mission& mission, const std::vector<VehicleSettings>& vehicles,
                                    std::optional<double> smallest, std::vector<PlanIssue>& notes) {
    if (!smallest)
        return;
    const double footprint = *smallest;
    std::vector<std::size_t> over;
    double longest = 0.0;
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot)
        if (vehicles[robot].cameraTriggerMetres > footprint) {
            over.push_back(robot);
            longest = std::max(longest, vehicles[robot].cameraTriggerMetres);
        }
    if (over.empty())
        return;
    const std::string named = (over.size() == vehicles.size() ? "" : namedRobots(mission, over) + ", ") +
                              "up to every " + formatQuantity(longest, 4) + " m";
    notes.push_back({IssueSeverity::Warning, "photos-farther-than-footprint",
                     "photos farther apart than the " + formatQuantity(footprint, 4) +
                         " m field of view the passes are spaced by (" + named +
                         "): the ground between two photos is missed; for 20 % overlap along the path, "
                         "a photo every " +
                         formatQuantity(0.8 * footprint, 4) + " m (--camera-trigger, camera_trigger_m)"});
}

// " (20 min)": the battery_s the mission gives the planner, or its default.
std::string plannerBattery(const PlannerDescription& planner, const ParameterValues& given) {
    for (const ParameterSpec& spec : planner.parameters) {
        if (spec.key != "battery_s")
            continue;
        const ParameterValue* value = given.find(spec.key);
        const ParameterValue& battery = value != nullptr ? *value : spec.defaultValue;
        if (const double* seconds = std::get_if<double>(&battery))
            return " (" + formatDuration(*seconds) + ")";
    }
    return {};
}

// "18 min 56 s for north-west and centre, 20 min for south-east": robots grouped by a duration.
std::string durationsOfRobots(const Mission& mission,
                              const std::map<double, std::vector<std::size_t>>& robotsBySeconds) {
    std::string groups;
    for (const auto& [seconds, robots] : robotsBySeconds)
        groups +=
            (groups.empty() ? "" : ", ") + formatDuration(seconds) + " for " + namedRobots(mission, robots);
    return groups;
}

// For a planner that flies on batteries, where robots' batteries come from their vehicles' flight times:
// what each robot's sorties are planned on, so that two settings of one battery do not part unseen.
std::optional<std::string> batteriesFromFlightTimesNote(const Mission& mission,
                                                        const std::vector<VehicleSettings>& vehicles) {
    const auto planner = findPlannerDescription(mission.planner.planner);
    if (!planner || !planner->fliesOnBatteries())
        return std::nullopt;
    std::map<double, std::vector<std::size_t>> fromVehicle; // by battery
    std::vector<std::size_t> own;
    std::vector<std::size_t> planners;
    for (std::size_t robot = 0; robot < mission.robots.size(); ++robot) {
        if (mission.robots[robot].batterySeconds)
            own.push_back(robot);
        else if (const double battery = vehicleBatterySeconds(vehicles[robot]); battery > 0.0)
            fromVehicle[battery].push_back(robot);
        else
            planners.push_back(robot);
    }
    if (fromVehicle.empty())
        return std::nullopt;
    std::string text = "sorties are planned on each vehicle's flight time, an aircraft's less its climb and "
                       "descent: ";
    text += durationsOfRobots(mission, fromVehicle);
    if (!own.empty())
        text += "; " + namedRobots(mission, own) + " on " + (own.size() == 1 ? "its" : "their") +
                " own battery_s";
    if (!planners.empty())
        text += "; " + namedRobots(mission, planners) +
                ", without a flight time, on the planner's battery_s" +
                plannerBattery(*planner, mission.planner.parameters);
    return text;
}

// Where some robot charges for its vehicle's turnaround (plannerRecharges): for how long each charges, so
// that the planner's recharge_s is not taken for every robot's.
std::optional<std::string> rechargesFromTurnaroundsNote(const Mission& mission,
                                                        const std::vector<double>& recharges) {
    std::map<double, std::vector<std::size_t>> byTurnaround;
    std::vector<std::size_t> others;
    for (std::size_t robot = 0; robot < recharges.size(); ++robot)
        (recharges[robot] > 0.0 ? byTurnaround[recharges[robot]] : others).push_back(robot);
    if (byTurnaround.empty())
        return std::nullopt;
    std::string text = "between sorties, robots charge for their vehicle's turnaround: ";
    text += durationsOfRobots(mission, byTurnaround);
    if (!others.empty())
        text += "; " + namedRobots(mission, others) + ", without one, for the planner's recharge_s";
    return text;
}

} // namespace

namespace {

// Whether some robot's split mission ends later than its path: then its time in the field is measured.
bool fieldTimeMeasured(const std::vector<VehicleSettings>& vehicles) {
    return std::any_of(vehicles.begin(), vehicles.end(), splitMissionEndsLater);
}

// Each robot's time in the field on a plan: its waypoint files' flights and the turnarounds between them
// where its vehicle's split mission ends later than its path, else its path's time. Unset where no robot's
// does.
std::function<std::vector<double>(const Plan&)> fieldSecondsOf(const Mission& mission,
                                                               const std::vector<VehicleSettings>& vehicles) {
    if (!fieldTimeMeasured(vehicles))
        return {};
    return [vehicles, settings = mission.exports](const Plan& plan) {
        std::vector<double> seconds(plan.paths.size(), 0.0);
        // A robot's mission is made as its waypoint files make it: robots in parallel.
        parallelFor(plan.paths.size(), [&](std::size_t robot, int) {
            const CoveragePath& path = plan.paths[robot];
            const double field = robot < vehicles.size() && splitMissionEndsLater(vehicles[robot])
                                     ? missionSize(plan, path, vehicles[robot], settings).fieldSeconds
                                     : 0.0;
            seconds[robot] = field > 0.0 ? field : path.timeSeconds;
        });
        return seconds;
    };
}

// The fewest seconds a robot's waypoint files take for a second of its planned path. A cruise speed is
// commanded as it is, and speeds changed only at turns are each leg's slowest, rounded down: as planned or
// slower. Otherwise land-cover speeds are commanded rounded (up to 5 % up, to two significant digits) and a
// speed in force is held while the next differs by no more than the tolerance: a cell may be flown faster.
double fastestPaceOf(const VehicleSettings& vehicle, const ExportSettings& exports) {
    constexpr double mostRoundedUp = 1.05;
    if (vehicle.cruiseSpeedMetresPerSecond > 0.0 || exports.speedChangesAtTurnsOnly)
        return 1.0;
    return std::clamp(1.0 - exports.speedTolerance, 0.0, 1.0) / mostRoundedUp;
}

// What each robot's flights allow, where some robot's split mission ends later than its path (as
// fieldSecondsOf); else none.
std::vector<FlightLimits> flightLimitsOf(const Mission& mission,
                                         const std::vector<VehicleSettings>& vehicles) {
    if (!fieldTimeMeasured(vehicles))
        return {};
    std::vector<FlightLimits> limits;
    for (const VehicleSettings& vehicle : vehicles) {
        // An aircraft flies from its start to its work and back at its cruise speed (AutopilotMission's
        // flights); without one, its trips are not counted.
        const bool flownOut = isAircraft(vehicle.type) && vehicle.cruiseSpeedMetresPerSecond > 0.0;
        limits.push_back({vehicle.flightTimeSeconds, climbAndDescentSeconds(vehicle),
                          vehicle.turnaroundSeconds, fastestPaceOf(vehicle, mission.exports),
                          flownOut ? vehicle.cruiseSpeedMetresPerSecond : 0.0});
    }
    return limits;
}

} // namespace

// A preset chosen for a raster recognised as another product: its rows may cover every value and still name,
// time and size the classes as that other product's (a Canada land-cover map planned with CORINE's grid
// codes reads needleleaf forest as continuous urban fabric). Said only where the raster names or colours
// its product, not where its codes alone suggest one.
std::optional<std::string> presetOfAnotherProductWarning(const Mission& mission, const LoadedRaster& raster) {
    if (mission.preset.empty())
        return std::nullopt;
    const auto preset = presetClassTable(mission.preset);
    if (!preset)
        return std::nullopt;
    // A class the mission has no row for, or one named as the preset names it (the window holds the
    // preset's rows as its own), is the preset's; where the rows rename every class on the map, none is.
    const bool presetGivesSome =
        std::any_of(raster.classPixelCounts.begin(), raster.classPixelCounts.end(), [&](const auto& counted) {
            const LandCoverClass* own = mission.classes.find(counted.first);
            const LandCoverClass* given = preset.value().find(counted.first);
            return counted.second > 0 && given != nullptr && (own == nullptr || own->name == given->name);
        });
    const auto product = presetGivesSome ? internal::recogniseProduct(raster) : std::nullopt;
    if (!product || product->preset == mission.preset || product->evidence.starts_with("its codes"))
        return std::nullopt;
    return "the raster is " + product->productName + " by " + product->evidence +
           ", yet the classes are preset " + mission.preset +
           "'s: the classes its rows give are named, timed and sized as that product's classes of the same "
           "values. Choose the preset " +
           product->preset +
           " (classes.preset in a mission file, --preset on the command line, the Preset box in the window), "
           "unless the raster only looks like " +
           product->productName;
}

FieldTimeInputs fieldTimeInputs(const Mission& mission) {
    std::vector<VehicleSettings> vehicles = robotVehicles(mission);
    const auto planner = findPlannerDescription(mission.planner.planner);
    // A battery plan's paths hold their sorties: they are not measured in the field.
    if (!fieldTimeMeasured(vehicles) || (planner && planner->fliesOnBatteries()))
        return {};
    const ExportSettings& exports = mission.exports;
    return {std::move(vehicles), exports.speedTolerance, exports.speedChangesAtTurnsOnly,
            exports.mergeCollinear};
}

void applyRobotSettings(const Mission& mission, const LoadedRaster& raster, PlanningProblem& problem) {
    problem.batterySeconds = robotBatteries(mission);
    // Every robot's, as batteries are: a comparison plans a battery planner on the problem of another.
    problem.rechargeSeconds = robotRecharges(mission);
    problem.events = mission.events;
    const std::vector<VehicleSettings> vehicles = robotVehicles(mission);
    problem.fieldSeconds = fieldSecondsOf(mission, vehicles);
    problem.robotFlights = flightLimitsOf(mission, vehicles);
    problem.flyingRobots = flyingRobots(mission);
    applyCruiseSpeed(mission, vehicles, problem);
    if (auto otherProduct = presetOfAnotherProductWarning(mission, raster))
        problem.notes.push_back(
            {IssueSeverity::Warning, "preset-of-another-product", std::move(*otherProduct)});
    // The passes are spaced by the smallest field of view of a class on the map, not of the whole table.
    const std::vector<std::int32_t> present = presentClassValues(raster);
    const std::optional<double> smallest = smallestFieldOfView(problem.classes, present);
    if (auto groundView = aircraftAtPresetFieldsOfViewNote(vehicles, problem.classes, present, smallest))
        problem.notes.push_back({IssueSeverity::Warning, "aircraft-at-ground-fov", std::move(*groundView)});
    noteAircraftAltitudes(mission, vehicles, problem.notes);
    notePhotosFartherThanFootprint(mission, vehicles, smallest, problem.notes);
    if (auto batteries = batteriesFromFlightTimesNote(mission, vehicles))
        problem.notes.push_back(
            {IssueSeverity::Information, "batteries-from-flight-times", std::move(*batteries)});
    if (auto recharges = rechargesFromTurnaroundsNote(mission, plannerRecharges(mission)))
        problem.notes.push_back(
            {IssueSeverity::Information, "recharges-from-turnarounds", std::move(*recharges)});
}

std::vector<VehicleSettings> robotVehicles(const Mission& mission) {
    std::vector<VehicleSettings> vehicles;
    vehicles.reserve(mission.robots.size());
    for (const RobotSpec& robot : mission.robots)
        vehicles.push_back(robot.vehicle.over(mission.exports.vehicle));
    return vehicles;
}

std::vector<bool> flyingRobots(const Mission& mission) {
    std::vector<bool> flying;
    for (const VehicleSettings& vehicle : robotVehicles(mission))
        flying.push_back(isAircraft(vehicle.type));
    return flying;
}

std::optional<std::string> fleetFlightProblem(const Mission& mission) {
    const std::vector<VehicleSettings> vehicles = robotVehicles(mission);
    std::optional<std::string> problem; // the first robot's, said of every robot that has the same
    std::vector<std::size_t> alike;
    std::vector<std::size_t> others; // robots that cannot fly settings of their own
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot) {
        auto tooShort = flightTooShortProblem(vehicles[robot]);
        if (!tooShort)
            continue;
        if (!problem)
            problem = tooShort;
        (*tooShort == *problem ? alike : others).push_back(robot);
    }
    if (!problem)
        return std::nullopt;
    // One setting shared by a whole fleet is one mistake, not one per robot.
    const std::string who =
        alike.size() == vehicles.size() && alike.size() > 1 ? "every robot" : namedRobots(mission, alike);
    return who + ": " + *problem +
           (others.empty()
                ? std::string()
                : "; " + namedRobots(mission, others) + " cannot fly " +
                      (others.size() == 1 ? "its own settings" : "their own settings") + " either");
}

} // namespace mcpp::io
