#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/Plan.hpp"
#include "core/model/RobotSorties.hpp"
#include "io/Mission.hpp"
#include "io/VehicleSettings.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::io {

// Consecutive waypoints of a mission, first and last included; a part after the first begins at the
// waypoint where the one before it ended, or, for a sortie of its own, at a waypoint of its own there.
struct MissionPart {
    std::size_t first = 0;
    std::size_t last = 0;
    int items = 0;        // its mission items, home and first speed command included
    double seconds = 0.0; // its flight, as partSeconds times it
    // The point an aircraft takes off from and returns to: the first of its sortie (its charger, or the
    // robot's start for the first sortie), the mission's first point when it flies no sorties.
    std::size_t home = 0;
    // An aircraft lands at its last point instead of returning home: the end of a sortie flown from the
    // robot's start to a charger elsewhere.
    bool landsAtLast = false;
};

// A robot's path as an autopilot flies it: its turning points and the points where the commanded speed
// changes, the speed commanded on the segment that ends at each point, and the parts the vehicle's item
// limit splits it into.
struct AutopilotMission {
    std::vector<Waypoint> points;
    std::vector<double> commandedSpeeds; // by point; the first is the speed the mission starts with
    std::vector<MissionPart> parts;
    int items = 0; // of the whole mission in one file
    // Where an aircraft takes off and lands when not at the first point (CoveragePath::takeOff).
    std::optional<MapPoint> takeOff;
    // The battery sorties it flies from a charger, a part or more each (sortieMission); 0: none.
    std::size_t sorties = 0;
    // Whether its first sortie leaves from the robot's start, away from the charger it ends at.
    bool firstSortieFromStart = false;
    // The time at the charger between two sorties (robotMission, from the battery plan).
    double rechargeSeconds = 0.0;
    // The time to fly it at the commanded speeds (each segment at the speed commanded for it) with the
    // plan's turn time; 0 when a speed is unknown.
    double seconds = 0.0;

    // Where a part takes off: its home point, unless the mission takes off elsewhere (in no cell of the
    // plan).
    [[nodiscard]] Waypoint homeOf(const MissionPart& part) const {
        if (!takeOff)
            return points[part.home];
        Waypoint there = points.front();
        there.x = takeOff->x;
        there.y = takeOff->y;
        there.cell = -1;
        return there;
    }

    // Whether time passes at a charger between its sorties.
    [[nodiscard]] bool chargesBetweenSorties() const { return sorties > 0 && rechargeSeconds > 0.0; }

    // Whether the vehicle is told a new speed before driving to this point.
    [[nodiscard]] bool changesSpeedAt(std::size_t point) const {
        return point > 0 && commandedSpeeds[point] != commandedSpeeds[point - 1];
    }
};

// A land-cover speed as a vehicle is told it: two significant digits (0.3168 -> 0.32 m/s, 12.34 -> 12).
[[nodiscard]] double roundedSpeed(double metresPerSecond);
// The same rounded down (0.3168 -> 0.31, 12.34 -> 12), for speeds that must not exceed the land cover's.
[[nodiscard]] double roundedDownSpeed(double metresPerSecond);

// The mission of a path. Speeds: the vehicle's cruise speed when it has one, else each waypoint's rounded
// land-cover speed, commanded anew only where it differs from the speed in force by more than
// settings.speedTolerance (a fraction of that speed; 0 commands every change); with
// speedChangesAtTurnsOnly, each straight leg at the slowest land-cover speed along it, rounded down (a leg
// keeps the speed before it when it would allow at most the tolerance more). With mergeCollinear, a point on
// the straight segment between its neighbours that commands no new speed is left out. Parts hold at most
// the vehicle's maxWaypoints items (home, a first speed command, waypoints and speed changes) and each fits
// its flightTimeSeconds as partSeconds times it (cells: the plan's, for the turns); with a flight time, legs
// get points along them so that a part can end part way. A part beyond one flight's reach holds a flight's
// work.
[[nodiscard]] AutopilotMission autopilotMission(const CoveragePath& path, const VehicleSettings& vehicle,
                                                const ExportSettings& settings, const CellGraph& cells);

// Seconds one part of a mission takes at its commanded speeds, turning where the plan prices turns (cells:
// the plan's); an aircraft's part also flies from home (AutopilotMission::homeOf) to its first waypoint
// and back from its last (unless it lands there), so that each flight can be held against a battery. 0 when
// a speed is unknown.
[[nodiscard]] double partSeconds(const AutopilotMission& mission, const MissionPart& part,
                                 const VehicleSettings& vehicle, const CellGraph& cells);

// How far an aircraft at its cruise speed can fly out and come back in one flight, its climb and descent
// taken out; 0 for a rover, or without a cruise speed or a flight time.
[[nodiscard]] double flightReachMetres(const VehicleSettings& vehicle);
// The same for each vehicle, in order: what the map rings round the robots' starts.
[[nodiscard]] std::vector<double> flightReachesMetres(const std::vector<VehicleSettings>& vehicles);
// How far the part's farthest waypoint lies from where it takes off (AutopilotMission::homeOf).
[[nodiscard]] double farthestFromHome(const AutopilotMission& mission, const MissionPart& part);

// What a mission's parts fly, held against the vehicle's flight time.
struct MissionFlights {
    double totalSeconds = 0.0; // all its parts, an aircraft's trips from and back to its home included
    double longestSeconds = 0.0;
    std::size_t overFlightTime = 0; // parts longer than the flight time; none without one
    // The flights and the vehicle's turnarounds between them (the time at the charger before each sortie
    // after the first): when the robot is done in the field; 0 when a part's time is unknown.
    double fieldSeconds = 0.0;
};
// Whether a part takes longer than the vehicle's flight time (never without one, or with a speed unknown).
[[nodiscard]] bool exceedsFlightTime(const MissionPart& part, const VehicleSettings& vehicle);
[[nodiscard]] MissionFlights missionFlights(const AutopilotMission& mission, const VehicleSettings& vehicle);

// About how many photos a camera set to vehicle.cameraTriggerMetres takes over the mission: in each part one
// where it starts, one every so many metres along the waypoints and one where it stops; 0 without a camera.
[[nodiscard]] std::int64_t missionPhotos(const AutopilotMission& mission, const VehicleSettings& vehicle);

// How big a robot's waypoint files come out: what the results panel shows before anything is exported.
struct MissionSize {
    int items = 0;         // of the whole mission in one file
    std::size_t parts = 0; // the files the vehicle's item limit and flight time split it into
    double longestPartSeconds = 0.0;
    std::size_t partsOverFlightTime = 0; // out of one flight's reach: a part holds at least two points
    double fieldSeconds = 0.0;           // the flights and the turnarounds between them
    std::size_t sorties = 0;             // battery sorties from a charger, each a part or more; 0: none
};
// How the window and the exports say that a robot's flights (a rover's mission parts) outlast its battery:
// "Robot 1: 305 of its 883 flights take up to 1 h 9 min with the flights to and from its start, longer than
// its 20 min flight time". Why, and which files, follow; flightsTooLongAdvice ends the sentence.
[[nodiscard]] std::string flightsTooLongLead(const std::string& robotName, const VehicleSettings& vehicle,
                                             std::size_t parts, std::size_t partsOver, double longestSeconds);
// Why, in general: "its region reaches beyond what one flight from its start can cover".
[[nodiscard]] std::string flightsTooLongCause(const VehicleSettings& vehicle);
// "Add robots, start them nearer that land, or plan with wavefront-battery and chargers" (a rover cannot
// start nearer: its stretches are too long wherever it starts).
[[nodiscard]] std::string flightsTooLongAdvice(const VehicleSettings& vehicle);
// Whether a robot flies several sorties from a charger, each ending at it and each but the first leaving
// from it: the first leaves from the robot's start, at the charger or away from it.
[[nodiscard]] bool fliesSortiesFromACharger(const CoveragePath& path, const RobotSorties* sorties);
// The mission of a robot that flies `sorties` of its path from a charger: each sortie's mission
// (autopilotMission) one after the other, so that each sortie is a part of its own, or more above the item
// limit, and the files are the flights the plan times. Each part takes off from its sortie's first point; a
// first sortie from a start away from the charger lands at the charger. Its items are those of all the
// sorties' files.
[[nodiscard]] AutopilotMission sortieMission(const CoveragePath& path, const std::vector<Sortie>& sorties,
                                             const VehicleSettings& vehicle, const ExportSettings& settings,
                                             const CellGraph& cells);
// The mission the waypoint files make of a robot's path: its sorties' where it flies them from a charger,
// else the whole path's.
[[nodiscard]] AutopilotMission robotMission(const Plan& plan, const CoveragePath& path,
                                            const VehicleSettings& vehicle, const ExportSettings& settings);
// The size of the mission of a robot's path in the plan, made as the waypoint files make it.
[[nodiscard]] MissionSize missionSize(const Plan& plan, const CoveragePath& path,
                                      const VehicleSettings& vehicle, const ExportSettings& settings);

// `number` padded with zeros to the width of `last` ("03" of 12): numbered files a file list sorts in order.
[[nodiscard]] std::string paddedNumber(std::size_t number, std::size_t last);

// The file of one part of a split mission in `parts`: "out/robot_1.plan" -> "out/robot_1_part_2.plan" (part
// from 0), the number padded with zeros to the width of `parts` ("robot_1_part_02.plan" of 12) so that a file
// list sorts the parts in the order they are flown.
[[nodiscard]] std::string missionPartPath(const std::string& path, std::size_t part, std::size_t parts);
// The file a mission's part is written to: `path` itself for a mission in one part, else missionPartPath.
[[nodiscard]] std::string missionFilePath(const std::string& path, std::size_t part, std::size_t parts);

// The file of one of a robot's `sorties` when it charges between flights: "out/robot_1.plan" ->
// "out/robot_1_sortie_2.plan" (sortie from 0, padded as parts are). A sortie above the item limit is split
// into its own parts.
[[nodiscard]] std::string missionSortiePath(const std::string& path, std::size_t sortie, std::size_t sorties);

// Removes what an earlier export to `path` left that this one did not write: the whole file when the mission
// was written in parts, and every part file beside it that is not one of this export's `parts` (all of them
// when it was written whole: parts 1, or not at all: 0), whatever its number's padding. True when a file
// went.
bool removeStaleMissionFiles(const std::string& path, std::size_t parts);

// Removes the sortie files (and their parts) an earlier export to `path` wrote that are not among this
// export's `written` sorties (0: none).
void removeStaleSortieFiles(const std::string& path, std::size_t written);

// Removes the files of a per-robot format (`extension` without its dot: "csv", "plan") an earlier batch run
// left in `folder` that one of `robots` robots does not write: those of robots it does not have and those
// whose number is padded to another width ("robot_3.csv" beside "robot_03.csv" of 12), with their parts and
// sorties.
void removeStaleRobotFiles(const std::string& folder, const std::string& extension, int robots);

} // namespace mcpp::io
