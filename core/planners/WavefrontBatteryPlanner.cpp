#include "core/planners/WavefrontBatteryPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/allocation/BatteryRange.hpp"
#include "core/coverage/ChargerTransit.hpp"
#include "core/coverage/OwnSpeeds.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/WavefrontCoverage.hpp"
#include "core/model/BatteryEndurance.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/StartPointCheck.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mcpp {
namespace {

std::string outOfRangeMessage(const RobotSorties& robot) {
    return formatArea(robot.outOfRangeAreaSquareMetres) + " at the edge of robot " +
           std::to_string(robot.robot + 1) + "'s region lies beyond half its battery (" +
           formatDuration(robot.enduranceSeconds) + ") from its charger and is not covered";
}

std::string beyondEveryChargerMessage(const CellGraph& cells, const std::vector<int>& ids,
                                      const BatteryRange& range) {
    double area = 0.0;
    for (const int id : ids)
        area += cells.cell(id).passableAreaSquareMetres;
    const auto [shortest, longest] =
        std::minmax_element(range.robotEndurances.begin(), range.robotEndurances.end());
    const std::string batteries = shortest == range.robotEndurances.end() || *shortest == *longest
                                      ? "half the battery (" + formatDuration(range.enduranceSeconds) + ")"
                                      : "half of each robot's battery (" + formatDuration(*shortest) +
                                            " to " + formatDuration(*longest) + ")";
    return formatArea(area) + " lies beyond " + batteries + " from every charger and is not covered";
}

// Each robot's endurance: its own where the problem gives one, else the planner's.
std::vector<double> robotBatteries(const PlanningProblem& problem, double plannerBattery) {
    std::vector<double> batteries(problem.starts.size(), plannerBattery);
    for (std::size_t robot = 0; robot < batteries.size() && robot < problem.batterySeconds.size(); ++robot)
        if (problem.batterySeconds[robot] > 0.0)
            batteries[robot] = problem.batterySeconds[robot];
    return batteries;
}

// Each robot's left-out cells are those it was the last to leave out (others may have taken the rest).
void keepOwnLeftOutCells(std::vector<WavefrontCoverage::Result>& results, const std::vector<int>& leftOutBy,
                         const CellGraph& cells) {
    for (WavefrontCoverage::Result& result : results) {
        result.sorties.outOfRangeCells.clear();
        result.sorties.outOfRangeAreaSquareMetres = 0.0;
    }
    for (std::size_t cell = 0; cell < leftOutBy.size(); ++cell) {
        if (leftOutBy[cell] < 0)
            continue;
        RobotSorties& robot = results[static_cast<std::size_t>(leftOutBy[cell])].sorties;
        robot.outOfRangeCells.push_back(static_cast<int>(cell));
        robot.outOfRangeAreaSquareMetres += cells.cell(static_cast<int>(cell)).passableAreaSquareMetres;
    }
}

// The cells in some charger's range, over which regions are drawn; the others are left out and warned of.
CellGraph cellsWithinRange(PlanningRun& run, const BatteryRange& range, const std::vector<int>& startCells) {
    const CellGraph& cells = run.plan().cells;
    BatteryRange::AllocationGraph allocation = range.allocationGraph(cells, startCells);
    if (!allocation.outOfRange.empty())
        run.addIssue(IssueSeverity::Warning, "beyond-every-charger",
                     beyondEveryChargerMessage(cells, allocation.outOfRange, range));
    return std::move(allocation.graph);
}

// Where each robot works from: its charger (its start unless the problem gives one) and, for a robot that
// starts elsewhere, its flight from the start to the charger.
struct Chargers {
    std::vector<MapPoint> points;
    std::vector<int> cells;                      // the regions grow from these
    std::vector<std::vector<Waypoint>> transits; // by robot; empty when it starts at its charger
};

int chargerCell(PlanningRun& run, int robot, MapPoint point) {
    if (const auto problem = startPointProblem(run.problem().grid, run.problem().classes, point))
        throw PlanningError::aboutCharger(
            problem->kind, robot, startRefusal(run.problem().grid, run.problem().classes, point, *problem));
    const int cell = run.plan().cells.cellAt(point);
    if (cell < 0)
        throw PlanningError::aboutCharger(
            PlanningError::Kind::StartOnObstacle, robot,
            describePoint(point) + " lies in no cell of the planning grid: obstacles fill most of its cell");
    return cell;
}

// Whether the problem places the robot's charger away from its start (a millimetre off, after a round trip
// through another CRS, is still at the start).
bool chargesElsewhere(const PlanningRun& run, std::size_t robot) {
    const std::vector<std::optional<MapPoint>>& given = run.problem().chargers;
    if (robot >= given.size() || !given[robot])
        return false;
    const MapPoint start = run.starts()[robot];
    return std::hypot(given[robot]->x - start.x, given[robot]->y - start.y) > 1e-3;
}

Chargers locateChargers(PlanningRun& run, const std::vector<int>& startCells,
                        const std::vector<double>& batteries) {
    Chargers chargers{run.starts(), startCells, std::vector<std::vector<Waypoint>>(startCells.size())};
    // Robots charging at their start first: a charger placed elsewhere must keep clear of them.
    std::vector<int> robotOfCell(run.plan().cells.size(), -1);
    for (std::size_t robot = 0; robot < startCells.size(); ++robot)
        if (!chargesElsewhere(run, robot))
            robotOfCell[static_cast<std::size_t>(startCells[robot])] = static_cast<int>(robot);
    std::optional<ChargerTransit> transit;
    for (std::size_t robot = 0; robot < startCells.size(); ++robot) {
        if (!chargesElsewhere(run, robot))
            continue;
        const auto index = static_cast<int>(robot);
        chargers.points[robot] = *run.problem().chargers[robot];
        chargers.cells[robot] = chargerCell(run, index, chargers.points[robot]);
        int& owner = robotOfCell[static_cast<std::size_t>(chargers.cells[robot])];
        if (owner >= 0)
            throw PlanningError::aboutCharger(
                PlanningError::Kind::StartsShareCell, index,
                describePoint(chargers.points[robot]) + " is in the same cell as robot " +
                    std::to_string(owner + 1) +
                    (chargesElsewhere(run, static_cast<std::size_t>(owner)) ? "'s charger"
                                                                            : "'s start and charger"));
        owner = index;
        if (!transit)
            transit.emplace(run.plan().cells);
        chargers.transits[robot] = transit->way(
            index, run.starts()[robot], startCells[robot], chargers.points[robot], chargers.cells[robot],
            batteries[robot], ownSpeedOf(run.problem().robotSpeeds, robot));
        run.progress().throwIfCancelled();
    }
    return chargers;
}

// The robots' sorties over one division of the cells.
struct RobotsOnBatteries {
    RegionAllocation regions;                       // less the cells left out, with those handed over
    std::vector<WavefrontCoverage::Result> results; // by robot
    std::vector<int> leftOutBy;                     // by cell: the robot that last left it out, or -1
};

// Plans the robots' regions (in parallel) and takes the cells they leave out of their regions.
void coverRegions(PlanningRun& run, const std::vector<int>& robots, const Chargers& chargers,
                  const std::vector<double>& batteries, RobotsOnBatteries& state) {
    const CellGraph& graph = run.plan().cells;
    const std::vector<std::vector<int>> cells = cellsByRobot(state.regions);
    const double plannerRecharge = run.parameters().real("recharge_s");
    const std::vector<double>& ownRecharges = run.problem().rechargeSeconds;
    parallelFor(robots.size(), [&](std::size_t i, int) {
        const auto robot = static_cast<std::size_t>(robots[i]);
        const bool own =
            robot < run.problem().batterySeconds.size() && run.problem().batterySeconds[robot] > 0.0;
        // A robot's own turnaround, as its waypoint files' time in the field counts it between flights.
        const double recharge =
            robot < ownRecharges.size() && ownRecharges[robot] > 0.0 ? ownRecharges[robot] : plannerRecharge;
        const WavefrontCoverage coverage(graph, {batteries[robot], recharge, own},
                                         ownSpeedOf(run.problem().robotSpeeds, robot));
        WavefrontCoverage::Result& result = state.results[robot];
        result = coverage.cover(robots[i], cells[robot], chargers.cells[robot], chargers.points[robot],
                                chargers.transits[robot], run.progress());
    });
    for (const int robot : robots)
        for (const int cell : state.results[static_cast<std::size_t>(robot)].sorties.outOfRangeCells) {
            state.regions.robotOfCell[static_cast<std::size_t>(cell)] = -1;
            state.leftOutBy[static_cast<std::size_t>(cell)] = robot;
        }
}

// Every robot's sorties over `division`; what a robot could not reach may be in reach of another's charger,
// which is then handed it and plans again.
RobotsOnBatteries coverDivision(PlanningRun& run, const RegionAllocation& division, const BatteryRange& range,
                                const Chargers& chargers, const std::vector<double>& batteries) {
    const CellGraph& graph = run.plan().cells;
    RobotsOnBatteries robots{division, std::vector<WavefrontCoverage::Result>(chargers.cells.size()),
                             std::vector<int>(graph.size(), -1)};
    std::vector<int> everyRobot(chargers.cells.size());
    std::iota(everyRobot.begin(), everyRobot.end(), 0);
    coverRegions(run, everyRobot, chargers, batteries, robots);
    const std::vector<int> gained =
        range.handOver(graph, robots.regions.robotOfCell, chargers.cells, robots.leftOutBy);
    for (std::size_t cell = 0; cell < robots.leftOutBy.size(); ++cell)
        if (robots.regions.robotOfCell[cell] >= 0)
            robots.leftOutBy[cell] = -1;
    coverRegions(run, gained, chargers, batteries, robots);
    return robots;
}

// Each robot's time, charges included.
std::vector<double> robotTimes(RobotsOnBatteries& robots, const CellGraph& graph) {
    std::vector<double> times;
    for (WavefrontCoverage::Result& result : robots.results) {
        timePath(result.path, graph);
        times.push_back(result.path.timeSeconds);
    }
    return times;
}

// Whether the robots that work end within 1 % of each other (a robot given nothing left out).
bool endTogether(const std::vector<double>& times) {
    double shortest = std::numeric_limits<double>::infinity();
    double longest = 0.0;
    for (const double time : times)
        if (time > 0.0) {
            shortest = std::min(shortest, time);
            longest = std::max(longest, time);
        }
    return longest <= 1.01 * shortest;
}

double coveredArea(const RobotsOnBatteries& robots, const CellGraph& graph) {
    double area = 0.0;
    for (std::size_t cell = 0; cell < robots.regions.robotOfCell.size(); ++cell)
        if (robots.regions.robotOfCell[cell] >= 0)
            area += graph.cell(static_cast<int>(cell)).passableAreaSquareMetres;
    return area;
}

// Each robot's pace for the next division: halfway (geometrically) from its pace in the last one to its
// seconds, charges included, for a second of the cost of the cells it was given and kept. Land it handed over
// (beyond its reach) or was handed (beyond another's) is then its own neighbours' to even out: a robot that
// gained cells is given fewer of its own, one that lost some is paced as if it had been given what it kept.
std::vector<double> pacesAsFlown(const CellGraph& graph, const RegionAllocation& given,
                                 const RobotsOnBatteries& robots, const std::vector<double>& times,
                                 std::vector<double> paces) {
    std::vector<double> kept(times.size(), 0.0);
    for (std::size_t cell = 0; cell < given.robotOfCell.size(); ++cell) {
        const int robot = given.robotOfCell[cell];
        if (robot >= 0 && robots.regions.robotOfCell[cell] == robot)
            kept[static_cast<std::size_t>(robot)] += graph.cell(static_cast<int>(cell)).coverSeconds();
    }
    for (std::size_t robot = 0; robot < times.size(); ++robot)
        if (kept[robot] > 0.0)
            paces[robot] = std::sqrt(paces[robot] * times[robot] / kept[robot]);
    return paces;
}

// What it takes to divide the cells again.
struct Division {
    const CellGraph& cells; // those within some charger's range
    const Chargers& chargers;
    const BatteryRange& range; // its robotEndurances: each robot's battery
    int rebalanceIterations = 0;
};

// The land no robot reached in the first plan is cut off from a later division, where the regions may lie
// otherwise: a robot whose way through its own region reaches some of it within its range is handed it, as
// after the first division. What is left stays the first plan's robot's to name (nameBorderingRobots).
// firstLeftOutBy: the first plan's leftOutBy.
void handOverCutOffCells(PlanningRun& run, const Division& division, const std::vector<int>& firstLeftOutBy,
                         RobotsOnBatteries& robots) {
    const CellGraph& graph = run.plan().cells;
    const auto byTheDivision = static_cast<int>(robots.results.size()); // open to every robot's way
    for (std::size_t cell = 0; cell < graph.size(); ++cell)
        if (firstLeftOutBy[cell] >= 0 && robots.regions.robotOfCell[cell] < 0)
            robots.leftOutBy[cell] = byTheDivision;
    const std::vector<int> gained =
        division.range.handOver(graph, robots.regions.robotOfCell, division.chargers.cells, robots.leftOutBy);
    for (std::size_t cell = 0; cell < graph.size(); ++cell)
        if (robots.regions.robotOfCell[cell] >= 0)
            robots.leftOutBy[cell] = -1;
    coverRegions(run, gained, division.chargers, division.range.robotEndurances, robots);
    for (std::size_t cell = 0; cell < graph.size(); ++cell)
        if (robots.leftOutBy[cell] == byTheDivision)
            robots.leftOutBy[cell] = firstLeftOutBy[cell];
}

// The division evens out cell costs, but a robot's time also goes on flights out to its work and back and
// on charges, more for a region far from its charger, and a robot hands over what lies beyond its reach to
// its neighbours. Up to balanceRounds times, while the last robot is done sooner than in the first plan,
// the cells are divided again on each robot's pace as flown (pacesAsFlown), without the land no robot reached
// in the first plan, and the plan whose last robot is done first is kept among those that cover nearly as
// much as the first: a region shaped anew may leave a few cells at the edge of its robot's reach that the
// first plan covered (on a CORINE map of 218 km2 at a battery of an hour, 31 ha for a fifth less time).
RobotsOnBatteries balancedOnBatteries(PlanningRun& run, const Division& division, RegionAllocation given,
                                      RobotsOnBatteries robots, std::vector<double> paces) {
    constexpr int balanceRounds = 3;
    constexpr double coverageTolerance = 0.002; // of the first plan's covered area
    constexpr double worthLessCover = 0.01;     // the least share of time a plan covering less must save
    const CellGraph& graph = run.plan().cells;
    std::vector<double> times = robotTimes(robots, graph);
    const double firstLongest = *std::max_element(times.begin(), times.end());
    if (endTogether(times))
        return robots;
    double bestLongest = firstLongest;
    const double firstCovered = coveredArea(robots, graph);
    const double leastCovered = (1.0 - coverageTolerance) * firstCovered;
    const std::vector<int> leftOutFirst = robots.leftOutBy;
    std::vector<char> leftOut(graph.size(), 0);
    for (std::size_t cell = 0; cell < graph.size(); ++cell)
        leftOut[cell] = leftOutFirst[cell] >= 0 ? 1 : 0;
    const CellGraph reachedFirst = cutOffCells(division.cells, leftOut);
    RobotsOnBatteries best = std::move(robots);
    RobotsOnBatteries candidate;
    const RobotsOnBatteries* last = &best; // the plan the next paces are taken from
    for (int round = 0; round < balanceRounds; ++round) {
        paces = pacesAsFlown(graph, given, *last, times, std::move(paces));
        AzimuthTrendAllocator allocator(division.rebalanceIterations);
        allocator.setPaces(paces);
        given = allocator.allocate(reachedFirst, division.chargers.cells, run.progress());
        candidate =
            coverDivision(run, given, division.range, division.chargers, division.range.robotEndurances);
        handOverCutOffCells(run, division, leftOutFirst, candidate);
        times = robotTimes(candidate, graph);
        const double longest = *std::max_element(times.begin(), times.end());
        if (longest >= firstLongest)
            break; // the paces drift away from even rather than towards it
        last = &candidate;
        // A plan that covers less must be quicker by a share worth it, not by a second.
        const double covered = coveredArea(candidate, graph);
        if ((covered >= firstCovered && longest < bestLongest) ||
            (covered >= leastCovered && longest < (1.0 - worthLessCover) * bestLongest)) {
            best = std::move(candidate);
            bestLongest = longest;
            last = &best;
        }
        if (endTogether(times))
            break;
    }
    return best;
}

// The pieces of land left out (cells with leftOutBy >= 0, joined through each other) and, by piece, the
// robots whose regions border it, each once.
struct LeftOutPieces {
    std::vector<int> pieceOfCell; // -1 for a cell not left out
    std::vector<std::vector<int>> borderingRobots;
    std::vector<int> borderCells; // region cells next to land left out
};

LeftOutPieces leftOutPieces(const CellGraph& graph, const std::vector<int>& robotOfCell,
                            const std::vector<int>& leftOutBy) {
    LeftOutPieces pieces{std::vector<int>(graph.size(), -1), {}, {}};
    std::vector<char> border(graph.size(), 0);
    for (std::size_t first = 0; first < graph.size(); ++first) {
        if (leftOutBy[first] < 0 || pieces.pieceOfCell[first] >= 0)
            continue;
        const auto label = static_cast<int>(pieces.borderingRobots.size());
        std::vector<int>& robots = pieces.borderingRobots.emplace_back();
        std::vector<int> stack{static_cast<int>(first)};
        pieces.pieceOfCell[first] = label;
        while (!stack.empty()) {
            const int cell = stack.back();
            stack.pop_back();
            for (const int next : graph.neighbours(cell)) {
                const auto index = static_cast<std::size_t>(next);
                if (const int robot = robotOfCell[index]; robot >= 0) {
                    if (std::find(robots.begin(), robots.end(), robot) == robots.end())
                        robots.push_back(robot);
                    if (border[index] == 0)
                        pieces.borderCells.push_back(next);
                    border[index] = 1;
                } else if (leftOutBy[index] >= 0 && pieces.pieceOfCell[index] < 0) {
                    pieces.pieceOfCell[index] = label;
                    stack.push_back(next);
                }
            }
        }
    }
    return pieces;
}

// By cell of land left out, the robot whose region lies fewest steps away through that land (-1 for land
// bordering no region and for other cells).
std::vector<int> nearestRegionThroughLeftOut(const CellGraph& graph, const std::vector<int>& robotOfCell,
                                             const LeftOutPieces& pieces) {
    std::vector<int> nearest(graph.size(), -1);
    std::vector<int> frontier = pieces.borderCells;
    const auto robotAt = [&](int cell) {
        const auto index = static_cast<std::size_t>(cell);
        return robotOfCell[index] >= 0 ? robotOfCell[index] : nearest[index];
    };
    while (!frontier.empty()) {
        std::vector<int> next;
        for (const int cell : frontier)
            for (const int neighbour : graph.neighbours(cell)) {
                const auto index = static_cast<std::size_t>(neighbour);
                if (pieces.pieceOfCell[index] < 0 || nearest[index] >= 0)
                    continue;
                nearest[index] = robotAt(cell);
                next.push_back(neighbour);
            }
        frontier = std::move(next);
    }
    return nearest;
}

// Land left out is warned of as lying at the edge of a robot's region: a robot whose region does not border
// it (another robot was handed the land between, or a later division drew the regions otherwise) gives it
// up to the robot whose region lies nearest through the land left out, which was not handed it either. Land
// that borders no region (walled in by obstacles and land beyond every charger) keeps its robot.
void nameBorderingRobots(const CellGraph& graph, const std::vector<int>& robotOfCell,
                         std::vector<int>& leftOutBy) {
    const LeftOutPieces pieces = leftOutPieces(graph, robotOfCell, leftOutBy);
    const std::vector<int> nearest = nearestRegionThroughLeftOut(graph, robotOfCell, pieces);
    for (std::size_t cell = 0; cell < graph.size(); ++cell) {
        if (pieces.pieceOfCell[cell] < 0 || nearest[cell] < 0)
            continue;
        const std::vector<int>& robots =
            pieces.borderingRobots[static_cast<std::size_t>(pieces.pieceOfCell[cell])];
        if (std::find(robots.begin(), robots.end(), leftOutBy[cell]) == robots.end())
            leftOutBy[cell] = nearest[cell];
    }
}

void addPathsAndSorties(PlanningRun& run, RobotsOnBatteries& state) {
    Plan& plan = run.plan();
    plan.regions = std::move(state.regions);
    nameBorderingRobots(plan.cells, plan.regions.robotOfCell, state.leftOutBy);
    keepOwnLeftOutCells(state.results, state.leftOutBy, plan.cells);
    std::vector<RobotSorties> sorties;
    for (WavefrontCoverage::Result& result : state.results) {
        if (result.sorties.outOfRangeAreaSquareMetres > 0.0)
            run.addIssue(IssueSeverity::Warning, "beyond-battery", outOfRangeMessage(result.sorties));
        plan.paths.push_back(std::move(result.path));
        sorties.push_back(std::move(result.sorties));
    }
    plan.layers.push_back(std::make_shared<SortieLayer>(std::move(sorties)));
}

} // namespace

PlannerDescription WavefrontBatteryPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "Wavefront with battery";
    description.summary = "wavefront coverage from far to near, in sorties from each robot's charger";
    // Cells beyond a battery's reach are left to no robot.
    description.promises.everyReachableCellCovered = false;
    // Each robot's sorties are timed at its own speed, its reach too, and the division gives it work in
    // proportion to its pace.
    description.balancesOwnSpeeds = true;
    // A robot whose charger is away from its start crosses others' regions on its first flight there; the
    // shared invariant suite plans without chargers, where every path keeps to its own region.
    description.parameters = {
        DecompositionOptions::blockedThresholdParameter(),
        AzimuthTrendAllocator::rebalanceIterationsParameter(),
        realParameter("battery_s", "Battery endurance", 1200.0, BatteryEndurance::minimumSeconds,
                      BatteryEndurance::maximumSeconds,
                      "Seconds of travel and turning on one charge; each sortie starts and ends at the "
                      "robot's charger (its start unless given) within it",
                      "s"),
        realParameter("recharge_s", "Recharge time", 600.0, 0.0, 1e7,
                      "Seconds at the charger between two sorties, for a robot whose vehicle has no "
                      "turnaround of its own (--turnaround, a mission's turnaround_s)",
                      "s"),
    };
    return description;
}

void WavefrontBatteryPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::WholeCell);
    const std::vector<int> startCells = run.locateStarts();
    const std::vector<double> batteries = robotBatteries(run.problem(), parameters.real("battery_s"));
    const BatteryRange range{*std::max_element(batteries.begin(), batteries.end()), run.problem().robotSpeeds,
                             batteries};
    const Chargers chargers =
        run.stage("chargers", [&] { return locateChargers(run, startCells, batteries); });
    // Robots of their own speeds get work in proportion to their paces over the cells.
    const int rebalanceIterations = parameters.integer("rebalance_iterations");
    AzimuthTrendAllocator allocator(rebalanceIterations);
    std::vector<double> paces(startCells.size(), 1.0);
    if (someOwnSpeed(run.problem().robotSpeeds)) {
        paces = robotPaces(plan.cells, run.problem().robotSpeeds, startCells.size());
        allocator.setPaces(paces);
    }
    CellGraph inRange; // the cells in some charger's range, each cut off from those beyond it
    RegionAllocation division = run.stage("allocation", [&] {
        inRange = cellsWithinRange(run, range, chargers.cells);
        return allocator.allocate(inRange, chargers.cells, run.progress());
    });
    RobotsOnBatteries robots =
        run.stage("paths", [&] { return coverDivision(run, division, range, chargers, batteries); });
    robots = run.stage("battery balance", [&] {
        return balancedOnBatteries(run, {inRange, chargers, range, rebalanceIterations}, std::move(division),
                                   std::move(robots), std::move(paces));
    });
    addPathsAndSorties(run, robots);
}

} // namespace mcpp
