#include "io/AutopilotMission.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/SortieLayer.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/StraightLine.hpp"
#include "io/internal/TextFiles.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::io {
namespace {

using internal::collinearAndBetween;

// A commanded speed along a path as steps: each holds from its first waypoint up to the next step's. A step
// begins only where the land cover's speed changes, at most once a cell (two waypoints): a large map's path
// holds tens of millions of waypoints, and a speed per waypoint took 8 bytes each (370 MB for one robot on
// a 69 M-cell map).
struct SpeedStep {
    std::size_t first = 0;
    double speed = 0.0;
};
using SpeedSteps = std::vector<SpeedStep>; // by first waypoint, ascending; the first step begins at 0

// Reads the speed of waypoints taken in ascending order.
class SpeedCursor {
  public:
    explicit SpeedCursor(const SpeedSteps& steps) : steps_(steps) {}
    [[nodiscard]] double at(std::size_t waypoint) {
        while (next_ < steps_.size() && steps_[next_].first <= waypoint)
            speed_ = steps_[next_++].speed;
        return speed_;
    }

  private:
    const SpeedSteps& steps_;
    std::size_t next_ = 0;
    double speed_ = 0.0;
};

// The commanded speed along the path, as steps: a new one only when it differs enough from the one before.
SpeedSteps commandedSpeeds(const std::vector<Waypoint>& waypoints, const VehicleSettings& vehicle,
                           double speedTolerance) {
    SpeedSteps steps{{0, vehicle.cruiseSpeedMetresPerSecond}};
    if (vehicle.cruiseSpeedMetresPerSecond > 0.0 || waypoints.empty())
        return steps;
    double current = roundedSpeed(waypoints.front().speedMetresPerSecond);
    steps.front().speed = current;
    // Runs of waypoints share a land cover's speed: rounded once a run (a logarithm and a power each time).
    float lastSpeed = waypoints.front().speedMetresPerSecond;
    double wanted = current;
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
        if (waypoints[i].speedMetresPerSecond == lastSpeed)
            continue;
        lastSpeed = waypoints[i].speedMetresPerSecond;
        wanted = roundedSpeed(lastSpeed);
        // A relative margin keeps a change of exactly the tolerance (1.1 after 1.0 at 10%) below it.
        if (wanted > 0.0 && std::abs(wanted - current) > speedTolerance * current * (1.0 + 1e-9)) {
            current = wanted;
            steps.push_back({i, current});
        }
    }
    return steps;
}

// The slowest land-cover speed of the waypoints from first to last, rounded down: no segment between them
// is then driven faster than its land cover allows.
double slowestSpeed(const std::vector<Waypoint>& waypoints, std::size_t first, std::size_t last) {
    float slowest = 0.0F;
    for (std::size_t i = first; i <= last; ++i) {
        const float speed = waypoints[i].speedMetresPerSecond;
        if (speed > 0.0F && (slowest == 0.0F || speed < slowest))
            slowest = speed;
    }
    return roundedDownSpeed(internal::decimalDouble(slowest)); // 0.7F as 0.7, not 0.69999998807907
}

// Each straight leg at the slowest speed along it, so that speeds change only at turns, with no waypoint in
// the middle of a leg. The tolerance only keeps a slower speed into a leg that allows a little more, never
// the reverse. A leg's speed holds from the waypoint after its start to its end; the first leg's from the
// path's start.
SpeedSteps slowestSpeedPerLeg(const std::vector<Waypoint>& waypoints, double speedTolerance) {
    SpeedSteps steps{{0, 0.0}};
    double current = 0.0;
    std::size_t legStart = 0;
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
        const bool legEnds = i + 1 == waypoints.size() ||
                             !collinearAndBetween(waypoints[i - 1], waypoints[i], waypoints[i + 1]);
        if (!legEnds)
            continue;
        const double slowest = slowestSpeed(waypoints, legStart, i);
        if (current == 0.0 || slowest < current || slowest > current * (1.0 + speedTolerance) * (1.0 + 1e-9))
            current = slowest;
        if (legStart == 0)
            steps.front().speed = current;
        else if (current != steps.back().speed)
            steps.push_back({legStart + 1, current});
        legStart = i;
    }
    return steps;
}

// The points the mission keeps and their speeds, read from the whole path without copying it (a large
// map's paths hold tens of millions of points).
void keepPoints(const std::vector<Waypoint>& points, const SpeedSteps& speeds, bool mergeCollinear,
                AutopilotMission& mission) {
    SpeedCursor speedHere(speeds);
    SpeedCursor speedNext(speeds);
    const auto keep = [&](std::size_t i) {
        mission.points.push_back(points[i]);
        mission.commandedSpeeds.push_back(speedHere.at(i));
    };
    if (points.empty())
        return;
    keep(0);
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        // Dropping point i is exact when the segment after it is commanded the same speed.
        if (mergeCollinear && collinearAndBetween(mission.points.back(), points[i], points[i + 1]) &&
            speedHere.at(i) == speedNext.at(i + 1))
            continue;
        keep(i);
    }
    if (points.size() > 1)
        keep(points.size() - 1);
}

double flightSeconds(const AutopilotMission& mission) {
    double seconds = 0.0;
    for (std::size_t i = 1; i < mission.points.size(); ++i) {
        const double speed = mission.commandedSpeeds[i];
        if (!(speed > 0.0))
            return 0.0;
        const Waypoint& from = mission.points[i - 1];
        const Waypoint& to = mission.points[i];
        seconds += std::hypot(to.x - from.x, to.y - from.y) / speed;
    }
    return seconds;
}

// The time of one flight along a part of a mission, kept as points are added, so that a part can be held
// against a battery point by point: the legs at their commanded speeds, the turns priced as the plan prices
// them, and for an aircraft its climb to the mission's altitude, the trips from home
// (AutopilotMission::homeOf) and back (none back when it lands at its last point), and its descent.
class FlightClock {
  public:
    static constexpr std::size_t noLanding = std::numeric_limits<std::size_t>::max();

    // landing: the point where a flight ending there lands (noLanding: each flight returns home).
    FlightClock(const AutopilotMission& mission, const VehicleSettings& vehicle, const CellGraph& cells,
                std::size_t landing = noLanding)
        : mission_(&mission), cells_(&cells), landing_(landing), fromHome_(isAircraft(vehicle.type)),
          climbSeconds_(fromHome_ ? vehicle.altitudeMetres / climbMetresPerSecond : 0.0),
          descentSeconds_(fromHome_ ? vehicle.altitudeMetres / descentMetresPerSecond : 0.0) {}

    // A new flight from the part's home to its first point.
    void begin(const MissionPart& part) {
        unknown_ = false;
        heading_.reset();
        last_ = part.first;
        part_ = part;
        seconds_ = climbSeconds_;
        if (fromHome_)
            fly(mission_->homeOf(part_), mission_->points[part.first], mission_->commandedSpeeds[part.first]);
        tripOut_ = seconds_;
    }
    // On to the next point of the mission.
    void extend() {
        ++last_;
        fly(mission_->points[last_ - 1], mission_->points[last_], mission_->commandedSpeeds[last_]);
    }
    // The flight ending at the last point added (and back home unless it lands there); 0 when a speed is
    // unknown.
    [[nodiscard]] double seconds() const {
        FlightClock ended = *this;
        if (fromHome_ && last_ != landing_)
            ended.fly(mission_->points[last_], mission_->homeOf(part_), mission_->commandedSpeeds[last_]);
        return ended.unknown_ ? 0.0 : ended.seconds_ + descentSeconds_;
    }
    // The same without the trips from home and back: the work one flight does.
    [[nodiscard]] double workSeconds() const { return unknown_ ? 0.0 : seconds_ - tripOut_; }

  private:
    void fly(const Waypoint& from, const Waypoint& to, double speed) {
        const double dx = to.x - from.x;
        const double dy = to.y - from.y;
        const double length = std::hypot(dx, dy);
        if (length == 0.0)
            return;
        unknown_ = unknown_ || !(speed > 0.0);
        seconds_ += speed > 0.0 ? length / speed : 0.0;
        if (heading_)
            seconds_ += turnSecondsAt(from, heading_->first, heading_->second, dx, dy, *cells_);
        heading_ = std::make_pair(dx, dy);
    }

    const AutopilotMission* mission_;
    const CellGraph* cells_;
    std::size_t landing_ = noLanding;
    bool fromHome_ = false;
    double climbSeconds_ = 0.0;
    double descentSeconds_ = 0.0;
    double seconds_ = 0.0;
    double tripOut_ = 0.0;
    bool unknown_ = false;
    std::optional<std::pair<double, double>> heading_; // of the last leg of non-zero length
    std::size_t last_ = 0;
    MissionPart part_; // the part flown, for where it takes off
};

// Legs split into pieces of at most a fortieth of a flight, so that a part can end part way along a leg
// longer than what is left of a battery: a survey's straight legs run for kilometres, and a part ending
// only at turns would lose up to a leg's flight to each cut, or not fit a flight at all. A flight at the
// edge of its working reach has a twentieth left (FlightLimits::workingReachMetres): a piece and the turns
// at its ends fit it (pieces of a twentieth took parts there 13 s over a 20 min flight).
void splitLongLegs(AutopilotMission& mission, double flightSeconds) {
    constexpr double piecesPerFlight = 40.0;
    const double pieceSeconds = flightSeconds / piecesPerFlight;
    AutopilotMission split;
    for (std::size_t point = 0; point < mission.points.size(); ++point) {
        const double speed = mission.commandedSpeeds[point];
        if (point > 0 && speed > 0.0) {
            const Waypoint& from = mission.points[point - 1];
            const Waypoint& to = mission.points[point];
            const double seconds = std::hypot(to.x - from.x, to.y - from.y) / speed;
            const int pieces = static_cast<int>(std::ceil(seconds / pieceSeconds));
            for (int piece = 1; piece < pieces; ++piece) {
                const double along = static_cast<double>(piece) / pieces;
                Waypoint between = along < 0.5 ? from : to; // its cell, for the price of a turn there
                between.x = from.x + along * (to.x - from.x);
                between.y = from.y + along * (to.y - from.y);
                split.points.push_back(between);
                split.commandedSpeeds.push_back(speed);
            }
        }
        split.points.push_back(mission.points[point]);
        split.commandedSpeeds.push_back(speed);
    }
    mission.points = std::move(split.points);
    mission.commandedSpeeds = std::move(split.commandedSpeeds);
}

// The seconds of one flight along the mission from its first point to `last`.
double wholeFlight(FlightClock clock, std::size_t last) {
    clock.begin({0, 0});
    for (std::size_t point = 0; point < last; ++point)
        clock.extend();
    return clock.seconds();
}

// What one part may hold: items (home and first speed command included) and seconds of flight (0: any).
struct PartLimits {
    int items = 0;
    double seconds = 0.0;
};

// Whether a part beginning at `first` could fit a flight of `limit` with its next point: a part out of
// reach ends where ground within reach begins again, so that the flights there fit.
bool flightFitsFrom(FlightClock clock, std::size_t first, double limit) {
    clock.begin({first, first});
    clock.extend();
    return clock.seconds() <= limit;
}

// The parts a mission splits into when each keeps within the limits, filled one after the other, with their
// flights' seconds when timed (0 otherwise). A part holds at least two points. One whose flight is already
// longer than the limit (a stretch out of one flight's reach of the start) goes on until its work alone,
// without the trips, would be (cut at every point, it would make a file a point), or until a part beginning
// at its last point would fit again.
std::vector<MissionPart> partsFilledUpTo(const AutopilotMission& mission, PartLimits limits, int beside,
                                         FlightClock clock) {
    const bool timed = limits.seconds > 0.0;
    std::vector<MissionPart> parts;
    MissionPart part{0, 0, beside + 1};
    double soFar = 0.0; // seconds of the part's flight so far, when timed
    if (timed)
        clock.begin(part);
    for (std::size_t point = 1; point < mission.points.size(); ++point) {
        const int added = mission.changesSpeedAt(point) ? 2 : 1;
        FlightClock longer = clock;
        double longerSeconds = 0.0;
        if (timed) {
            longer.extend();
            longerSeconds = longer.seconds();
        }
        const bool tooLong = timed && longerSeconds > limits.seconds &&
                             (soFar <= limits.seconds || longer.workSeconds() > limits.seconds ||
                              flightFitsFrom(clock, part.last, limits.seconds));
        if ((part.items + added > limits.items || tooLong) && part.last > part.first) {
            part.seconds = soFar;
            parts.push_back(part);
            part = {part.last, part.last, beside + 1};
            if (timed) {
                clock.begin(part);
                longer = clock;
                longer.extend();
                longerSeconds = longer.seconds();
            }
        }
        clock = longer;
        soFar = longerSeconds;
        part.last = point;
        part.items += added;
    }
    part.seconds = soFar;
    parts.push_back(part);
    return parts;
}

// As few parts as the limits allow, as even as they can be: the smallest share of the limits that needs no
// more parts than filling each to the limits does. Filled to the limits alone, the last part could hold three
// items or a minute's flight. landsAtEnd: the last part lands at the mission's last point.
void splitIntoParts(AutopilotMission& mission, const VehicleSettings& vehicle, const CellGraph& cells,
                    bool landsAtEnd) {
    const std::size_t count = mission.points.size();
    if (count == 0)
        return;
    const int beside = itemsBesideWaypoints(vehicle);
    mission.items = beside + 1;
    for (std::size_t point = 1; point < count; ++point)
        mission.items += mission.changesSpeedAt(point) ? 2 : 1;
    FlightClock clock(mission, vehicle, cells, landsAtEnd ? count - 1 : FlightClock::noLanding);
    const int itemLimit = vehicle.maxWaypoints > 0 ? vehicle.maxWaypoints : std::numeric_limits<int>::max();
    const PartLimits full{itemLimit, vehicle.flightTimeSeconds};
    // A mission that fits one flight is one part, though filling would cut it where a return home from
    // part way would be too long: a sortie that lands at a charger away from its start, or comes back
    // near home after flying far.
    if (mission.items <= itemLimit && !(full.seconds > 0.0 && wholeFlight(clock, count - 1) > full.seconds)) {
        mission.parts = {{0, count - 1, mission.items}};
        mission.parts.back().landsAtLast = landsAtEnd;
        return;
    }
    std::vector<MissionPart> parts = partsFilledUpTo(mission, full, beside, clock);
    const std::size_t fewest = parts.size();
    // Parts out of one flight's reach go on for a flight's work: with a smaller share of the flight, more of
    // them would, and parts that fit a flight would no longer. Counted in legs, not parts: a smaller share
    // may merge many parts that fit (near the edge of the reach, each a leg or two) into a few that do not.
    const auto overFlight = [&](const std::vector<MissionPart>& tried) {
        std::size_t legs = 0;
        if (full.seconds > 0.0)
            for (const MissionPart& part : tried)
                legs += part.seconds > full.seconds ? part.last - part.first : 0;
        return legs;
    };
    const std::size_t fewestOver = overFlight(parts);
    // Two waypoints with a speed change between them are the least a part holds.
    const auto share = [&](double fraction) {
        return PartLimits{std::max(beside + 3, static_cast<int>(std::min<double>(itemLimit, 1e9) * fraction)),
                          full.seconds * fraction};
    };
    double tooSmall = 0.0;
    double enough = 1.0;
    while (fewest > 1 && enough - tooSmall > 1e-4) {
        const double fraction = (tooSmall + enough) / 2.0;
        std::vector<MissionPart> tried = partsFilledUpTo(mission, share(fraction), beside, clock);
        if (tried.size() <= fewest && overFlight(tried) <= fewestOver) {
            enough = fraction;
            parts = std::move(tried);
        } else {
            tooSmall = fraction;
        }
    }
    mission.parts = std::move(parts);
    mission.parts.back().landsAtLast = landsAtEnd;
}

// autopilotMission, whose last part lands at the path's end when landsAtEnd.
AutopilotMission missionOfPath(const CoveragePath& path, const VehicleSettings& vehicle,
                               const ExportSettings& settings, const CellGraph& cells, bool landsAtEnd) {
    AutopilotMission mission;
    mission.takeOff = path.takeOff;
    const bool byLeg = settings.speedChangesAtTurnsOnly && !(vehicle.cruiseSpeedMetresPerSecond > 0.0);
    const SpeedSteps speeds = byLeg ? slowestSpeedPerLeg(path.waypoints, settings.speedTolerance)
                                    : commandedSpeeds(path.waypoints, vehicle, settings.speedTolerance);
    keepPoints(path.waypoints, speeds, settings.mergeCollinear, mission);
    // A mission that fits one flight keeps its legs whole.
    if (vehicle.flightTimeSeconds > 0.0 && !mission.points.empty()) {
        MissionPart whole{0, mission.points.size() - 1};
        whole.landsAtLast = landsAtEnd;
        if (partSeconds(mission, whole, vehicle, cells) > vehicle.flightTimeSeconds)
            splitLongLegs(mission, vehicle.flightTimeSeconds);
    }
    splitIntoParts(mission, vehicle, cells, landsAtEnd);
    for (MissionPart& part : mission.parts)
        part.seconds = partSeconds(mission, part, vehicle, cells);
    const double flight = flightSeconds(mission);
    // Turns are made at the same points, so they cost what the plan priced them at.
    mission.seconds = flight > 0.0 ? flight + path.turnSeconds : 0.0;
    return mission;
}

} // namespace

double roundedDownSpeed(double metresPerSecond) {
    if (!(metresPerSecond > 0.0) || !std::isfinite(metresPerSecond))
        return 0.0;
    const int decimals = 1 - static_cast<int>(std::floor(std::log10(metresPerSecond)));
    const double scale = std::pow(10.0, std::abs(decimals));
    // A hair above the product, so that 0.29 * 100 = 28.999999999999996 still rounds down to 29.
    const double down = decimals > 0 ? std::floor(metresPerSecond * scale * (1.0 + 1e-12)) / scale
                                     : std::floor(metresPerSecond / scale * (1.0 + 1e-12)) * scale;
    return down > 0.0 ? down : metresPerSecond;
}

double roundedSpeed(double metresPerSecond) {
    if (!(metresPerSecond > 0.0) || !std::isfinite(metresPerSecond))
        return 0.0;
    const int digitsBeforePoint = static_cast<int>(std::floor(std::log10(metresPerSecond))) + 1;
    const int decimals = 2 - digitsBeforePoint;
    // Divide by a power of ten rather than multiply by its inverse, so that 0.32 comes out as 0.32.
    if (decimals > 0) {
        const double scale = std::pow(10.0, decimals);
        return std::round(metresPerSecond * scale) / scale;
    }
    const double scale = std::pow(10.0, -decimals);
    return std::round(metresPerSecond / scale) * scale;
}

AutopilotMission autopilotMission(const CoveragePath& path, const VehicleSettings& vehicle,
                                  const ExportSettings& settings, const CellGraph& cells) {
    return missionOfPath(path, vehicle, settings, cells, false);
}

double partSeconds(const AutopilotMission& mission, const MissionPart& part, const VehicleSettings& vehicle,
                   const CellGraph& cells) {
    FlightClock clock(mission, vehicle, cells, part.landsAtLast ? part.last : FlightClock::noLanding);
    clock.begin(part);
    for (std::size_t point = part.first; point < part.last; ++point)
        clock.extend();
    return clock.seconds();
}

double farthestFromHome(const AutopilotMission& mission, const MissionPart& part) {
    const Waypoint start = mission.homeOf(part);
    double farthest = 0.0;
    for (std::size_t point = part.first; point <= part.last; ++point)
        farthest = std::max(farthest,
                            std::hypot(mission.points[point].x - start.x, mission.points[point].y - start.y));
    return farthest;
}

std::vector<double> flightReachesMetres(const std::vector<VehicleSettings>& vehicles) {
    std::vector<double> reaches;
    reaches.reserve(vehicles.size());
    for (const VehicleSettings& vehicle : vehicles)
        reaches.push_back(flightReachMetres(vehicle));
    return reaches;
}

double flightReachMetres(const VehicleSettings& vehicle) {
    if (!isAircraft(vehicle.type) || !(vehicle.cruiseSpeedMetresPerSecond > 0.0) ||
        !(vehicle.flightTimeSeconds > 0.0))
        return 0.0;
    return std::max(0.0, vehicle.flightTimeSeconds - climbAndDescentSeconds(vehicle)) *
           vehicle.cruiseSpeedMetresPerSecond / 2.0;
}

bool fliesSortiesFromACharger(const CoveragePath& path, const RobotSorties* sorties) {
    if (sorties == nullptr || sorties->sorties.size() < 2 || path.takeOff || path.waypoints.empty())
        return false;
    const std::size_t chargerPoint = sorties->sorties.front().lastWaypoint;
    if (sorties->sorties.front().firstWaypoint != 0 || chargerPoint >= path.waypoints.size())
        return false;
    const Waypoint& charger = path.waypoints[chargerPoint];
    constexpr double sameMetres = 1e-6; // a charger on a cell's centre may come back as that centre
    const auto atCharger = [&](std::size_t waypoint) {
        return waypoint < path.waypoints.size() &&
               std::hypot(path.waypoints[waypoint].x - charger.x, path.waypoints[waypoint].y - charger.y) <=
                   sameMetres;
    };
    return std::all_of(sorties->sorties.begin() + 1, sorties->sorties.end(), [&](const Sortie& sortie) {
        return atCharger(sortie.firstWaypoint) && atCharger(sortie.lastWaypoint);
    });
}

AutopilotMission sortieMission(const CoveragePath& path, const std::vector<Sortie>& sorties,
                               const VehicleSettings& vehicle, const ExportSettings& settings,
                               const CellGraph& cells) {
    AutopilotMission whole; // no takeOff: each sortie leaves from its first point
    whole.sorties = sorties.size();
    for (const Sortie& sortie : sorties) {
        const CoveragePath flightPath = sortiePath(path, sortie);
        const Waypoint& from = flightPath.waypoints.front();
        const Waypoint& to = flightPath.waypoints.back();
        // A first sortie from a start away from the charger lands there: a return to launch would fly
        // back to the start.
        const bool landsAway = std::hypot(to.x - from.x, to.y - from.y) > 1e-6;
        if (whole.parts.empty())
            whole.firstSortieFromStart = landsAway;
        AutopilotMission flight = missionOfPath(flightPath, vehicle, settings, cells, landsAway);
        // Each sortie keeps its own first point, at the charger where the one before ended, so that its
        // file commands the speed it starts with.
        const std::size_t offset = whole.points.size();
        whole.points.insert(whole.points.end(), flight.points.begin(), flight.points.end());
        whole.commandedSpeeds.insert(whole.commandedSpeeds.end(), flight.commandedSpeeds.begin(),
                                     flight.commandedSpeeds.end());
        for (MissionPart part : flight.parts) {
            part.first += offset;
            part.last += offset;
            part.home += offset;
            whole.parts.push_back(part);
        }
        whole.items += flight.items;
    }
    const double flight = flightSeconds(whole);
    whole.seconds = flight > 0.0 ? flight + path.turnSeconds : 0.0;
    return whole;
}

AutopilotMission robotMission(const Plan& plan, const CoveragePath& path, const VehicleSettings& vehicle,
                              const ExportSettings& settings) {
    if (const RobotSorties* sorties = sortiesOfRobot(plan, path.robot);
        fliesSortiesFromACharger(path, sorties)) {
        AutopilotMission mission = sortieMission(path, sorties->sorties, vehicle, settings, plan.cells);
        mission.rechargeSeconds = sorties->rechargeSeconds;
        return mission;
    }
    CoveragePath whole;
    return autopilotMission(pathForWaypointFiles(path, plan.cells, settings.mergeCollinear, whole), vehicle,
                            settings, plan.cells);
}

MissionSize missionSize(const Plan& plan, const CoveragePath& path, const VehicleSettings& vehicle,
                        const ExportSettings& settings) {
    const AutopilotMission mission = robotMission(plan, path, vehicle, settings);
    const MissionFlights flights = missionFlights(mission, vehicle);
    return {mission.items,          mission.parts.size(), flights.longestSeconds,
            flights.overFlightTime, flights.fieldSeconds, mission.sorties};
}

std::string flightsTooLongLead(const std::string& robotName, const VehicleSettings& vehicle,
                               std::size_t parts, std::size_t partsOver, double longestSeconds) {
    const bool aircraft = isAircraft(vehicle.type);
    const std::string which = parts == 1 ? "its mission takes "
                                         : std::to_string(partsOver) + " of its " + std::to_string(parts) +
                                               (aircraft ? " flights" : " mission parts") +
                                               (partsOver == 1 ? " takes" : " take") + " up to ";
    return robotName + ": " + which + formatDuration(longestSeconds) +
           (aircraft ? " with the flights to and from its start" : "") + ", longer than its " +
           formatDuration(vehicle.flightTimeSeconds) + " " + batteryTimeName(vehicle.type);
}

std::string flightsTooLongCause(const VehicleSettings& vehicle) {
    return isAircraft(vehicle.type) ? "its region reaches beyond what one flight from its start can cover"
                                    : "its path has stretches longer than one battery lasts";
}

std::string flightsTooLongAdvice(const VehicleSettings& vehicle) {
    return isAircraft(vehicle.type)
               ? "Add robots, start them nearer that land, or plan with wavefront-battery and chargers"
               : "Add robots, or plan with wavefront-battery and chargers";
}

bool exceedsFlightTime(const MissionPart& part, const VehicleSettings& vehicle) {
    return vehicle.flightTimeSeconds > 0.0 && part.seconds > vehicle.flightTimeSeconds;
}

std::int64_t missionPhotos(const AutopilotMission& mission, const VehicleSettings& vehicle) {
    if (!(vehicle.cameraTriggerMetres > 0.0))
        return 0;
    std::int64_t photos = 0;
    for (const MissionPart& part : mission.parts) {
        double metres = 0.0;
        for (std::size_t point = part.first + 1; point <= part.last; ++point)
            metres += std::hypot(mission.points[point].x - mission.points[point - 1].x,
                                 mission.points[point].y - mission.points[point - 1].y);
        photos += static_cast<std::int64_t>(std::floor(metres / vehicle.cameraTriggerMetres)) + 2;
    }
    return photos;
}

MissionFlights missionFlights(const AutopilotMission& mission, const VehicleSettings& vehicle) {
    MissionFlights flights;
    for (const MissionPart& part : mission.parts) {
        flights.totalSeconds += part.seconds;
        flights.longestSeconds = std::max(flights.longestSeconds, part.seconds);
        if (exceedsFlightTime(part, vehicle))
            ++flights.overFlightTime;
    }
    // Unknown, as the flights, where a speed is unknown: turnarounds alone would read as a time.
    const bool timed = std::all_of(mission.parts.begin(), mission.parts.end(),
                                   [](const MissionPart& part) { return part.seconds > 0.0; });
    // A sortie's first part takes off from its first point; a part the item limit cut off does not.
    double between = 0.0;
    for (std::size_t part = 1; part < mission.parts.size(); ++part)
        between += mission.sorties > 0 && mission.parts[part].first == mission.parts[part].home
                       ? mission.rechargeSeconds
                       : vehicle.turnaroundSeconds;
    if (timed)
        flights.fieldSeconds = flights.totalSeconds + between;
    return flights;
}

namespace {

// "robot_1.plan", "_part_", 2 of 12 -> "robot_1_part_03.plan".
std::string numberedPath(const std::string& path, const std::string& tag, std::size_t index,
                         std::size_t count) {
    const std::filesystem::path file(path);
    return (file.parent_path() /
            (file.stem().string() + tag + paddedNumber(index + 1, count) + file.extension().string()))
        .string();
}

bool digits(const std::string& text) {
    return !text.empty() &&
           std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

// Whether `text` is what may follow a numbered file's number: nothing, its part, its sortie or its sortie's
// part ("", "_part_2", "_sortie_3", "_sortie_3_part_2").
bool isNumberedFileTail(const std::string& text) {
    std::string rest = text;
    for (const std::string tag : {"_sortie_", "_part_"}) {
        if (!rest.starts_with(tag))
            continue;
        const std::size_t end = rest.find('_', tag.size());
        if (!digits(rest.substr(tag.size(), end == std::string::npos ? std::string::npos : end - tag.size())))
            return false;
        rest = end == std::string::npos ? std::string() : rest.substr(end);
    }
    return rest.empty();
}

// The numbered files with `tag` an export to `path` may have written beside it ("robot_1_sortie_7.plan",
// "robot_1_sortie_07.plan" for "robot_1.plan" and "_sortie_"), whatever their number's padding, each named
// once, also where only its parts or sorties are there ("robot_1_sortie_7_part_2.plan").
std::vector<std::filesystem::path> numberedFilesBeside(const std::string& path, const std::string& tag) {
    namespace fs = std::filesystem;
    const fs::path file(path);
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    const std::string prefix = file.stem().string() + tag;
    const std::string extension = file.extension().string();
    std::vector<fs::path> found;
    std::error_code code;
    for (fs::directory_iterator entry(folder, code), end; !code && entry != end; entry.increment(code)) {
        const std::string name = entry->path().filename().string();
        if (name.size() <= prefix.size() + extension.size() || !name.starts_with(prefix) ||
            !name.ends_with(extension))
            continue;
        const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
        const std::size_t tail = middle.find('_');
        const std::string number = middle.substr(0, tail);
        if (!digits(number) || !isNumberedFileTail(tail == std::string::npos ? "" : middle.substr(tail)))
            continue;
        const fs::path numbered = file.parent_path() / (prefix + number + extension);
        if (std::find(found.begin(), found.end(), numbered) == found.end())
            found.push_back(numbered);
    }
    return found;
}

// Whether `file` (one numberedFilesBeside found) is one of the `count` numbered files of `path` with `tag`:
// its number as wide as the last one's and at most it.
bool isWritten(const std::filesystem::path& file, const std::string& path, const std::string& tag,
               std::size_t count) {
    const std::string name = file.stem().string();
    const std::string number = name.substr(std::filesystem::path(path).stem().string().size() + tag.size());
    const std::string last = std::to_string(count);
    return count > 0 && number.size() == last.size() && number >= std::string(number.size() - 1, '0') + "1" &&
           number <= last;
}

} // namespace

std::string paddedNumber(std::size_t number, std::size_t last) {
    std::string text = std::to_string(number);
    const std::size_t width = std::to_string(std::max(number, last)).size();
    return std::string(width - text.size(), '0') + text;
}

std::string missionPartPath(const std::string& path, std::size_t part, std::size_t parts) {
    return numberedPath(path, "_part_", part, parts);
}

std::string missionFilePath(const std::string& path, std::size_t part, std::size_t parts) {
    return parts > 1 ? missionPartPath(path, part, parts) : path;
}

std::string missionSortiePath(const std::string& path, std::size_t sortie, std::size_t sorties) {
    return numberedPath(path, "_sortie_", sortie, sorties);
}

bool removeStaleMissionFiles(const std::string& path, std::size_t parts) {
    std::error_code code;
    bool removed = parts > 1 && std::filesystem::remove(path, code);
    const std::size_t written = parts > 1 ? parts : 0;
    for (const std::filesystem::path& file : numberedFilesBeside(path, "_part_"))
        if (!isWritten(file, path, "_part_", written))
            removed = std::filesystem::remove(file, code) || removed;
    return removed;
}

void removeStaleSortieFiles(const std::string& path, std::size_t written) {
    std::error_code code;
    for (const std::filesystem::path& file : numberedFilesBeside(path, "_sortie_"))
        if (!isWritten(file, path, "_sortie_", written)) {
            std::filesystem::remove(file, code);
            removeStaleMissionFiles(file.string(), 0);
        }
}

void removeStaleRobotFiles(const std::string& folder, const std::string& extension, int robots) {
    // Robot files are numbered files of "robot.<extension>" with "_" before the number.
    const std::string pattern = (std::filesystem::path(folder) / ("robot." + extension)).string();
    std::error_code code;
    for (const std::filesystem::path& file : numberedFilesBeside(pattern, "_"))
        if (!isWritten(file, pattern, "_", static_cast<std::size_t>(std::max(robots, 0)))) {
            std::filesystem::remove(file, code);
            removeStaleMissionFiles(file.string(), 0);
            removeStaleSortieFiles(file.string(), 0);
        }
}

} // namespace mcpp::io
