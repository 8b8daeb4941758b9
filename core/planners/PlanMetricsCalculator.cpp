#include "core/planners/PlanMetricsCalculator.hpp"

#include "core/allocation/StartComponents.hpp"
#include "core/coverage/OwnSpeeds.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/planners/WorkByDistance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {

namespace {

// Relative rounding of time sums, within which a path's time meets its bound.
constexpr double ratioRounding = 1e-6;

struct PartFigures {
    double secondsNoPlanBeats = 0.0; // its cells' travel time and its robots' turn and connector time
    double areaSquareMetres = 0.0;
};

PartFigures figuresOf(const Plan& plan, const StartComponent& part) {
    PartFigures figures;
    for (const int id : part.cells) {
        const auto index = static_cast<std::size_t>(id);
        if (index >= plan.regions.robotOfCell.size() || plan.regions.robotOfCell[index] < 0)
            continue;
        const Cell& cell = plan.cells.cell(id);
        figures.secondsNoPlanBeats += cell.travelSeconds();
        figures.areaSquareMetres += cell.passableAreaSquareMetres;
    }
    for (const int robot : part.robots)
        if (static_cast<std::size_t>(robot) < plan.paths.size()) {
            const CoveragePath& path = plan.paths[static_cast<std::size_t>(robot)];
            figures.secondsNoPlanBeats += path.turnSeconds + path.connectorSeconds;
        }
    return figures;
}

// The longest path time among `robots`.
double longestTimeOf(const PlanMetrics& metrics, const std::vector<int>& robots) {
    double longest = 0.0;
    for (const int robot : robots)
        if (static_cast<std::size_t>(robot) < metrics.robots.size())
            longest = std::max(longest, metrics.robots[static_cast<std::size_t>(robot)].timeSeconds);
    return longest;
}

// The travel time of a covered cell, 0 for one no robot covers.
double coveredTravelSeconds(const Plan& plan, int id) {
    const auto index = static_cast<std::size_t>(id);
    if (index >= plan.regions.robotOfCell.size())
        return 0.0;
    const auto robot = static_cast<std::size_t>(plan.regions.robotOfCell[index]); // -1 wraps round
    return robot < plan.regions.startCell.size() ? plan.cells.cell(id).travelSeconds() : 0.0;
}

// Where a robot's flights take off and land: where it takes off outside its path, else its path's first point
// (the waypoint files' home), or its start cell where it has no path.
StartSquare homeOf(const Plan& plan, std::size_t robot) {
    if (robot < plan.paths.size() && plan.paths[robot].takeOff)
        return {*plan.paths[robot].takeOff, 0.0};
    if (robot < plan.paths.size() && !plan.paths[robot].waypoints.empty()) {
        const Waypoint& home = plan.paths[robot].waypoints.front();
        return {{home.x, home.y}, 0.0};
    }
    const Cell& start = plan.cells.cell(plan.regions.startCell[robot]);
    return {{start.centreX(), start.centreY()}, start.size / 2.0};
}

bool startsOnTheMap(const Plan& plan) {
    return std::all_of(plan.regions.startCell.begin(), plan.regions.startCell.end(), [&](int start) {
        return start >= 0 && static_cast<std::size_t>(start) < plan.cells.size();
    });
}

// Whether the robots, each within its flights, do a share's work within `fieldSeconds`: all of it, and of
// the work beyond each distance from the starts of the robots that fly out to it (`far`, where known) what
// their flights can reach (FlightLimits::mostPathSecondsBeyond).
bool doneWithin(const PlanMetricsCalculator::SharedWork& share, const std::vector<FlightLimits>& flights,
                const WorkByDistance* far, double fieldSeconds) {
    const auto doneBeyond = [&](double metres) {
        double done = 0.0;
        for (std::size_t robot = 0; robot < share.weights.size() && robot < flights.size(); ++robot)
            if (share.weights[robot] > 0.0)
                done += share.weights[robot] * flights[robot].mostPathSecondsBeyond(fieldSeconds, metres);
        return done;
    };
    if (doneBeyond(0.0) < share.seconds)
        return false;
    for (std::size_t step = 0; far != nullptr && step < far->secondsBeyond().size(); ++step)
        if (doneBeyond(static_cast<double>(step) * far->stepMetres()) < far->secondsBeyond()[step])
            return false;
    return true;
}

// The least such time, by bisection.
double leastFieldSeconds(const PlanMetricsCalculator::SharedWork& share,
                         const std::vector<FlightLimits>& flights, const WorkByDistance* far) {
    const auto first =
        std::find_if(share.weights.begin(), share.weights.end(), [](double weight) { return weight > 0.0; });
    const auto robot = static_cast<std::size_t>(first - share.weights.begin());
    if (first == share.weights.end() || robot >= flights.size() || !(share.seconds > 0.0))
        return 0.0;
    // Any robot of the share alone does its work within its own least time; the trips may need longer.
    double low = 0.0;
    double high = std::max(1.0, flights[robot].leastFieldSecondsFor(share.seconds / *first));
    for (int doubling = 0; doubling < 64 && !doneWithin(share, flights, far, high); ++doubling)
        high *= 2.0;
    for (int step = 0; step < 64 && high - low > 1e-9 * high; ++step) {
        const double middle = 0.5 * (low + high);
        (doneWithin(share, flights, far, middle) ? high : low) = middle;
    }
    return high;
}

} // namespace

// Robots cannot leave the connected part they start in, so each part must be covered by its own robots.
void PlanMetricsCalculator::boundByConnectedParts(Plan& plan, bool regionsLinked,
                                                  std::vector<SharedWork>& shares) {
    PlanMetrics& metrics = plan.metrics;
    metrics.confinedRobots.clear();
    metrics.sharedPartsRatio = 0.0;
    const std::vector<int>& starts = plan.regions.startCell;
    if (!startsOnTheMap(plan))
        return; // a planner without start cells keeps the whole-map bound
    // Linked regions (asked by compute, in a pass over the neighbours) settle it, where finding the parts
    // searches the whole graph: the metrics took 7.2 s with that search, 4.0 s without, on a map of 69 M
    // cells.
    if (regionsLinked)
        return; // one part: the whole-map bound holds
    const std::vector<StartComponent> parts = componentsWithStarts(plan.cells, starts);
    if (parts.size() < 2)
        return;
    double loneBound = 0.0; // the largest bound of a part with one robot, and of one shared by several
    double sharedBound = 0.0;
    double sharedRatio = 0.0;
    std::vector<PartFigures> figures;
    std::size_t largest = 0;
    // A detection plan need not pass every sub-cell, so a part's travel over its cells bounds nothing; nor
    // does a part's even share where robots drive at their own speeds.
    const bool evenShares = detectionLayerOf(plan) == nullptr && !someOwnSpeed(plan.robotSpeeds);
    for (const StartComponent& part : parts) {
        figures.push_back(figuresOf(plan, part));
        if (figures.back().areaSquareMetres > figures[largest].areaSquareMetres)
            largest = figures.size() - 1;
        if (!evenShares)
            continue;
        const double partBound = figures.back().secondsNoPlanBeats / static_cast<double>(part.robots.size());
        metrics.lowerBoundSeconds = std::max(metrics.lowerBoundSeconds, partBound);
        double& boundOfItsKind = part.robots.size() > 1 ? sharedBound : loneBound;
        boundOfItsKind = std::max(boundOfItsKind, partBound);
        if (part.robots.size() > 1 && partBound > 0.0)
            sharedRatio = std::max(sharedRatio, longestTimeOf(metrics, part.robots) / partBound);
        SharedWork work{std::vector<double>(starts.size(), 0.0), figures.back().secondsNoPlanBeats, {}};
        for (const int robot : part.robots)
            work.weights[static_cast<std::size_t>(robot)] = 1.0;
        // A region lies in its robot's part.
        work.workOfCell = [&plan, inPart = work.weights](int id) {
            const double seconds = coveredTravelSeconds(plan, id);
            if (!(seconds > 0.0))
                return 0.0;
            const auto robot =
                static_cast<std::size_t>(plan.regions.robotOfCell[static_cast<std::size_t>(id)]);
            return robot < inPart.size() && inPart[robot] > 0.0 ? seconds : 0.0;
        };
        shares.push_back(std::move(work));
    }
    // Only where robots alone set the bound does every plan share the ratio, and the others' say more.
    if (loneBound > sharedBound)
        metrics.sharedPartsRatio = sharedRatio;
    for (std::size_t part = 0; part < parts.size(); ++part) {
        if (part == largest)
            continue;
        for (const int robot : parts[part].robots)
            metrics.confinedRobots.push_back(
                {robot, figures[part].areaSquareMetres, static_cast<int>(parts[part].robots.size())});
    }
}

// Each robot r takes t_r(i) to travel cell i: the class table's travel time, or the cell's length at its own
// speed. For any weights w_r >= 0 the makespan T satisfies T * sum(w_r) >= sum over r of w_r times r's
// cells' t_r and its turns and connectors, which is at least sum over cells of min over r of w_r t_r(i),
// plus the turns and connectors weighted. Weighted by what each robot would take alone (w_r = 1 / sum of
// t_r), w_r t_r(i) is the cell's share of the map's travel time for a robot at the class speeds and its
// share of the map's length for one at its own, whatever that speed. Uniform speeds give the usual bound.
std::optional<PlanMetricsCalculator::SharedWork> PlanMetricsCalculator::boundWithOwnSpeeds(Plan& plan) {
    // Two passes over the covered cells rather than a list of them: 16 bytes a cell on a map of 69 M cells.
    const auto forEachCoveredCell = [&plan](const auto& use) {
        for (std::size_t id = 0; id < plan.cells.size() && id < plan.regions.robotOfCell.size(); ++id)
            if (plan.regions.robotOfCell[id] >= 0) {
                const Cell cell = plan.cells.cell(static_cast<int>(id));
                use(cell.travelSeconds(), cell.travelSeconds() * cell.speedMetresPerSecond);
            }
    };
    double travel = 0.0; // over the covered cells, at the class speeds
    double length = 0.0;
    forEachCoveredCell([&](double seconds, double metres) {
        travel += seconds;
        length += metres;
    });
    if (!(travel > 0.0) || !(length > 0.0))
        return std::nullopt;
    bool classSpeeds = false; // some robot drives at the class table's speeds
    SharedWork work{std::vector<double>(plan.regions.startCell.size(), 0.0), 0.0, {}};
    double weights = 0.0;
    double weightedExtras = 0.0; // turns and connectors
    for (std::size_t robot = 0; robot < plan.regions.startCell.size(); ++robot) {
        const double speed = ownSpeedOf(plan.robotSpeeds, robot);
        const double weight = speed > 0.0 ? speed / length : 1.0 / travel;
        classSpeeds = classSpeeds || !(speed > 0.0);
        work.weights[robot] = weight;
        weights += weight;
        if (robot < plan.paths.size())
            weightedExtras += weight * (plan.paths[robot].turnSeconds + plan.paths[robot].connectorSeconds);
    }
    if (!(weights > 0.0))
        return std::nullopt; // no robot
    const auto shareOf = [classSpeeds, travel, length](double seconds, double metres) {
        return classSpeeds ? std::min(seconds / travel, metres / length) : metres / length;
    };
    double shares = 0.0;
    forEachCoveredCell([&](double seconds, double metres) { shares += shareOf(seconds, metres); });
    work.seconds = shares + weightedExtras;
    work.workOfCell = [&plan, shareOf](int id) {
        const double seconds = coveredTravelSeconds(plan, id);
        return seconds > 0.0 ? shareOf(seconds, seconds * plan.cells.cell(id).speedMetresPerSecond) : 0.0;
    };
    plan.metrics.lowerBoundSeconds = work.seconds / weights;
    return work;
}

namespace {

// The work of a share by how far it lies from the homes (by robot: where its flights take off and land) of
// its robots that fly out to their work; none where it has no such robot, or no robot reaches some of it.
std::optional<WorkByDistance> workBeyondTripStarts(const Plan& plan,
                                                   const PlanMetricsCalculator::SharedWork& share,
                                                   const std::vector<FlightLimits>& flights,
                                                   const std::vector<std::vector<StartSquare>>& homes) {
    if (!share.workOfCell)
        return std::nullopt;
    std::vector<StartSquare> starts;
    std::vector<WorkByDistance::TurningPath> turning; // the share's seconds count its robots' turns
    for (std::size_t robot = 0; robot < share.weights.size() && robot < flights.size(); ++robot) {
        if (share.weights[robot] > 0.0 && flights[robot].makesTrips())
            starts.insert(starts.end(), homes[robot].begin(), homes[robot].end());
        if (share.weights[robot] > 0.0 && robot < plan.paths.size())
            turning.push_back({&plan.paths[robot], share.weights[robot]});
    }
    if (starts.empty())
        return std::nullopt;
    WorkByDistance far(plan.cells, std::move(starts), share.workOfCell, turning);
    const auto reached = [&](double metres) {
        for (std::size_t robot = 0; robot < share.weights.size() && robot < flights.size(); ++robot)
            if (share.weights[robot] > 0.0 && flights[robot].reachMetres() > metres)
                return true;
        return false;
    };
    for (std::size_t step = 0; step < far.secondsBeyond().size(); ++step)
        if (far.secondsBeyond()[step] > 0.0 && !reached(static_cast<double>(step) * far.stepMetres()))
            return std::nullopt;
    return far;
}

} // namespace

// Each robot's flights as the bound counts them. A flight may skip the path's turn where it ends (the
// waypoint files turn from the trip out and onto the trip back instead): up to a U-turn at the dearest price,
// given to every flight as spare time so that no plan's flights come out under the bound.
std::vector<FlightLimits> PlanMetricsCalculator::boundedFlights(std::size_t robots,
                                                                double dearestTurnSeconds) const {
    std::vector<FlightLimits> flights;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        FlightLimits limits = limitsOf(robot);
        if (limits.splitsPaths())
            limits.climbAndDescentSeconds -= 2.0 * dearestTurnSeconds * limits.fastestPace;
        flights.push_back(limits);
    }
    return flights;
}

double PlanMetricsCalculator::fieldBound(const Plan& plan, const std::vector<SharedWork>& shares,
                                         double dearestTurnSeconds) const {
    const std::vector<FlightLimits> flights =
        boundedFlights(plan.regions.startCell.size(), dearestTurnSeconds);
    if (!flightsReachTheirWork(plan))
        return boundOfFlights(plan, shares, flights, {});
    std::vector<std::vector<StartSquare>> homes;
    for (std::size_t robot = 0; robot < flights.size(); ++robot)
        homes.push_back({homeOf(plan, robot)});
    return boundOfFlights(plan, shares, flights, homes);
}

// homes: by robot, where its flights take off and land; none: their trips are not counted.
double PlanMetricsCalculator::boundOfFlights(const Plan& plan, const std::vector<SharedWork>& shares,
                                             const std::vector<FlightLimits>& flights,
                                             const std::vector<std::vector<StartSquare>>& homes) {
    double bound = 0.0;
    for (const SharedWork& share : shares) {
        const std::optional<WorkByDistance> far =
            homes.empty() ? std::nullopt : workBeyondTripStarts(plan, share, flights, homes);
        bound = std::max(bound, leastFieldSeconds(share, flights, far ? &*far : nullptr));
    }
    return bound;
}

// The plan's paths are its sorties, the trips out to the work and the charges between them included: each
// robot flies sorties of at most its endurance (and a U-turn at the dearest price, which a sortie's end may
// make beyond it) from its charger, or on the first from its start, at most as fast as it goes anywhere.
// A robot flying from one home to another spends, to work beyond some distance of both, twice that distance.
double PlanMetricsCalculator::sortieBound(const Plan& plan, const std::vector<SharedWork>& shares,
                                          double dearestTurnSeconds, double fastestCell) {
    const SortieLayer* layer = sortieLayerOf(plan);
    const std::size_t robots = plan.regions.startCell.size();
    if (layer == nullptr || !startsOnTheMap(plan))
        return 0.0;
    std::vector<FlightLimits> flights(robots);
    std::vector<std::vector<StartSquare>> homes(robots);
    for (const RobotSorties& sorties : layer->robots()) {
        const auto robot = static_cast<std::size_t>(sorties.robot);
        if (robot >= robots || !(sorties.enduranceSeconds > 0.0) || !std::isfinite(sorties.enduranceSeconds))
            continue;
        FlightLimits& limits = flights[robot];
        limits.flightSeconds = sorties.enduranceSeconds + 2.0 * dearestTurnSeconds;
        limits.turnaroundSeconds = sorties.rechargeSeconds;
        // Floats round speeds: a millionth faster keeps the trips from being priced above what is flown.
        limits.tripMetresPerSecond =
            (1.0 + ratioRounding) * std::max(ownSpeedOf(plan.robotSpeeds, robot), fastestCell);
        homes[robot].push_back({sorties.charger, 0.0});
        if (robot < plan.paths.size() && !plan.paths[robot].closed)
            homes[robot].push_back(homeOf(plan, robot));
    }
    return boundOfFlights(plan, shares, flights, homes);
}

// Where some robot flies out to its work: whether each such robot reaches every cell of its region within
// one flight. Where one does not, the plan has flights longer than a battery, which the trips' bound does
// not price: the trips are left out.
bool PlanMetricsCalculator::flightsReachTheirWork(const Plan& plan) const {
    const std::size_t robots = plan.regions.startCell.size();
    if (!startsOnTheMap(plan))
        return false;
    std::vector<StartSquare> homes;
    std::vector<double> reaches;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        homes.push_back(homeOf(plan, robot));
        reaches.push_back(limitsOf(robot).reachMetres());
    }
    if (std::all_of(reaches.begin(), reaches.end(), [](double reach) { return std::isinf(reach); }))
        return false; // no trips
    for (std::size_t id = 0; id < plan.cells.size() && id < plan.regions.robotOfCell.size(); ++id) {
        const auto robot = static_cast<std::size_t>(plan.regions.robotOfCell[id]);
        if (robot >= robots || std::isinf(reaches[robot]))
            continue; // uncovered (-1 wraps round), or a robot without trips
        const Cell cell = plan.cells.cell(static_cast<int>(id));
        if (homes[robot].gapTo(cell.centreX(), cell.centreY(), cell.size) > reaches[robot])
            return false;
    }
    return true;
}

// The busiest robot travels at least the bound; on one charge it flies at most the longest endurance, so
// it charges at least ceil(bound / endurance) - 1 times, each for at least the shortest recharge.
void PlanMetricsCalculator::boundByCharges(Plan& plan) {
    const SortieLayer* layer = sortieLayerOf(plan);
    if (layer == nullptr || layer->robots().empty())
        return;
    double endurance = 0.0;
    double recharge = std::numeric_limits<double>::infinity();
    for (const RobotSorties& robot : layer->robots()) {
        endurance = std::max(endurance, robot.enduranceSeconds);
        recharge = std::min(recharge, robot.rechargeSeconds);
    }
    const double travel = plan.metrics.lowerBoundSeconds;
    if (!(endurance > 0.0) || !std::isfinite(endurance) || travel <= endurance)
        return;
    plan.metrics.lowerBoundSeconds = travel + (std::ceil(travel / endurance) - 1.0) * recharge;
}

void PlanMetricsCalculator::compute(Plan& plan) const {
    PlanMetrics& metrics = plan.metrics;
    const CellGraph& graph = plan.cells;
    const std::size_t robots = plan.regions.startCell.size();
    metrics.robots.assign(robots, {});
    plan.regions.costSeconds.assign(robots, 0.0);
    double secondsNoPlanBeats = 0.0; // the turns the paths make, and below the travel no plan beats
    double cellTravelSeconds = 0.0;  // over every covered cell
    double connectorSeconds = 0.0;   // the paths' steps between cells of different sizes, beyond that travel
    double covered = 0.0;
    double unreachable = 0.0;
    std::size_t subCells = 0;
    double dearestTurnSeconds = 0.0; // the highest price of a quarter turn
    double fastestCell = 0.0;        // the highest speed over any cell, for the trips out on batteries
    // Whether the regions link every robot is asked beside the pass over the cells: on a map of 69 M cells
    // each takes most of a second.
    bool regionsLinked = false;
    parallelFor(2, [&](std::size_t task, int) {
        if (task == 1) {
            regionsLinked = startsOnTheMap(plan) && regionsLinkEveryRobot(graph, plan.regions);
            return;
        }
        for (std::size_t id = 0; id < graph.size(); ++id) {
            const Cell& cell = graph.cell(static_cast<int>(id));
            dearestTurnSeconds =
                std::max(dearestTurnSeconds, static_cast<double>(cell.turnSecondsPer90Degrees));
            fastestCell = std::max(fastestCell, static_cast<double>(cell.speedMetresPerSecond));
            const int robot = id < plan.regions.robotOfCell.size() ? plan.regions.robotOfCell[id] : -1;
            if (robot < 0 || static_cast<std::size_t>(robot) >= robots) {
                unreachable += cell.passableAreaSquareMetres;
                continue;
            }
            RobotMetrics& robotMetrics = metrics.robots[static_cast<std::size_t>(robot)];
            ++robotMetrics.cells;
            robotMetrics.areaSquareMetres += cell.freeAreaSquareMetres();
            robotMetrics.costSeconds += cell.coverSeconds();
            plan.regions.costSeconds[static_cast<std::size_t>(robot)] += cell.coverSeconds();
            cellTravelSeconds += cell.travelSeconds();
            covered += cell.passableAreaSquareMetres;
            subCells += static_cast<std::size_t>(cell.freeSubCellCount());
        }
    });
    std::size_t repeats = 0;
    metrics.makespanSeconds = 0.0;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        RobotMetrics& robotMetrics = metrics.robots[robot];
        robotMetrics.robot = static_cast<int>(robot);
        if (robot < plan.paths.size()) {
            const CoveragePath& path = plan.paths[robot];
            robotMetrics.lengthMetres = path.lengthMetres;
            robotMetrics.timeSeconds = path.timeSeconds;
            robotMetrics.turnSeconds = path.turnSeconds;
            robotMetrics.connectorSeconds = path.connectorSeconds;
            secondsNoPlanBeats += path.turnSeconds;
            connectorSeconds += path.connectorSeconds;
            robotMetrics.turns = path.turns;
            repeats += static_cast<std::size_t>(path.repeatedSubCellVisits);
        }
        metrics.makespanSeconds = std::max(metrics.makespanSeconds, robotMetrics.timeSeconds);
    }
    // A detection plan need not pass every sub-cell: its travel bound counts the passes its targets need,
    // at top speed, so the steps between cells' sub-cells that connector time adds to are not in it.
    const DetectionLayer* detection = detectionLayerOf(plan);
    metrics.boundOfDetectionPasses = detection != nullptr;
    secondsNoPlanBeats += detection != nullptr
                              ? detection->summary().travelSecondsNoPlanBeats(metrics.totalTurns(), robots)
                              : cellTravelSeconds + connectorSeconds;
    metrics.lowerBoundSeconds = robots == 0 ? 0.0 : secondsNoPlanBeats / static_cast<double>(robots);
    std::vector<SharedWork> shares{{std::vector<double>(robots, 1.0), secondsNoPlanBeats, {}}};
    if (detection == nullptr)
        shares.front().workOfCell = [&plan](int id) { return coveredTravelSeconds(plan, id); };
    // With robots of their own speeds the parts' bounds, each part's work shared evenly, would not hold:
    // the map's bound with those speeds does (weaker where a robot is walled in).
    if (someOwnSpeed(plan.robotSpeeds) && detection == nullptr)
        if (std::optional<SharedWork> work = boundWithOwnSpeeds(plan))
            shares.front() = std::move(*work);
    boundByConnectedParts(plan, regionsLinked, shares);
    // The planner gives flights only where its paths are flown in them (Planner::planOnce).
    const bool flights = std::any_of(robotFlights_.begin(), robotFlights_.end(),
                                     [](const FlightLimits& limits) { return limits.splitsPaths(); });
    metrics.fieldLowerBoundSeconds = flights ? fieldBound(plan, shares, dearestTurnSeconds) : 0.0;
    // Aircraft flying out to their work that cannot reach all of it: the bound prices no trip.
    metrics.fieldBoundWithoutTrips =
        flights &&
        std::any_of(robotFlights_.begin(), robotFlights_.end(),
                    [](const FlightLimits& limits) { return std::isfinite(limits.reachMetres()); }) &&
        !flightsReachTheirWork(plan);
    const double partsBound = metrics.lowerBoundSeconds;
    boundByCharges(plan);
    metrics.lowerBoundSeconds =
        std::max(metrics.lowerBoundSeconds, sortieBound(plan, shares, dearestTurnSeconds, fastestCell));
    if (metrics.lowerBoundSeconds > partsBound) // set by the charges or the trips, not by robots alone
        metrics.sharedPartsRatio = 0.0;
    metrics.ratio =
        metrics.lowerBoundSeconds > 0.0 ? metrics.makespanSeconds / metrics.lowerBoundSeconds : 0.0;
    // The bound and the paths add the same cells in other orders at speeds kept as floats: a ratio a
    // millionth below 1 is that rounding (0.99999983 for an even MSTC plan), not a plan beating its bound.
    if (metrics.ratio > 1.0 - ratioRounding && metrics.ratio < 1.0)
        metrics.ratio = 1.0;
    metrics.passableAreaSquareMetres = graph.passableAreaSquareMetres;
    metrics.coveredAreaSquareMetres = covered;
    metrics.coveredFraction =
        graph.passableAreaSquareMetres > 0.0 ? covered / graph.passableAreaSquareMetres : 0.0;
    metrics.unreachableAreaSquareMetres = unreachable;
    metrics.repeatedFraction =
        subCells == 0 ? 0.0 : static_cast<double>(repeats) / static_cast<double>(subCells);
}

} // namespace mcpp
