#include "core/planners/Planner.hpp"

#include "core/coverage/OwnSpeeds.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/SpeedEventCheck.hpp"
#include "core/model/StartPointCheck.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/model/TurnTimeModel.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/AreaEdgeCheck.hpp"
#include "core/planners/ClosedInStart.hpp"
#include "core/planners/LandBeyondReach.hpp"
#include "core/planners/PlanMetricsCalculator.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "core/planners/PlanningRun.hpp"
#include "core/planners/UncoveredLand.hpp"
#include "core/planners/UnevenField.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

std::string multiRobotPlanners() {
    std::string names;
    for (const PlannerDescription& planner : plannerDescriptions())
        if (!planner.singleRobot)
            names += (names.empty() ? "" : ", ") + planner.name;
    return names;
}

// Bad starts are wrong whatever the cells: say so before building them.
void checkStarts(const PlannerDescription& planner, const PlanningProblem& problem, bool snap) {
    if (problem.starts.empty())
        throw PlanningError(Kind::InvalidParameter, "no robots: give at least one start point");
    if (problem.starts.size() > mostRobots)
        throw PlanningError(Kind::TooManyRobots, std::to_string(problem.starts.size()) +
                                                     " robots: one plan takes at most " +
                                                     std::to_string(mostRobots));
    if (planner.singleRobot && problem.starts.size() > 1)
        throw PlanningError(
            Kind::InvalidParameter,
            planner.name + " plans for one robot, but " + std::to_string(problem.starts.size()) +
                " starts were given; planners that take several robots: " + multiRobotPlanners());
    for (std::size_t robot = 0; robot < problem.starts.size(); ++robot) {
        const auto problemAtStart = startPointProblem(problem.grid, problem.classes, problem.starts[robot]);
        if (!problemAtStart)
            continue;
        const bool snappable = problemAtStart->kind != Kind::InvalidParameter;
        // An aircraft takes off where it stands and flies to its path (PlanningRun::locateStarts), except
        // on batteries: those sorties start from the start's cell.
        const bool takesOff =
            !planner.fliesOnBatteries() && robotTakesOffThere(problem.flyingRobots, robot, problem.grid,
                                                              problem.starts[robot], *problemAtStart);
        if (!snappable || !(snap || takesOff))
            throw PlanningError::aboutStart(
                problemAtStart->kind, static_cast<int>(robot),
                startRefusal(problem.grid, problem.classes, problem.starts[robot], *problemAtStart));
    }
}

void checkEvents(const PlanningProblem& problem) {
    for (std::size_t index = 0; index < problem.events.size(); ++index)
        if (const auto wrong = speedEventProblem(problem.events[index], problem.starts.size()))
            throw PlanningError(Kind::InvalidParameter, "event " + std::to_string(index + 1) + " " +
                                                            wrong->field + ": " + wrong->detail);
}

// The names of the registered planners that `has` holds for, comma-separated.
template <typename Predicate> std::string plannerNamesWhere(Predicate has) {
    std::string names;
    for (const PlannerDescription& other : plannerDescriptions())
        if (has(other))
            names += (names.empty() ? "" : ", ") + other.name;
    return names;
}

std::string eventsIgnoredMessage(const PlannerDescription& planner) {
    return planner.label +
           " plans without events: the mission's events are left out (planners that play them: " +
           plannerNamesWhere([](const PlannerDescription& other) { return other.simulatesEvents; }) + ")";
}

std::string ownSpeedsUnbalancedMessage(const PlannerDescription& planner) {
    return planner.label +
           " divides the work as if every robot drove at the class table's speeds: robots of their own "
           "speeds are timed at them and finish at other times (planners that balance them: " +
           plannerNamesWhere([](const PlannerDescription& other) { return other.balancesOwnSpeeds; }) + ")";
}

// Robots of their own speeds drive every path at them, whatever the planner made of them; a plan whose
// layers (detection, a timeline) were timed while planning keeps the class table's speeds, unless its
// planner planned them at the robots' own.
void applyOwnSpeeds(const PlannerDescription& planner, const PlanningProblem& problem, PlanningRun& run) {
    if (!someOwnSpeed(problem.robotSpeeds))
        return;
    Plan& plan = run.plan();
    if (planner.balancesOwnSpeeds) {
        // Its paths were driven at them as it planned: timing them again is a pass over every waypoint.
        plan.robotSpeeds = problem.robotSpeeds;
        return;
    }
    if (!plan.layers.empty()) {
        // The mission's note that each robot is timed at its own speed does not hold for this plan.
        std::erase_if(plan.issues,
                      [](const PlanIssue& issue) { return issue.code == "cruise-speeds-differ"; });
        plan.metrics.ownSpeedsIgnored = true;
        run.addIssue(IssueSeverity::Warning, "own-speeds-ignored",
                     planner.label + " times every robot at the class table's speeds: the robots' own speeds "
                                     "are left out of its plan");
        return;
    }
    plan.robotSpeeds = problem.robotSpeeds;
    driveAtOwnSpeeds(plan.paths, plan.cells, plan.robotSpeeds);
    if (problem.starts.size() > 1)
        run.addIssue(IssueSeverity::Warning, "own-speeds-unbalanced", ownSpeedsUnbalancedMessage(planner));
}

std::string chargersIgnoredMessage(const PlannerDescription& planner) {
    return planner.label +
           " plans without batteries: the robots' chargers are left out (planners that fly on batteries: " +
           plannerNamesWhere([](const PlannerDescription& other) { return other.fliesOnBatteries(); }) + ")";
}

// idle: the part holds under half an even share of the land per robot in it (`share` of one), so the robot
// stands idle most of the mission. byReach: the robot's region borders the land left out beyond every
// flight's reach, whose edge, not the land cover, may be what cuts it off.
std::string confinedRobotMessage(const ConfinedRobot& confined, double share, bool idle, bool byReach) {
    const std::string others =
        confined.robotsInPocket > 1
            ? " with " + std::to_string(confined.robotsInPocket - 1) + " other robot(s)"
            : "";
    const std::string advice =
        byReach ? "start it nearer the other robots, or give it a longer flight time or a faster cruise "
                  "speed, so that its flights reach the land between them and share the work"
                : "start it in the largest part to share the work";
    return "robot " + std::to_string(confined.robot + 1) +
           " starts in a part of the map cut off from the rest (" +
           formatArea(confined.pocketAreaSquareMetres) +
           (idle ? ", " + formatPercent(share) + " of an even share of the land" : std::string()) + ")" +
           (byReach ? " by the land beyond every flight's reach or by impassable land," : std::string()) +
           " and can cover only that part" + others +
           "; the lower bound counts each part with its own robots" +
           (idle ? "; it stands idle most of the mission: " + advice : std::string());
}

// "robot 3", "robots 3 and 4", "robots 3, 4 and 10" (counted from 1); past a dozen, "and 40 more".
std::string robotList(const std::vector<int>& robots) {
    constexpr std::size_t named = 12;
    std::string list = robots.size() == 1 ? "robot " : "robots ";
    const std::size_t shown = robots.size() > named + 1 ? named : robots.size(); // never "and 1 more"
    for (std::size_t i = 0; i < shown; ++i) {
        if (i > 0)
            list += i + 1 == robots.size() ? " and " : ", ";
        list += std::to_string(robots[i] + 1);
    }
    if (shown < robots.size())
        list += " and " + std::to_string(robots.size() - shown) + " more";
    return list;
}

// Where a drone's geofence follows the area's edge, it would be crossed: said with how far. The planner
// knows the area by its pixels, those whose centres the drawn edge encloses: the edge runs within half a
// pixel of their border, so waypoints that near may lie on the right side of it, and a fence needs that
// half pixel more.
std::string beyondAreaMessage(const WaypointsBeyondArea& beyond) {
    const bool noGoOnly = beyond.inNoGoZones == beyond.waypoints;
    const std::string where = beyond.inNoGoZones == 0 ? "on pixels outside the area of interest"
                              : noGoOnly              ? "on pixels of a no-go zone"
                                         : "on pixels outside the area of interest or of a no-go zone";
    const double halfPixel = beyond.pixelMetres / 2.0;
    // Counted at the sub-cell centres the paths pass through: the waypoint files hold only the turning
    // points, so a count of "waypoints" would not match what a user finds in them.
    const bool one = beyond.robots.size() == 1;
    std::string text = (one ? "the path of " : "the paths of ") + robotList(beyond.robots) +
                       (one ? " passes over " : " pass over ") + where.substr(std::string("on ").size()) +
                       " at " + std::to_string(beyond.waypoints) +
                       (beyond.waypoints == 1 ? " sub-cell centre" : " sub-cell centres") + ", up to " +
                       formatDistance(beyond.farthestMetres) +
                       " past the task area's pixels: cells that straddle the edge are covered whole";
    if (beyond.farthestMetres <= halfPixel)
        text += "; the edge as drawn runs within half a pixel (" + formatDistance(halfPixel) +
                ") of those pixels' border, so those centres may lie " +
                (noGoOnly ? "outside the zone as drawn" : "inside the area as drawn");
    const std::string margin = formatDistance(beyond.farthestMetres + halfPixel);
    return text + ". For a drone whose geofence follows that edge, draw " +
           (noGoOnly ? "the no-go zone " + margin + " larger" : "the area " + margin + " inside the fence");
}

// Paths past the raster's edge: what a robot would find there is not on the map, and a drone's geofence
// drawn round the raster would be crossed.
std::string beyondRasterMessage(const WaypointsBeyondRaster& beyond) {
    const bool one = beyond.robots.size() == 1;
    return (one ? "the path of " : "the paths of ") + robotList(beyond.robots) +
           (one ? " passes " : " pass ") + "beyond the raster's edge at " + std::to_string(beyond.waypoints) +
           (beyond.waypoints == 1 ? " sub-cell centre" : " sub-cell centres") + ", up to " +
           formatDistance(beyond.farthestMetres) +
           " past it, over ground the map says nothing of: cells the edge cuts through are covered"
           " whole where the part beyond, counted as obstacle, is within the blocked threshold. A lower"
           " blocked threshold leaves those cells out, and the land inside them uncovered";
}

// "Balanced pieces": the label of the planner's switch that evens its pieces out.
std::string switchLabel(const PlannerDescription& planner) {
    for (const ParameterSpec& spec : planner.parameters)
        if (spec.key == planner.balanceSwitch)
            return spec.label;
    return planner.balanceSwitch;
}

// "set Balanced pieces on (balanced=true)": the planner's switch that evens its pieces out.
std::string balanceSwitchAdvice(const PlannerDescription& planner) {
    return "set " + switchLabel(planner) + " on (" + planner.balanceSwitch +
           "=true) to cut pieces of equal time";
}

// "robot 2's start is closed in by the starts of robots 1 and 3, so its region can hold no more than
// 100 m2" for each robot short of work whose start is, where regions hold their starts. A robot of its own
// speed is timed at it: its share of the bound is in cover time over its pace.
std::string closedInStartsText(const Plan& plan, const PlannerDescription& planner,
                               const std::vector<int>& shortOfWork) {
    if (!planner.promises.regionsConnected)
        return {};
    const std::vector<double> paces = robotPaces(plan.cells, plan.robotSpeeds, plan.paths.size());
    constexpr int described = 3; // the others are counted, so that the advice after them is read
    std::string text;
    int closedIn = 0;
    for (const int robot : shortOfWork) {
        const double enough = 0.5 * plan.metrics.lowerBoundSeconds / paceOf(paces, std::size_t(robot));
        const auto closed = closedInStart(plan, robot, enough);
        if (!closed || ++closedIn > described)
            continue;
        text += "robot " + std::to_string(robot + 1) + "'s start is closed in by the " +
                (closed->closedBy.size() == 1 ? "start of " : "starts of ") + robotList(closed->closedBy) +
                ", so its region can hold no more than " + formatArea(closed->areaSquareMetres) + "; ";
    }
    if (closedIn > described)
        text += closedIn - described == 1 ? "the start of one more robot is closed in too; "
                                          : "the starts of " + std::to_string(closedIn - described) +
                                                " more robots are closed in too; ";
    return text;
}

// Where every region holds its robot's start, robots set off from one base wall each other in. A planner
// whose switch cuts pieces of equal time needs no start inside them (MSTC's balanced pieces: on the
// crowded-start maps of bench/crowded-starts.sh, 1.03-1.13 times the bound where MCPP-MLCT warns at
// 1.08-2.09). Only planners that balance robots of their own speeds are offered for a fleet of them.
std::string passingOtherStartsAdvice(const Plan& plan) {
    std::string advice;
    for (const PlannerDescription& other : plannerDescriptions()) {
        if (other.singleRobot || other.promises.regionsConnected || other.balanceSwitch.empty() ||
            (!plan.robotSpeeds.empty() && !other.balancesOwnSpeeds))
            continue;
        advice += "; or plan with " + other.label + " and " + switchLabel(other) + " on (planner " +
                  other.name + ", " + other.balanceSwitch +
                  "=true), whose robots go past the others' starts to pieces of equal time";
    }
    return advice;
}

// Robots left with less than half a fair share where the longest path is well above the bound (on batteries,
// whose bound prices each robot's reach, also where it is not: the short battery is then named): most often
// starts so close together that the others' regions wall theirs in, or, where the planner has a switch
// that evens its pieces out (PlannerDescription::balanceSwitch) and it is off, the reason it gives. Empty
// where there are none, and on maps whose starts lie in several parts (the bound is then one part's share,
// not every robot's).
std::string unevenPlanMessage(const Plan& plan, const PlannerDescription& planner) {
    const PlanMetrics& metrics = plan.metrics;
    const ParameterValues& parameters = plan.parameters;
    constexpr double noticeableRatio = 1.05;
    // On batteries the bound prices each robot's reach: a plan near it may still leave a robot idle.
    if (!(metrics.ratio > noticeableRatio || planner.fliesOnBatteries()) ||
        !(metrics.lowerBoundSeconds > 0.0) || !metrics.confinedRobots.empty())
        return {};
    std::vector<int> shortOfWork;
    for (const RobotMetrics& robot : metrics.robots)
        if (robot.timeSeconds < 0.5 * metrics.lowerBoundSeconds)
            shortOfWork.push_back(robot.robot);
    if (shortOfWork.empty())
        return {};
    std::ostringstream ratio;
    ratio.precision(3);
    ratio << metrics.ratio;
    if (!(metrics.ratio > noticeableRatio))
        return robotList(shortOfWork) + (shortOfWork.size() == 1 ? " covers" : " cover") +
               " less than half of a fair share: a short battery, or a slow robot's, leaves a robot little "
               "within reach of its charger, and no plan is done much sooner (the longest path takes " +
               ratio.str() +
               " times the lower bound, which counts each robot's reach); a charger nearer the "
               "work, or a longer battery, shares the work out";
    const std::string uneven = robotList(shortOfWork) + (shortOfWork.size() == 1 ? " covers" : " cover") +
                               " less than half of a fair share, and the longest path takes " + ratio.str() +
                               " times the lower bound: ";
    if (!planner.balanceSwitch.empty() && parameters.has(planner.balanceSwitch) &&
        !parameters.boolean(planner.balanceSwitch))
        return uneven + planner.unbalancedBecause + "; " + balanceSwitchAdvice(planner);
    return uneven + closedInStartsText(plan, planner, shortOfWork) +
           (planner.fliesOnBatteries()
                ? "a short battery, or a slow robot's, leaves a robot little within reach of its charger, "
                  "and "
                  "starts close together leave robots walled in by the others' regions; a charger nearer "
                  "the work, or starts spread over the area, even the plan out"
                : "starts close together leave robots walled in by the others' regions; spread over the "
                  "area, they even the plan out" +
                      (planner.promises.regionsConnected ? passingOtherStartsAdvice(plan) : ""));
}

// Land no robot covers, and why. Land a planner on batteries leaves beyond their reach is warned of where
// it is left out (beyond-battery, beyond-every-charger).
// reachEdge: land beyond every aircraft's reach was left out of the task area (LandBeyondReach), so its edge
// may cut land off too.
std::vector<std::string> uncoveredLandMessages(const UncoveredLand& land, const PlannerDescription& planner,
                                               bool reachEdge) {
    std::vector<std::string> messages;
    if (land.cutOffSquareMetres > 0.0) {
        const std::string where = land.cutOffPieces == 1
                                      ? "it lies round " + describePoint(land.largestPieceCentre)
                                      : "in " + std::to_string(land.cutOffPieces) + " pieces, the largest (" +
                                            formatArea(land.largestPieceSquareMetres) + ") round " +
                                            describePoint(land.largestPieceCentre);
        messages.push_back(
            formatArea(land.cutOffSquareMetres) +
            " of passable land cannot be reached by any robot: impassable land" +
            (reachEdge ? ", the area's edge or the edge of the flights' reach" : " or the area's edge") +
            " cuts it off from every start (" + where + "); a robot started there would cover it");
    }
    if (land.leftOutSquareMetres > 0.0 && !planner.fliesOnBatteries())
        messages.push_back(formatArea(land.leftOutSquareMetres) +
                           " of passable land joined to a start is covered by no robot");
    return messages;
}

// Each robot's time in the field, as the problem measures it, and the last robot's.
void measureFieldTimes(Plan& plan, const std::vector<double>& fieldSeconds) {
    PlanMetrics& metrics = plan.metrics;
    metrics.fieldMakespanSeconds = 0.0;
    for (std::size_t robot = 0; robot < metrics.robots.size() && robot < fieldSeconds.size(); ++robot) {
        metrics.robots[robot].fieldSeconds = fieldSeconds[robot];
        metrics.fieldMakespanSeconds = std::max(metrics.fieldMakespanSeconds, fieldSeconds[robot]);
    }
}

std::vector<double> fieldTimesOf(const PlanMetrics& metrics) {
    std::vector<double> seconds;
    for (const RobotMetrics& robot : metrics.robots)
        seconds.push_back(robot.fieldSeconds);
    return seconds;
}

double stagesMilliseconds(const PlanMetrics& metrics) {
    double sum = 0.0;
    for (const auto& [stage, milliseconds] : metrics.stageMilliseconds)
        sum += milliseconds;
    return sum;
}

// By robot, its seconds in the field for a second of its path as the plan flies it; 1 where unknown.
std::vector<double> fieldPacesFlown(const Plan& plan, const std::vector<double>& fieldSeconds) {
    std::vector<double> paces;
    for (std::size_t robot = 0; robot < plan.paths.size() && robot < fieldSeconds.size(); ++robot)
        paces.push_back(
            plan.paths[robot].timeSeconds > 0.0 ? fieldSeconds[robot] / plan.paths[robot].timeSeconds : 1.0);
    return paces;
}

// The paces flown over those the division already counted (PlanningRun::fieldPaces); 1 where either time
// is unknown.
std::vector<double> measuredFieldPaces(const Plan& plan, const std::vector<double>& fieldSeconds) {
    std::vector<double> paces = fieldPacesFlown(plan, fieldSeconds);
    paces.resize(plan.paths.size(), 1.0);
    for (std::size_t robot = 0; robot < paces.size() && robot < fieldSeconds.size(); ++robot)
        paces[robot] = plan.paths[robot].timeSeconds > 0.0 && fieldSeconds[robot] > 0.0
                           ? paces[robot] / fieldPaceOf(plan.countedFieldPaces, robot)
                           : 1.0;
    return paces;
}

// Whether the robot whose trips the division counted dearest is not the last home: cells weighed by their
// trips then gave it too little.
bool tripsOverCounted(const Plan& plan, const std::vector<double>& fieldSeconds) {
    const std::vector<double>& counted = plan.countedFieldPaces;
    if (counted.empty() || counted.size() != fieldSeconds.size())
        return false;
    return std::max_element(counted.begin(), counted.end()) - counted.begin() !=
           std::max_element(fieldSeconds.begin(), fieldSeconds.end()) - fieldSeconds.begin();
}

double longestOf(const std::vector<double>& seconds) {
    return seconds.empty() ? 0.0 : *std::max_element(seconds.begin(), seconds.end());
}

// Within 1 % of each other.
bool evenInTheField(const std::vector<double>& seconds) {
    return seconds.empty() || longestOf(seconds) <= 1.01 * *std::min_element(seconds.begin(), seconds.end());
}

// measured: the paces were measured on the plan before; else they are those the division counted.
std::string fieldPacesMessage(const std::vector<double>& paces, bool measured) {
    std::ostringstream text;
    text.precision(2);
    text << std::fixed << "the division evens out time in the field rather than on the paths: each robot's "
         << "mission in parts (an aircraft's climbs, descents and trips out to its work) and the turnarounds "
         << "between them take";
    for (std::size_t robot = 0; robot < paces.size(); ++robot)
        text << (robot == 0 ? " robot " : ", robot ") << robot + 1 << " " << fieldPaceOf(paces, robot)
             << " x";
    text << " its path's time, "
         << (measured ? "as measured on the plan before"
                      : "as the division counts them (work farther from where an aircraft takes off costs it "
                        "longer trips)")
         << "; the paths' times differ by design";
    return text.str();
}
bool leftOutBeyondReach(const ClassGrid& grid) {
    return std::find(grid.outside.begin(), grid.outside.end(), ClassGrid::beyondFlightReach) !=
           grid.outside.end();
}

// The land left out beyond every reach is passable land no robot covers: the plan's figures count it.
void countLandBeyondReach(Plan& plan, LandBeyondReach& land) {
    plan.landBeyondReach = std::move(land.passable);
    PlanMetrics& metrics = plan.metrics;
    metrics.passableAreaSquareMetres += land.passableSquareMetres;
    metrics.unreachableAreaSquareMetres += land.passableSquareMetres;
    metrics.coveredFraction = metrics.passableAreaSquareMetres > 0.0
                                  ? metrics.coveredAreaSquareMetres / metrics.passableAreaSquareMetres
                                  : 0.0;
    plan.issues.push_back({IssueSeverity::Warning, "beyond-flight-reach", landBeyondReachMessage(land)});
}
} // namespace

ParameterSpec Planner::snapStartsParameter() {
    return booleanParameter(
        "snap_starts_to_free_cells", "Move blocked starts to the nearest free cell", false,
        "A start on an obstacle, outside the area or in another robot's cell is moved to the "
        "nearest free cell, with a warning, instead of being refused");
}

PlannerDescription Planner::description() const {
    PlannerDescription own = describe();
    own.parameters.push_back(TurnTimeModel::turnSecondsParameter());
    own.parameters.push_back(TurnTimeModel::accelerationParameter());
    own.parameters.push_back(snapStartsParameter());
    return own;
}

Plan Planner::plan(const PlanningProblem& problem, const ProgressReporter& progress) const {
    return plan(problem, problem.planner.parameters, progress);
}

Plan Planner::plan(const PlanningProblem& problem, const ParameterValues& given,
                   const ProgressReporter& progress) const {
    const PlannerDescription planner = description();
    // Aircraft would fly flights longer than their batteries to land none of them reaches: it is left out.
    // Planners on batteries plan their sorties from chargers and say what they leave.
    if (!planner.fliesOnBatteries()) {
        const auto begin = std::chrono::steady_clock::now();
        if (std::optional<LandBeyondReach> beyond = landBeyondEveryReach(problem)) {
            if (!beyond->reachedPassable)
                throw PlanningError(PlanningError::Kind::NoPassableCell, nothingWithinReachMessage(*beyond));
            PlanningProblem within = problem;
            within.grid.outside = std::move(beyond->outside);
            const std::chrono::duration<double, std::milli> found = std::chrono::steady_clock::now() - begin;
            Plan plan = planWithinReach(planner, within, given, progress, *beyond);
            plan.metrics.stageMilliseconds.insert(plan.metrics.stageMilliseconds.begin(),
                                                  {"flight reach", found.count()});
            countLandBeyondReach(plan, *beyond);
            return plan;
        }
    }
    return planWithin(planner, problem, given, progress);
}

Plan Planner::planWithinReach(const PlannerDescription& planner, const PlanningProblem& problem,
                              const ParameterValues& given, const ProgressReporter& progress,
                              const LandBeyondReach& beyond) const {
    try {
        return planWithin(planner, problem, given, progress);
    } catch (const PlanningError& error) {
        // Cells too large for what is left within reach: the reach is why, not the land cover.
        if (error.kind() == PlanningError::Kind::NoPassableCell)
            throw PlanningError(PlanningError::Kind::NoPassableCell, nothingWithinReachMessage(beyond));
        throw;
    }
}

Plan Planner::planWithin(const PlannerDescription& planner, const PlanningProblem& problem,
                         const ParameterValues& given, const ProgressReporter& progress) const {
    if (planner.balancesFieldTime && problem.fieldSeconds)
        return planInFieldTime(planner, problem, given, progress);
    return planOnce(planner, problem, given, progress, {});
}

Plan Planner::planInFieldTime(const PlannerDescription& planner, const PlanningProblem& problem,
                              const ParameterValues& given, const ProgressReporter& progress) const {
    // Each round plans the whole problem again; the first does most.
    constexpr int fieldBalanceRounds = 2;
    const double roundShare = 1.0 / (fieldBalanceRounds + 2); // the rounds and the division on the paths
    // The rounds plan the same cells: the first builds them, the others copy them.
    std::optional<CellGraph> cells;
    Plan best = planOnce(planner, problem, given, progress.scaled(0.0, roundShare), {{}, {}, &cells});
    if (!(best.metrics.fieldMakespanSeconds > 0.0))
        return best; // its times in the field are not measured (planOnce says where)
    std::vector<double> bestField = fieldTimesOf(best.metrics);
    double dropped = 0.0; // milliseconds of the plans not kept
    // Keeps the plan that brings the last robot home sooner; false where that is still the best.
    const auto keepSooner = [&](Plan next) {
        std::vector<double> nextField = fieldTimesOf(next.metrics);
        if (!(longestOf(nextField) < longestOf(bestField))) {
            dropped += stagesMilliseconds(next.metrics);
            return false;
        }
        dropped += stagesMilliseconds(best.metrics);
        best = std::move(next);
        bestField = std::move(nextField);
        return true;
    };
    for (int round = 1; round <= fieldBalanceRounds; ++round) {
        const std::vector<double> paces = measuredFieldPaces(best, bestField);
        // Paces within 5 % of each other divide the map about as before (one flight's climb and descent).
        if (longestOf(paces) <= 1.05 * *std::min_element(paces.begin(), paces.end()) ||
            evenInTheField(bestField))
            break;
        const std::vector<double> flown = fieldPacesFlown(best, bestField);
        if (!keepSooner(
                planOnce(planner, problem, given,
                         progress.within("field time balance", round * roundShare, (round + 1) * roundShare),
                         {paces, flown, &cells})))
            break;
    }
    // Cells weighed by their trips can over-correct (each priced at its own distance, while a flight flies
    // out to where its work begins and back from where it ends): there a division on the paths, each
    // robot's path weighed by its pace in the field as flown on the plan kept, is tried too.
    if (!evenInTheField(bestField) && tripsOverCounted(best, bestField)) {
        const std::vector<double> flown = fieldPacesFlown(best, bestField);
        keepSooner(planOnce(planner, problem, given,
                            progress.within("field time balance", 1.0 - roundShare, 1.0),
                            {flown, flown, &cells, false}));
    }
    // Weighed cells and measured paces both move the border by what the plan before them flew; where
    // neither evened the robots out, the division on the paths alone is tried, and from it divisions with
    // each robot's path weighed by the geometric mean of its pace in the field as flown and the pace its
    // division counted (half way on a log scale): the pace grows with the ground taken from another robot
    // (farther out, dearer trips), so the whole step overshoots.
    if (!evenInTheField(bestField)) {
        constexpr int pathPaceRounds = 4;
        const auto onPaths = [&](std::vector<double> paces) {
            return planOnce(planner, problem, given,
                            progress.within("field time balance", 1.0 - roundShare, 1.0),
                            {paces, paces, &cells, false});
        };
        Plan current = onPaths({});
        std::vector<double> counted(current.paths.size(), 1.0);
        for (int round = 0; round < pathPaceRounds; ++round) {
            const std::vector<double> currentField = fieldTimesOf(current.metrics);
            if (evenInTheField(currentField))
                break;
            std::vector<double> paces = fieldPacesFlown(current, currentField);
            paces.resize(counted.size(), 1.0);
            for (std::size_t robot = 0; robot < paces.size(); ++robot)
                paces[robot] = std::sqrt(paces[robot] * counted[robot]);
            Plan next = onPaths(paces);
            if (!(longestOf(fieldTimesOf(next.metrics)) < longestOf(currentField))) {
                keepSooner(std::move(next));
                break;
            }
            keepSooner(std::move(current));
            current = std::move(next);
            counted = std::move(paces);
        }
        keepSooner(std::move(current));
    }
    // The plans made and dropped took time too: the report's timings add up to what the user waited.
    if (dropped > 0.0)
        best.metrics.stageMilliseconds.emplace_back("field time rounds", dropped);
    progress.report("done", 1.0);
    return best;
}

Plan Planner::planOnce(const PlannerDescription& planner, const PlanningProblem& problem,
                       const ParameterValues& given, const ProgressReporter& progress,
                       FieldRound round) const {
    ParameterValues parameters = resolveParameters(planner.parameters, given);
    checkStarts(planner, problem, parameters.boolean("snap_starts_to_free_cells"));
    checkEvents(problem);
    Plan plan;
    plan.planner = planner.name;
    plan.parameters = parameters;
    plan.issues = problem.notes;
    PlanningRun planningRun(problem, std::move(parameters), progress, plan, planner.bytesPerBottomCell);
    planningRun.allowTakeOffs(!planner.fliesOnBatteries());
    if (!problem.events.empty() && !planner.simulatesEvents)
        planningRun.addIssue(IssueSeverity::Warning, "events-ignored", eventsIgnoredMessage(planner));
    for (const std::string& note :
         parametersWithoutEffect(planner.parameters, given, planningRun.parameters()))
        planningRun.addIssue(IssueSeverity::Warning, "parameter-without-effect", note);
    const bool anyCharger =
        std::any_of(problem.chargers.begin(), problem.chargers.end(),
                    [](const std::optional<MapPoint>& charger) { return charger.has_value(); });
    if (anyCharger && !planner.fliesOnBatteries())
        planningRun.addIssue(IssueSeverity::Warning, "chargers-ignored", chargersIgnoredMessage(planner));
    const bool fieldPaced = planner.balancesFieldTime && someFieldPace(round.paces);
    const std::vector<double> shownPaces = round.measuredPaces.empty() ? round.paces : round.measuredPaces;
    planningRun.setFieldPaces(std::move(round.paces));
    planningRun.keepCellsIn(round.cells);
    planningRun.weighTrips(round.tripsWeighed);
    const std::size_t balanceNoteAt = plan.issues.size();
    run(planningRun);
    // Said before what the planner found: how the plan was meant to be uneven on its paths.
    const bool fieldWeighed = fieldPaced || !plan.countedFieldPaces.empty();
    if (fieldWeighed)
        plan.issues.insert(plan.issues.begin() + static_cast<std::ptrdiff_t>(balanceNoteAt),
                           {IssueSeverity::Information, "field-time-balance",
                            fieldPaced ? fieldPacesMessage(shownPaces, true)
                                       : fieldPacesMessage(plan.countedFieldPaces, false)});
    for (CoveragePath& path : plan.paths)
        if (const auto robot = static_cast<std::size_t>(path.robot);
            robot < planningRun.takeOffPoints().size())
            path.takeOff = planningRun.takeOffPoints()[robot];
    applyOwnSpeeds(planner, problem, planningRun);
    planningRun.stage("metrics", [&] {
        parallelFor(plan.paths.size(),
                    [&](std::size_t path, int) { measurePath(plan.paths[path], plan.cells); });
        // Times in the field are the waypoint files' flights at the robots' own speeds: beside paths timed at
        // the class table's (own speeds ignored) they would compare flights with walks, and beside a plan
        // played through events, full speed with the mission as played (a simulating planner's plan played
        // through none is its paths, flown as the others'). A battery plan's paths hold their sorties and
        // charges: they are not split into flights again.
        const TimelineLayer* timeline = timelineLayerOf(plan);
        const bool playedThroughEvents = timeline != nullptr && !timeline->summary().events.empty();
        const bool inTheField = problem.fieldSeconds && sortieLayerOf(plan) == nullptr &&
                                !playedThroughEvents &&
                                (!someOwnSpeed(problem.robotSpeeds) || !plan.robotSpeeds.empty());
        PlanMetricsCalculator{inTheField ? problem.robotFlights : std::vector<FlightLimits>{}}.compute(plan);
        if (inTheField)
            measureFieldTimes(plan, problem.fieldSeconds(plan));
        return 0;
    });
    if (plan.metrics.unreachableAreaSquareMetres > 0.0)
        for (const std::string& message :
             uncoveredLandMessages(uncoveredLand(plan), planner, leftOutBeyondReach(problem.grid)))
            planningRun.addIssue(IssueSeverity::Warning, "unreachable-area", message);
    if (const WaypointsBeyondArea beyond = waypointsBeyondArea(problem.grid, plan.paths);
        beyond.waypoints > 0)
        planningRun.addIssue(IssueSeverity::Warning, "paths-beyond-area", beyondAreaMessage(beyond));
    if (const WaypointsBeyondRaster beyond = waypointsBeyondRaster(problem.grid, plan.paths);
        beyond.waypoints > 0)
        planningRun.addIssue(IssueSeverity::Warning, "paths-beyond-raster", beyondRasterMessage(beyond));
    const bool reachEdge = !plan.metrics.confinedRobots.empty() && leftOutBeyondReach(problem.grid);
    for (const ConfinedRobot& confined : plan.metrics.confinedRobots) {
        // Most often a start put on the wrong side of a river or a fence. The land no robot reaches is no
        // one's share.
        const double reached =
            plan.metrics.passableAreaSquareMetres - plan.metrics.unreachableAreaSquareMetres;
        const double evenShare =
            reached / static_cast<double>(std::max<std::size_t>(problem.starts.size(), 1));
        const double share = evenShare > 0.0
                                 ? confined.pocketAreaSquareMetres /
                                       static_cast<double>(std::max(confined.robotsInPocket, 1)) / evenShare
                                 : 1.0;
        const bool idle = share < 0.5;
        const bool byReach =
            reachEdge &&
            coversNextToLandBeyondReach(problem.grid, plan.cells, plan.regions.robotOfCell, confined.robot);
        planningRun.addIssue(idle ? IssueSeverity::Warning : IssueSeverity::Information, "confined-robot",
                             confinedRobotMessage(confined, share, idle, byReach));
    }
    // Robots slowed or stopped by events are meant to do less: their plan is uneven by design.
    const bool playsEvents = planner.simulatesEvents && !problem.events.empty();
    // Nor is a plan that divides the work at one speed between robots of their own (own-speeds-unbalanced),
    // or one that evens out time in the field, where paths of different lengths end together.
    const bool unevenSpeeds = !plan.robotSpeeds.empty() && !planner.balancesOwnSpeeds;
    const std::string uneven = unevenPlanMessage(plan, planner);
    if (!uneven.empty() && !playsEvents && !unevenSpeeds && !fieldWeighed)
        planningRun.addIssue(IssueSeverity::Warning, "uneven-plan", uneven);
    else if (const std::string field = unevenFieldMessage(plan, planner);
             !field.empty() && !playsEvents && !unevenSpeeds)
        planningRun.addIssue(IssueSeverity::Warning, "uneven-in-the-field", field);
    progress.report("done", 1.0);
    return plan;
}

} // namespace mcpp
