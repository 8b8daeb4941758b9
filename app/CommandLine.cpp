#include "app/CommandLine.hpp"

#include "core/decomposition/DecompositionOptions.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/LandCoverClass.hpp"
#include "core/model/NameSuggestion.hpp"
#include "core/model/SpeedEventCheck.hpp"
#include "core/parameters/NumberText.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/ExportCatalogue.hpp"
#include "io/VehicleSettings.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#ifndef MCPP_VERSION
#define MCPP_VERSION "unknown"
#endif

namespace mcpp::app {
namespace {

struct FlagSpec {
    std::string_view name;
    std::string_view valueName; // empty for switches
    bool batchOnly;
    bool repeatable;
};

constexpr std::array flagSpecs{
    FlagSpec{"--batch", "", false, false},         FlagSpec{"--out", "DIR", true, false},
    FlagSpec{"--raster", "FILE", true, false},     FlagSpec{"--classes", "TABLE.csv", true, false},
    FlagSpec{"--preset", "NAME", true, false},     FlagSpec{"--start", "X,Y", true, true},
    FlagSpec{"--start-crs", "CRS", true, false},   FlagSpec{"--planner", "NAME", true, false},
    FlagSpec{"--band", "N", true, false},          FlagSpec{"--param", "KEY=VALUE", true, true},
    FlagSpec{"--purity", "F", true, false},        FlagSpec{"--missing-as-obstacle", "", true, false},
    FlagSpec{"--open-paths", "", true, false},     FlagSpec{"--quiet", "", true, false},
    FlagSpec{"--dense-paths", "", true, false},    FlagSpec{"--cell-polygons", "", true, false},
    FlagSpec{"--threads", "N", true, false},       FlagSpec{"--compare", "NAMES", true, false},
    FlagSpec{"--area", "FILE", true, false},       FlagSpec{"--no-go", "FILE", true, false},
    FlagSpec{"--max-waypoints", "N", true, false}, FlagSpec{"--event", "T:ROBOT:FACTOR", true, true},
    FlagSpec{"--charger", "X,Y", true, true},      FlagSpec{"--vehicle", "TYPE", true, false},
    FlagSpec{"--altitude", "M", true, false},      FlagSpec{"--cruise-speed", "M/S", true, false},
    FlagSpec{"--fov-scale", "F", true, false},     FlagSpec{"--flight-time", "T", true, false},
    FlagSpec{"--turnaround", "T", true, false},    FlagSpec{"--fov", "M", true, false},
    FlagSpec{"--outputs", "KEYS", true, false},    FlagSpec{"--camera-trigger", "M", true, false},
};

// --outputs: catalogue keys separated by commas, each once; report.json, which the summary and the
// comparison read, is always written.
std::optional<std::string> parseOutputKeys(std::string_view value, std::vector<std::string>& keys) {
    keys.clear();
    std::size_t begin = 0;
    while (begin <= value.size()) {
        const std::size_t end = std::min(value.find(',', begin), value.size());
        const std::string key(value.substr(begin, end - begin));
        begin = end + 1;
        if (key.empty())
            continue;
        if (io::findExportFormat(key) == nullptr)
            return "--outputs: \"" + key + "\" is not an output; the outputs are " + io::exportFormatKeys();
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            keys.push_back(key);
    }
    if (keys.empty())
        return "--outputs needs output names separated by commas: " + io::exportFormatKeys();
    if (std::find(keys.begin(), keys.end(), "report-json") == keys.end())
        keys.push_back("report-json");
    return std::nullopt;
}

const FlagSpec* findFlag(std::string_view name) {
    if (name == "-o")
        name = "--out";
    if (name == "-q")
        name = "--quiet";
    const auto found = std::find_if(flagSpecs.begin(), flagSpecs.end(),
                                    [name](const FlagSpec& spec) { return spec.name == name; });
    return found == flagSpecs.end() ? nullptr : &*found;
}

// "unknown flag --cruise (did you mean --cruise-speed? see mcpp --help)".
std::string unknownFlagMessage(std::string_view name) {
    std::vector<std::string> known;
    for (const FlagSpec& spec : flagSpecs)
        known.emplace_back(spec.name);
    const auto meant = closestName(std::string(name), known);
    return "unknown flag " + std::string(name) + " (" +
           (meant ? "did you mean " + *meant + "? " : std::string()) + "see mcpp --help)";
}

std::optional<int> parseNonNegativeInteger(std::string_view text) {
    text = trimmedText(text);
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0)
        return std::nullopt;
    return value;
}

// "300:0:0.5": from 300 s on, robot 0 at half speed.
std::optional<SpeedEvent> parseEvent(std::string_view text) {
    const std::size_t first = text.find(':');
    const std::size_t second = first == std::string_view::npos ? first : text.find(':', first + 1);
    if (second == std::string_view::npos || text.find(':', second + 1) != std::string_view::npos)
        return std::nullopt;
    const auto time = parseFiniteNumber(text.substr(0, first));
    const auto robot = parseNonNegativeInteger(text.substr(first + 1, second - first - 1));
    const auto factor = parseFiniteNumber(text.substr(second + 1));
    if (!time || !robot || !factor)
        return std::nullopt;
    return SpeedEvent{*time, *robot, *factor};
}

// ": write 100" for "100m" or "100 metres" on a flag in metres: the number the flag takes, where the unit
// written is the flag's own (`perSecond`: metres per second) and the number is one the flag accepts.
std::string numberWithUnitHint(std::string_view value, bool perSecond,
                               const std::function<bool(double)>& accepts) {
    const std::string_view text = trimmedText(value);
    double number = 0.0;
    const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
    const auto [end, error] = std::from_chars(first, text.data() + text.size(), number);
    if (error != std::errc() || !std::isfinite(number) || !accepts(number))
        return {};
    std::string unit(
        trimmedText(std::string_view(end, static_cast<std::size_t>(text.data() + text.size() - end))));
    std::transform(unit.begin(), unit.end(), unit.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    static const std::set<std::string> metres{"m", "metre", "metres", "meter", "meters"};
    static const std::set<std::string> metresPerSecond{"m/s", "mps", "metres per second",
                                                       "meters per second"};
    if (!(perSecond ? metresPerSecond : metres).contains(unit))
        return {};
    return ": write " + std::string(first, end);
}

// Seconds given without a unit, too few for a flight but a likely number of minutes: "25" meant 25min.
std::string minutesMeantHint(const std::string& value, std::optional<double> seconds) {
    if (!seconds || *seconds < 1.0 || *seconds >= 60.0 || !parseFiniteNumber(value))
        return {};
    return " (for " + formatQuantity(*seconds) + (*seconds == 1.0 ? " minute" : " minutes") + ", write " +
           std::string(trimmedText(value)) + "min)";
}

// A duration flag's value read into `seconds`, or what is wrong with it: not a duration (`example` shows
// one), or one that `problem` refuses.
std::optional<std::string> readDurationFlag(std::string_view flag, const std::string& value,
                                            std::string_view example,
                                            std::optional<std::string> (*problem)(double),
                                            std::optional<double>& seconds) {
    seconds = parseDuration(value);
    const std::string named = std::string(flag);
    if (!seconds)
        return named + ": \"" + value +
               "\" is not a duration (seconds, or a number with s, min or h: " + std::string(example) + ")";
    if (const auto refused = problem(*seconds))
        return named + " \"" + value + "\": " + *refused + minutesMeantHint(value, seconds);
    return std::nullopt;
}

std::optional<int> parsePositiveInteger(std::string_view text) {
    const auto value = parseNonNegativeInteger(text);
    return value && *value >= 1 ? value : std::nullopt;
}

std::optional<MapPoint> parsePoint(std::string_view text) {
    const auto comma = text.find(',');
    if (comma == std::string_view::npos)
        return std::nullopt;
    const auto x = parseFiniteNumber(text.substr(0, comma));
    const auto y = parseFiniteNumber(text.substr(comma + 1));
    if (!x || !y)
        return std::nullopt;
    return MapPoint{*x, *y};
}

// "7.40," is what the shell passes of "--start 7.40, 1.67".
std::string spaceAfterCommaHint(std::string_view value) {
    return !value.empty() && value.back() == ',' ? ": write it without a space after the comma, or in quotes"
                                                 : std::string();
}

std::string quoted(std::string_view text) {
    return "\"" + std::string(text) + "\"";
}

// A value-taking flag swallows the next argument unless it is another long flag; "-12,5" stays a value
// so negative coordinates need no escaping.
bool looksLikeFlag(std::string_view argument) {
    return argument.size() > 2 && argument.substr(0, 2) == "--";
}

bool anyPlannerDeclares(const std::string& key) {
    for (const PlannerDescription& planner : plannerDescriptions())
        if (findParameter(planner.parameters, key) != nullptr)
            return true;
    return false;
}

// The key any planner declares that a mistyped one most likely meant.
std::optional<std::string> closestParameterKey(const std::string& typed) {
    std::vector<std::string> keys;
    for (const PlannerDescription& planner : plannerDescriptions())
        for (const ParameterSpec& spec : planner.parameters)
            if (std::find(keys.begin(), keys.end(), spec.key) == keys.end())
                keys.push_back(spec.key);
    return closestName(typed, keys);
}

// Words of `text` on lines of at most `width` characters, each line indented.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width) {
    std::istringstream words(text);
    std::string result;
    std::string line;
    std::string word;
    while (words >> word) {
        if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
            result += std::string(indent, ' ') + line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty())
        result += std::string(indent, ' ') + line + "\n";
    return result;
}

// A planner's page for --help-planner: name, summary, then each parameter with its default, what it
// takes and what it does.
void describePlanner(std::ostringstream& text, const PlannerDescription& planner) {
    text << planner.label << " (" << planner.name << (planner.singleRobot ? ", one robot" : "") << ")\n";
    text << wrapped(planner.summary, 2, 100)
         << "\nParameters (--param KEY=VALUE, or planner.parameters in a "
            "mission file), shown with their defaults:\n";
    for (const ParameterSpec& parameter : planner.parameters) {
        text << "  " << parameter.key << "=" << parameter.format(parameter.defaultValue) << "\n";
        // expected() names the unit with the range ("a number from 0 to 600 s").
        const std::vector<const ParameterSpec*> switches = switchesNeeded(planner.parameters, parameter);
        const std::string switchNote = switches.empty() ? "" : " Only with " + switchesText(switches) + ".";
        text << wrapped(parameter.help + ". Takes " + parameter.expected() + "." + switchNote, 6, 100);
    }
}

CommandLineParseResult failure(std::string message) {
    CommandLineParseResult result;
    result.error = std::move(message);
    result.exitCode = 2;
    return result;
}

} // namespace

CommandLineParseResult CommandLine::parse(const std::vector<std::string>& arguments) {
    // --help and --version win over everything else, so a user can always get them.
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (argument == "--")
            break;
        if (argument == "--help-planner" || argument.rfind("--help-planner=", 0) == 0) {
            const bool inlineName = argument.size() > std::string("--help-planner").size();
            const std::string name = inlineName
                                         ? argument.substr(argument.find('=') + 1)
                                         : (i + 1 < arguments.size() ? arguments[i + 1] : std::string());
            if (name.empty())
                return failure("--help-planner needs a value: NAME");
            if (!findPlannerDescription(name))
                return failure("--help-planner: " + unknownPlannerMessage(name));
            CommandLineParseResult result;
            result.options.mode = RunMode::PlannerHelp;
            result.options.helpPlanner = name;
            return result;
        }
        if (argument == "--help" || argument == "-h") {
            CommandLineParseResult result;
            result.options.mode = RunMode::Help;
            return result;
        }
        if (argument == "--version" || argument == "-v") {
            CommandLineParseResult result;
            result.options.mode = RunMode::Version;
            return result;
        }
    }

    CommandLineOptions options;
    bool batch = false;
    std::vector<std::string> positionals;
    std::vector<std::string_view> seen; // flags in the order given
    int startCount = 0;
    std::string chargerWithoutStart; // the first --charger given before any --start
    bool onlyPositionalsFollow = false;

    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (onlyPositionalsFollow || argument.empty() || argument == "-" || argument.front() != '-') {
            positionals.push_back(argument);
            continue;
        }
        if (argument == "--") {
            onlyPositionalsFollow = true;
            continue;
        }
        std::string_view name = argument;
        std::optional<std::string> inlineValue;
        if (const auto equals = name.find('='); equals != std::string_view::npos && looksLikeFlag(name)) {
            inlineValue = std::string(name.substr(equals + 1));
            name = name.substr(0, equals);
        }
        const FlagSpec* spec = findFlag(name);
        if (spec == nullptr)
            return failure(unknownFlagMessage(name));
        if (!spec->repeatable && std::find(seen.begin(), seen.end(), spec->name) != seen.end()) {
            return failure(std::string(spec->name) + " is given more than once");
        }
        seen.push_back(spec->name);

        std::string value;
        if (spec->valueName.empty()) {
            if (inlineValue)
                return failure(std::string(spec->name) + " takes no value");
        } else if (inlineValue) {
            value = *inlineValue;
        } else if (i + 1 < arguments.size() && !looksLikeFlag(arguments[i + 1])) {
            value = arguments[++i];
        } else {
            return failure(std::string(spec->name) + " needs a value: " + std::string(spec->valueName));
        }
        if (!spec->valueName.empty() && trimmedText(value).empty()) {
            return failure(std::string(spec->name) + " needs a value: " + std::string(spec->valueName));
        }

        const std::string_view flag = spec->name;
        if (flag == "--batch") {
            batch = true;
        } else if (flag == "--out") {
            options.outputDirectory = value;
        } else if (flag == "--raster") {
            options.rasterPath = value;
        } else if (flag == "--classes") {
            options.classesPath = value;
        } else if (flag == "--preset") {
            options.preset = value;
        } else if (flag == "--area") {
            options.areaPath = value;
        } else if (flag == "--no-go") {
            options.noGoPath = value;
        } else if (flag == "--start") {
            ++startCount;
            const auto point = parsePoint(value);
            if (!point)
                return failure("--start " + std::to_string(startCount) + ": " + quoted(value) +
                               " is not X,Y" + spaceAfterCommaHint(value));
            options.starts.push_back(*point);
            options.chargers.emplace_back();
        } else if (flag == "--charger") {
            // It belongs to the robot of the --start before it; one with none is reported once it is
            // known whether a mission file gives the robots instead.
            if (options.starts.empty()) {
                if (chargerWithoutStart.empty())
                    chargerWithoutStart = value;
                continue;
            }
            const std::string which = "--charger after --start " + std::to_string(options.starts.size());
            const auto point = parsePoint(value);
            if (!point)
                return failure(which + ": " + quoted(value) + " is not X,Y" + spaceAfterCommaHint(value));
            std::optional<MapPoint>& charger = options.chargers[options.starts.size() - 1];
            if (charger)
                return failure("--start " + std::to_string(options.starts.size()) +
                               " has a --charger already: give one --charger after each --start");
            charger = *point;
        } else if (flag == "--start-crs") {
            // Any CRS GDAL reads, as a mission file's start_crs; one it does not know is said on loading.
            options.startCrs = value;
        } else if (flag == "--planner") {
            if (!findPlannerDescription(value))
                return failure("--planner: " + unknownPlannerMessage(value));
            options.planner = value;
        } else if (flag == "--param") {
            const auto equals = value.find('=');
            const std::string key = std::string(trimmedText(std::string_view(value).substr(0, equals)));
            if (equals == std::string::npos || key.empty())
                return failure("--param: " + quoted(value) + " is not KEY=VALUE");
            if (!anyPlannerDeclares(key)) {
                const auto meant = closestParameterKey(key);
                return failure("--param " + key + ": no planner has a parameter of that name (" +
                               (meant ? "did you mean " + *meant + "? " : std::string()) +
                               "see mcpp --help-planner NAME)");
            }
            options.parameters.push_back({key, value.substr(equals + 1), "--param " + key});
        } else if (flag == "--band") {
            const auto band = parsePositiveInteger(value);
            if (!band)
                return failure("--band: " + quoted(value) + " is not a band number (1, 2, ...)");
            options.band = *band;
        } else if (flag == "--purity") {
            std::string problem;
            if (!DecompositionOptions::purityToleranceParameter().parse(value, &problem))
                return failure("--purity: " + problem);
            options.parameters.push_back({"purity_tolerance", value, "--purity"});
        } else if (flag == "--missing-as-obstacle") {
            options.missingAsObstacle = true;
        } else if (flag == "--open-paths") {
            options.parameters.push_back({"closed_tour", "false", "--open-paths"});
        } else if (flag == "--quiet") {
            options.quiet = true;
        } else if (flag == "--compare") {
            options.comparePlanners.clear();
            if (trimmedText(value) == "all") {
                options.comparePlanners = availablePlanners();
                continue;
            }
            std::string_view rest = value;
            while (!rest.empty()) {
                const auto comma = rest.find(',');
                const std::string planner(trimmedText(rest.substr(0, comma)));
                rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
                if (planner.empty())
                    continue;
                if (!findPlannerDescription(planner))
                    return failure("--compare: " + unknownPlannerMessage(planner));
                if (std::find(options.comparePlanners.begin(), options.comparePlanners.end(), planner) ==
                    options.comparePlanners.end())
                    options.comparePlanners.push_back(planner);
            }
            if (options.comparePlanners.empty())
                return failure("--compare needs planner names separated by commas, or all");
        } else if (flag == "--threads") {
            const auto threads = parsePositiveInteger(value);
            if (!threads || *threads > 64)
                return failure("--threads: " + quoted(value) + " is not a thread count (1 to 64)");
            options.threads = *threads;
        } else if (flag == "--event") {
            const auto event = parseEvent(value);
            if (!event)
                return failure("--event " + quoted(value) +
                               ": expected TIME_S:ROBOT:SPEED_FACTOR, e.g. 300:0:0.5 (robot 0 at half speed "
                               "from 300 s)");
            // The robot is checked once the mission says how many there are.
            if (const auto wrong = speedEventProblem(*event, static_cast<std::size_t>(event->robot) + 1))
                return failure("--event " + quoted(value) + ": " + wrong->field + ": " + wrong->detail);
            options.events.push_back(*event);
        } else if (flag == "--max-waypoints") {
            const auto limit = parseNonNegativeInteger(value);
            if (!limit || !io::isWorkableItemLimit(*limit))
                return failure("--max-waypoints: " + quoted(value) +
                               " is not an item limit (0 for none, or " +
                               std::to_string(io::minimumMaxWaypoints) + " or more mission items)");
            options.maxWaypoints = *limit;
        } else if (flag == "--vehicle") {
            options.vehicleType = io::vehicleTypeFromKey(std::string(trimmedText(value)));
            if (!options.vehicleType)
                return failure("--vehicle: " + quoted(value) +
                               " is not a vehicle (rover, multirotor or fixed-wing)");
        } else if (flag == "--altitude") {
            options.altitudeMetres = parseFiniteNumber(value);
            if (!options.altitudeMetres || *options.altitudeMetres < 0.0 || *options.altitudeMetres > 10000.0)
                return failure(
                    "--altitude: " + quoted(value) +
                    " is not an altitude above home (a number of metres without a unit, 0 to 10000)" +
                    numberWithUnitHint(value, false,
                                       [](double metres) { return metres >= 0.0 && metres <= 10000.0; }));
        } else if (flag == "--cruise-speed") {
            options.cruiseSpeedMetresPerSecond = parseFiniteNumber(value);
            if (!options.cruiseSpeedMetresPerSecond || *options.cruiseSpeedMetresPerSecond < 0.0 ||
                *options.cruiseSpeedMetresPerSecond > 1000.0)
                return failure("--cruise-speed: " + quoted(value) +
                               " is not a speed (a number of metres per second without a unit: 0 for the "
                               "land-cover speeds, up to 1000)" +
                               numberWithUnitHint(value, true, [](double speed) {
                                   return speed >= 0.0 && speed <= 1000.0;
                               }));
        } else if (flag == "--flight-time") {
            if (auto problem =
                    readDurationFlag(flag, value, "25min", &io::flightTimeProblem, options.flightTimeSeconds))
                return failure(std::move(*problem));
        } else if (flag == "--turnaround") {
            if (auto problem =
                    readDurationFlag(flag, value, "5min", &io::turnaroundProblem, options.turnaroundSeconds))
                return failure(std::move(*problem));
        } else if (flag == "--camera-trigger") {
            options.cameraTriggerMetres = parseFiniteNumber(value);
            if (!options.cameraTriggerMetres || io::cameraTriggerProblem(*options.cameraTriggerMetres))
                return failure("--camera-trigger: " + quoted(value) +
                               " is not a distance between photos (a number of metres without a unit: 0 for "
                               "none, or 0.1 to 10000)" +
                               numberWithUnitHint(value, false, [](double metres) {
                                   return !io::cameraTriggerProblem(metres);
                               }));
        } else if (flag == "--fov-scale") {
            options.fieldOfViewScale = parseFiniteNumber(value);
            if (!options.fieldOfViewScale || !(*options.fieldOfViewScale > 0.0) ||
                *options.fieldOfViewScale > 1000.0)
                return failure("--fov-scale: " + quoted(value) +
                               " is not a factor for the fields of view (more than 0, up to 1000)");
        } else if (flag == "--fov") {
            options.fieldOfViewMetres = parseFiniteNumber(value);
            if (!options.fieldOfViewMetres || !(*options.fieldOfViewMetres > 0.0) ||
                *options.fieldOfViewMetres > kMaximumFieldOfViewMetres)
                return failure("--fov: " + quoted(value) + " is not a field of view (more than 0, up to " +
                               formatQuantity(kMaximumFieldOfViewMetres) + " m)" +
                               numberWithUnitHint(value, false, [](double metres) {
                                   return metres > 0.0 && metres <= kMaximumFieldOfViewMetres;
                               }));
        } else if (flag == "--outputs") {
            if (auto problem = parseOutputKeys(value, options.outputKeys))
                return failure(*problem);
        } else if (flag == "--dense-paths") {
            options.densePaths = true;
        } else if (flag == "--cell-polygons") {
            options.cellPolygons = true;
        }
    }

    if (positionals.size() > 1)
        return failure("unexpected argument " + quoted(positionals[1]) + " (see mcpp --help)");

    if (!batch) {
        for (const auto flag : seen) {
            if (findFlag(flag)->batchOnly)
                return failure(std::string(flag) + " only applies with --batch");
        }
        options.mode = RunMode::Gui;
        if (!positionals.empty())
            options.guiFile = positionals.front();
        return {options, {}, 0};
    }

    options.mode = RunMode::Batch;
    const auto given = [&seen](std::string_view flag) {
        return std::find(seen.begin(), seen.end(), flag) != seen.end();
    };
    if (given("--fov") && given("--fov-scale"))
        return failure("--fov and --fov-scale cannot be used together: --fov sets every class's field of "
                       "view, --fov-scale multiplies the table's");
    if (given("--compare") && given("--planner"))
        return failure("--compare and --planner cannot be used together: --compare names the planners");
    if (!positionals.empty()) {
        options.missionPath = positionals.front();
        for (const std::string_view flag :
             {"--raster", "--classes", "--preset", "--start", "--start-crs", "--charger"}) {
            if (given(flag))
                return failure(std::string(flag) +
                               " cannot be combined with a mission file; the mission gives it");
        }
    } else {
        if (options.rasterPath.empty())
            return failure("--batch needs MISSION.json or --raster FILE");
        if (given("--classes") && given("--preset"))
            return failure("--classes and --preset cannot be used together");
        if (options.starts.empty())
            return failure("--raster needs at least one --start X,Y");
        if (!chargerWithoutStart.empty())
            return failure("--charger " + quoted(chargerWithoutStart) +
                           " comes before any --start: give it after the --start of its robot");
    }
    if (options.outputDirectory.empty())
        return failure("--batch needs --out DIR");
    return {options, {}, 0};
}

std::string CommandLine::usage() {
    std::ostringstream text;
    text
        << "Usage:\n"
           "  mcpp [MISSION.json | RASTER]\n"
           "      Opens the planner window, optionally with a mission or a land-cover raster.\n"
           "  mcpp --batch MISSION.json --out DIR [options]\n"
           "  mcpp --batch --raster FILE [--classes TABLE.csv | --preset NAME] --start X,Y [--charger X,Y]\n"
           "       [--start X,Y [--charger X,Y] ...] [--start-crs CRS] --out DIR [options]\n"
           "      Plans without a window and writes the outputs into DIR.\n"
           "\n"
           "Batch flags:\n"
           "  --batch                  plan headless; the only positional argument is then a mission file\n"
           "  -o, --out DIR            output folder, created when missing; existing files are replaced\n"
           "  --raster FILE            land-cover raster (any format GDAL reads)\n"
           "  --classes TABLE.csv      class table with columns value,name,speed_mps,fov_m,passable[,color]\n"
           "  --preset NAME            built-in class table instead of --classes. With neither, the\n"
           "                           table comes from the raster: the preset of a recognised product\n"
           "                           (ESA WorldCover, CORINE, NLCD, ...), else the file's legend\n"
           "  --start X,Y              a robot's start; give it once per robot. Coordinates are in the\n"
           "                           raster's CRS (longitude,latitude for a geographic raster) unless\n"
           "                           --start-crs says otherwise. Errors number the --start flags from 1\n"
           "                           in the order given, as the outputs number the robots\n"
           "  --start-crs CRS          CRS of the --start and --charger coordinates: EPSG:N (EPSG:4326\n"
           "                           for longitude,latitude), ESRI:N, or a PROJ or WKT definition\n"
           "  --charger X,Y            where the robot of the --start before it charges, for planners\n"
           "                           that run on batteries (wavefront-battery); robots without one\n"
           "                           charge at their start\n"
           "  --band N                 raster band holding the classes (default 1)\n"
           "  --area FILE              plan only inside the polygons of this vector file (any format\n"
           "                           GDAL reads; reprojected to the raster's CRS)\n"
           "  --no-go FILE             leave out the polygons of this vector file (no-go zones)\n"
           "  --planner NAME           planner to run (default mcpp-mlct; the list is below)\n"
           "  --param KEY=VALUE        a parameter of the planner (the list is below); repeatable\n"
           "  --purity F               same as --param purity_tolerance=F: a class covering at most this\n"
           "                           fraction of a cell does not split it (0 <= F < 1, default 0)\n"
           "  --missing-as-obstacle    treat raster values the class table lacks as obstacles instead of\n"
           "                           failing\n"
           "  --open-paths             same as --param closed_tour=false: paths stop at their last cell\n"
           "                           instead of returning to the start\n"
           "  --compare NAMES          run several planners on the mission (comma-separated names, or all)\n"
           "                           one after another: each one's outputs in DIR/<name>/, and in DIR\n"
           "                           comparison.csv, comparison.json and comparison.png. One-robot\n"
           "                           planners are skipped when there are several robots\n"
           "  --dense-paths            paths in plan.geojson and plan.gpkg through every sub-cell centre\n"
           "                           instead of only their turning points\n"
           "  --cell-polygons          add a polygon per cell to plan.gpkg (layer cells; big on large maps)\n"
           "  --outputs KEYS           write only these outputs (comma-separated keys, listed below;\n"
           "                           report.json is always written), e.g. report-json,png to compare\n"
           "                           planners on a large map without its waypoint files\n"
           "  --max-waypoints N        mission items every robot's autopilot holds, home included (0 for\n"
           "                           no limit; default: the mission's, else 700), in place of each\n"
           "                           robot's own. A longer mission is written in consecutive parts,\n"
           "                           robot_<n>_part_<j>.plan and .waypoints, each beginning where the\n"
           "                           one before it ended (j as 01, 02, ... from ten parts on)\n"
           "  --vehicle TYPE           what every robot is: rover (default), multirotor or fixed-wing;\n"
           "                           sets the waypoint files' vehicle type, and aircraft missions take\n"
           "                           off from the start and return to it\n"
           "  --altitude M             waypoint altitude above home in metres (default 30)\n"
           "  --cruise-speed M/S       every robot's speed in metres per second: the plan uses it over\n"
           "                           every passable class instead of the class table's speeds (a\n"
           "                           drone's speed does not follow the ground under it), and the waypoint\n"
           "                           files command it (0: the land-cover speeds, the default)\n"
           "  --flight-time T          the longest flight one battery allows, in seconds or with a unit\n"
           "                           (25min, 0.5h; at least 1 min; 0: no limit, the default): each\n"
           "                           robot's waypoint files are split into parts that each fit it, an\n"
           "                           aircraft's climb, trips from its start and back, and descent\n"
           "                           included. Leave your battery reserve out of it (say 20 of 25 min)\n"
           "  --turnaround T           time on the ground between two parts of a split mission (battery\n"
           "                           swap, next part uploaded), in seconds or with a unit (5min; 0, the\n"
           "                           default: not counted), in place of each robot's own:\n"
           "                           report.csv's mission_field_s adds it to the flights, and\n"
           "                           wavefront-battery charges for it between sorties (for recharge_s)\n"
           "  --camera-trigger M       a photo every M metres along each part's waypoints: the waypoint\n"
           "                           files start the camera at a part's first waypoint and stop it at\n"
           "                           its last (MAV_CMD_DO_SET_CAM_TRIGG_DIST; 0: no camera commands,\n"
           "                           the default), in place of each robot's own\n"
           "  --fov-scale F            every class's field of view times F, e.g. 4 for a drone whose\n"
           "                           camera sees four times as wide as the table's ground robot; land\n"
           "                           covers keep their proportions (forest half as far as grass)\n"
           "  --fov M                  every class's field of view set to M metres: a drone camera's\n"
           "                           footprint on the ground, the same over every land cover (for\n"
           "                           photos overlapping side by side, the footprint times one less the\n"
           "                           overlap: 42 for 30 % of a 60 m footprint)\n"
           "  --event T:ROBOT:FACTOR   from T seconds on, robot ROBOT (counted from 0: the first\n"
           "                           start, robot_1 in the outputs) drives at FACTOR times its speeds\n"
           "                           (0.5 half speed, 0 stopped); repeatable, added to the mission's\n"
           "                           events. Played by mdstc; report.json then gives each robot's\n"
           "                           completion_s and the static plan's static_makespan_s\n"
           "  --threads N              plan the robots' paths and write the outputs on N threads\n"
           "                           (default: the machine's cores); the files are the same whatever N\n"
           "  -q, --quiet              no progress lines, warnings or summary; errors are still printed\n"
           "\n"
           "Mission files (format: docs/mission-format.md) may be combined with --band, --area, --no-go,\n"
           "--planner, --param, --purity, --missing-as-obstacle, --open-paths, --dense-paths,\n"
           "--cell-polygons, --max-waypoints, --vehicle, --altitude, --cruise-speed, --flight-time,\n"
           "--turnaround, --camera-trigger, --fov-scale and --fov, which override the mission's values.\n"
           "\n"
           "Other flags:\n"
           "  -h, --help               this text\n"
           "  --help-planner NAME      a planner's parameters, their defaults, ranges and meaning\n"
           "  -v, --version            the version\n"
           "\n"
           "Outputs in DIR: plan.geojson, report.json, report.csv, plan.gpkg, regions.tif (the robot of "
           "each\n"
           "sub-cell as a GeoTIFF), plan.png and per robot n\n"
           "(numbered from 1, as on the map and in the \"robot\" fields of plan.geojson and report.json;\n"
           "padded with zeros from ten robots on: robot_01 to robot_12)\n"
           "robot_<n>.plan (QGroundControl), robot_<n>.waypoints (QGC WPL 110) and robot_<n>.csv; a mission\n"
           "above its robot's item limit is written as robot_<n>_part_<j>.plan and .waypoints instead (j "
           "padded\n"
           "with zeros from ten parts on: robot_1_part_01 to robot_1_part_12, in the order they are flown).\n"
           "A battery plan's robot has its sorties as those parts (more above the item limit), each from\n"
           "its charger and back; with a charger away from its start, the first sortie takes off at the\n"
           "start and lands at the charger;\n"
           "detection plans (cppied) add detection.tif (the chance a target is seen per sub-cell, and the\n"
           "chance required).\n"
           "\n"
           "Planners (mcpp --help-planner NAME lists one's parameters for --param):\n";
    std::size_t plannerWidth = 0;
    for (const PlannerDescription& planner : plannerDescriptions())
        plannerWidth = std::max(plannerWidth, planner.name.size());
    for (const PlannerDescription& planner : plannerDescriptions())
        text << "  " << planner.name << std::string(plannerWidth - planner.name.size() + 2, ' ')
             << planner.summary << (planner.singleRobot ? " (one robot)" : "") << "\n";
    text << "\nPresets:\n";
    const auto presets = io::classTablePresets();
    std::size_t nameWidth = 0;
    for (const auto& preset : presets)
        nameWidth = std::max(nameWidth, preset.name.size());
    for (const auto& preset : presets) {
        text << "  " << preset.name << std::string(nameWidth - preset.name.size() + 2, ' ')
             << preset.description << '\n';
    }
    text << "\nOutputs for --outputs (* written by default):\n";
    std::size_t keyWidth = 0;
    std::size_t fileWidth = 0;
    for (const io::ExportFormat& format : io::exportFormats()) {
        keyWidth = std::max(keyWidth, format.key.size());
        fileWidth = std::max(fileWidth, io::batchOutputName(format).size());
    }
    for (const io::ExportFormat& format : io::exportFormats()) {
        const std::string file = io::batchOutputName(format);
        text << "  " << format.key << std::string(keyWidth - format.key.size() + 1, ' ')
             << (format.inBatchOutputs ? "* " : "  ") << file << std::string(fileWidth - file.size() + 2, ' ')
             << format.label << '\n';
    }
    text << "\nExit status: 0 success, 2 bad input (one line on stderr says what), 1 internal error,\n"
            "3 with --compare when some planners failed (their rows in comparison.csv say why).\n";
    return text.str();
}

std::string CommandLine::plannerHelp(const std::string& name) {
    const auto planner = findPlannerDescription(name);
    if (!planner)
        return unknownPlannerMessage(name) + "\n";
    std::ostringstream text;
    describePlanner(text, *planner);
    return text.str();
}

std::string CommandLine::versionText() {
    return std::string("mcpp ") + MCPP_VERSION + "\n";
}

} // namespace mcpp::app
