#include "core/planners/MlctPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/allocation/BorderStraightening.hpp"
#include "core/allocation/OwnFlightReach.hpp"
#include "core/allocation/TripWeighting.hpp"
#include "core/coverage/OwnSpeeds.hpp"
#include "core/coverage/PathTimeBalancing.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TurnCalibration.hpp"
#include "core/coverage/TurnSearch.hpp"
#include "core/decomposition/DecompositionOptions.hpp"
#include "core/planners/PlanningRun.hpp"
#include "core/planners/QuadTreeStage.hpp"

#include <algorithm>
#include <optional>

namespace mcpp {
namespace {

using RegionTree = SpanningTreeCoverage::RegionTree;

// Whether turns take a share of some robot's time that a better estimate of them could rebalance: on slow
// land covers they are a rounding error (0.05 % of the time on the WorldCover crop) and a second
// allocation would only cost time.
bool turnsWeigh(const std::vector<RegionTree>& trees) {
    constexpr double smallestShare = 0.005;
    return std::any_of(trees.begin(), trees.end(), [](const RegionTree& planned) {
        return planned.shape.turningSeconds() > smallestShare * planned.shape.seconds();
    });
}

// Rounds of evening out with the paces the paths drove: on a mixed fleet the first round does most.
constexpr int speedBalanceRounds = 3;

// The longest time in the field (the longest path where no robot has a field pace).
double longestTime(const std::vector<CoveragePath>& paths, const std::vector<double>& fieldPaces) {
    double longest = 0.0;
    for (const CoveragePath& path : paths)
        longest = std::max(longest, fieldSeconds(path, fieldPaces));
    return longest;
}

// Robots of their own speeds or field paces: paces guessed from travel alone, their turns left out, are put
// right by the paths as driven, and the division evened out again with them while that shortens the
// longest time in the field. Returns the rounds kept.
int balanceOwnSpeeds(PlanningRun& run, const TripWeighting& trips, OwnFlightReach& reach,
                     const std::vector<int>& startCells, const std::vector<double>& guessed,
                     AzimuthTrendAllocator& allocator, BorderStraightening& straightening,
                     const SpanningTreeCoverage& coverage) {
    Plan& plan = run.plan();
    int kept = 0;
    for (; kept < speedBalanceRounds && startCells.size() > 1; ++kept) {
        const ProgressReporter progress =
            run.progress().within("speed balance", static_cast<double>(kept) / speedBalanceRounds,
                                  static_cast<double>(kept + 1) / speedBalanceRounds);
        // Paces of a round that does not help stay set: nothing divides the map after this stage.
        const std::vector<double>& fieldPaces = run.fieldPaces();
        const std::vector<double> paces = withFieldPaces(
            drivenPaces(plan.cells, plan.regions, plan.paths, guessed), fieldPaces, startCells.size());
        allocator.setPaces(paces);
        straightening.setPaces(paces);
        reach.setPaces(paces);
        RegionAllocation regions =
            allocator.rebalance(trips.divided(plan.cells), startCells, plan.regions, progress);
        straightening.straighten(regions);
        reach.handOver(trips.divided(plan.cells), regions);
        std::vector<CoveragePath> paths = coverage.walkTrees(
            plan.cells, coverage.planTrees(plan.cells, regions, run.starts(), progress, false), run.starts(),
            progress);
        driveAtOwnSpeeds(paths, plan.cells, run.problem().robotSpeeds);
        // Compared in time in the field as the division counts it, trips included.
        const auto longest = [&](const std::vector<CoveragePath>& compared,
                                 const RegionAllocation& division) {
            return longestTime(
                compared, withFieldPaces(trips.paces(plan.cells, division), fieldPaces, startCells.size()));
        };
        if (!(longest(paths, regions) < longest(plan.paths, plan.regions)))
            break;
        plan.regions = std::move(regions);
        plan.paths = std::move(paths);
    }
    return kept;
}

// Where each robot's flights take off: its start, or where it takes off outside its path.
std::vector<MapPoint> launchPoints(const PlanningRun& run) {
    std::vector<MapPoint> points = run.starts();
    const auto& takeOffs = run.takeOffPoints();
    for (std::size_t robot = 0; robot < points.size() && robot < takeOffs.size(); ++robot)
        if (takeOffs[robot])
            points[robot] = *takeOffs[robot];
    return points;
}

} // namespace

PlannerDescription MlctPlanner::describe() const {
    PlannerDescription description;
    description.name = plannerName;
    description.label = "MCPP-MLCT";
    description.summary = "quadtree cells sized by field of view, azimuth-trend regions, improved STC";
    description.parameters = {DecompositionOptions::purityToleranceParameter(),
                              DecompositionOptions::blockedThresholdParameter(),
                              AzimuthTrendAllocator::rebalanceIterationsParameter(),
                              AzimuthTrendAllocator::treePieceShareParameter(),
                              BorderStraightening::slackParameter(),
                              SpanningTreeCoverage::closedTourParameter(),
                              TurnSearch::roundsParameter()};
    // Measured peaks, outputs included, on maps of 4 M cells or more (paths merge their straight runs, large
    // regions are walked once): 104-110 bytes a bottom cell on forest-4250 with a fast robot (the turn
    // balance plans a second division), 56-58 on the 69 M-cell tile (docs/benchmarks.md); with room to
    // spare. Below 4 M cells, where paths keep every waypoint, more a cell, still under a gigabyte.
    description.bytesPerBottomCell = 210;
    description.quadTreeCells = true;
    description.balancesOwnSpeeds = true;
    description.balancesFieldTime = true;
    return description;
}

void MlctPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    const ProgressReporter& progress = run.progress();
    Plan& plan = run.plan();
    plan.cells = quadTreeStage(run);
    const std::vector<int> startCells = run.locateStarts();
    // Aircraft flying out to far work: the division weighs cells by the field time their trips take.
    const TripWeighting trips(plan.cells, launchPoints(run),
                              run.tripsWeighed() ? run.problem().robotFlights : std::vector<FlightLimits>{});
    const CellGraph& divided = trips.divided(plan.cells);
    // Each aircraft keeps to cells its own flights reach: the division's others go to robots that reach them.
    OwnFlightReach reach(launchPoints(run), run.problem().robotFlights);
    AzimuthTrendAllocator allocator(parameters.integer("rebalance_iterations"),
                                    parameters.real("tree_piece_share") / 100.0);
    BorderStraightening straightening(divided, parameters.real("fewer_turns_slack") / 100.0);
    SpanningTreeCoverage coverage(parameters.boolean("closed_tour"),
                                  SpanningTreeCoverage::fewestCellsForMergedRuns);
    TurnSearch turnSearch = TurnSearch::forPlan(plan.cells, parameters);
    // Robots of their own speeds (an aircraft beside ground robots) are balanced in their own times.
    const std::vector<double>& speeds = run.problem().robotSpeeds;
    const bool ownSpeeds = someOwnSpeed(speeds);
    // Robots that spend longer in the field than on their paths (drones between flights) are balanced in
    // field time: the division and the balancing that follows weigh each path by its robot's field pace.
    const std::vector<double>& fieldPaces = run.fieldPaces();
    const bool paced = ownSpeeds || someFieldPace(fieldPaces);
    const std::vector<double> guessedPaces =
        ownSpeeds ? robotPaces(plan.cells, speeds, startCells.size()) : std::vector<double>{};
    if (paced) {
        const std::vector<double> paces = withFieldPaces(guessedPaces, fieldPaces, startCells.size());
        allocator.setPaces(paces);
        straightening.setPaces(paces);
        reach.setPaces(paces);
    }
    if (ownSpeeds) {
        coverage.setRobotSpeeds(speeds);
        turnSearch.setRobotSpeeds(speeds);
    }
    plan.regions = run.stage("allocation", [&] { return allocator.allocate(divided, startCells, progress); });
    run.stage("straight borders", [&] { return straightening.straighten(plan.regions); });
    const bool reachCaps = reach.limits() && run.stage("reach handover", [&] {
        return reach.handOver(divided, plan.regions);
    }) > 0;
    // Trees first, walked once the division is settled: two divisions are compared by their trees, which
    // take a quarter of the memory of their paths (3.7 GB instead of 5.4 GB on 17.6 M cells with a fast
    // robot). On large maps a region whose merged path is small is walked as its tree is measured, and its
    // path waits instead of the tree.
    std::vector<RegionTree> trees = run.stage(
        "paths", [&] { return coverage.planTrees(plan.cells, plan.regions, run.starts(), progress, true); });
    // Turns are not spread evenly: the division evened out again with each region's measured turn rate
    // balances real time better. The faster division is kept. Evened out from where it stands rather than
    // grown anew: on the benchmark maps the makespans within -0.3 % and +0.2 % of a new division's, in a
    // fraction of the time.
    // Skipped for robots of their own speeds (trees are timed at the class table's speeds), field paces or
    // cells weighed by trips (the rebalance would share out the cells unweighed).
    run.stage("turn balance", [&] {
        if (paced || trips.weighs() || !turnsWeigh(trees) ||
            !calibrateTurnRates(plan.cells, plan.regions, turningSecondsOf(trees)))
            return 0;
        RegionAllocation regions = allocator.rebalance(plan.cells, startCells, plan.regions,
                                                       progress.within("turn balance", 0.0, 0.5));
        straightening.straighten(regions);
        reach.handOver(plan.cells, regions);
        std::vector<RegionTree> second =
            coverage.replanTrees(plan.cells, regions, plan.regions, trees, run.starts(),
                                 progress.within("turn balance", 0.5, 1.0), true);
        if (walksQuicker(second, trees)) {
            plan.regions = std::move(regions);
            trees = std::move(second);
        }
        return 0;
    });
    plan.paths = run.stage("waypoints", [&] {
        std::vector<CoveragePath> paths =
            coverage.walkTrees(plan.cells, std::move(trees), run.starts(), progress);
        driveAtOwnSpeeds(paths, plan.cells, speeds);
        return paths;
    });
    if (paced)
        run.stage("speed balance", [&] {
            return balanceOwnSpeeds(run, trips, reach, startCells, guessedPaces, allocator, straightening,
                                    coverage);
        });
    // Costs only estimate path times: border cells pass from the longest path to shorter neighbours, paths
    // replanned, while that shortens the longest. Bounded to about half a second of replanning. Skipped where
    // the robots' reach shaped the division: the robots it caps keep the paths from their mean, and the
    // chains tried spend the budget (1.2 s in each field-time round on 25 M pixels with six drones) for a
    // later last robot home.
    PathTimeBalancing balancing(coverage, PathTimeBalancing::budgetFor(plan.cells));
    // Path balancing weighs each path by its robot's time in the field as the division counts it.
    balancing.setFieldPaces(
        trips.weighs() ? withFieldPaces(trips.paces(plan.cells, plan.regions), fieldPaces, startCells.size())
                       : fieldPaces);
    if (reach.limits())
        balancing.setMayTake(
            [&](std::size_t robot, int cell) { return reach.reaches(robot, plan.cells.cell(cell)); });
    run.stage("path balance", [&] {
        if (reachCaps)
            return 0;
        return balancing.balance(plan.cells, plan.regions, plan.paths, run.starts(), progress);
    });
    run.stage("turn search", [&] {
        return turnSearch.improve(plan.cells, plan.regions, plan.paths, run.starts(), progress);
    });
    plan.countedFieldPaces = trips.paces(plan.cells, plan.regions);
}

} // namespace mcpp
