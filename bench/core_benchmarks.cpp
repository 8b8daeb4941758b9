// Benchmarks of the MCPP-MLCT pipeline. Run: build/release/bench/mcpp_core_benchmarks
// Counters: ratio = makespan / lower bound, makespan_s, turn_time_s = time all robots lose turning (turn_s
// auto by default: speed / 1 m/s2, here 1 s per 90 degrees), border_km = length of the borders between
// regions (how compact they are), cells = active cells, peak_rss_mb = process
// peak memory so far. The *_free_turns cases plan with turn_s 0, as before turns were timed.
#include "core/model/DetectionLayer.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <string>
#include <sys/resource.h>

using namespace mcpp;

namespace {

double peakResidentMegabytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// Three land covers (FOV 5, 10, 20 m) in patches, 5% obstacles; `size` bottom cells a side.
PlanningProblem multiCover(int size, int robots, std::uint32_t seed) {
    return test::randomProblem(test::multiCoverSpec(size, robots, seed));
}

// Length of the borders between regions, each counted once (the map's edge not counted): how compact the
// regions are, as a user sees them on the map.
double regionBorderKilometres(const Plan& plan) {
    const std::vector<int>& robotOf = plan.regions.robotOfCell;
    if (robotOf.size() != plan.cells.size())
        return 0.0;
    double metres = 0.0;
    for (int cell = 0; cell < static_cast<int>(plan.cells.size()); ++cell) {
        const int robot = robotOf[static_cast<std::size_t>(cell)];
        for (int other : plan.cells.neighbours(cell)) {
            const int otherRobot = robotOf[static_cast<std::size_t>(other)];
            if (other > cell && robot >= 0 && otherRobot >= 0 && otherRobot != robot)
                metres += std::min(plan.cells.cell(cell).size, plan.cells.cell(other).size);
        }
    }
    return metres / 1000.0;
}

void runPlanner(benchmark::State& state, PlanningProblem problem,
                const std::string& plannerName = "mcpp-mlct", const ParameterValues& overrides = {}) {
    const auto planner = makePlanner(plannerName);
    problem.planner = defaultPlannerChoice(plannerName);
    for (const auto& [key, value] : overrides.all())
        problem.planner.parameters.set(key, value);
    Plan plan;
    for (auto _ : state) {
        plan = planner->plan(problem, {});
        benchmark::ClobberMemory();
    }
    int turns = 0;
    double turnSeconds = 0.0;
    for (const auto& path : plan.paths) {
        turns += path.turns;
        turnSeconds += path.turnSeconds;
    }
    state.counters["ratio"] = plan.metrics.ratio;
    // balance = longest path / mean path; connector_time_s = what all paths spend stepping between cells of
    // different sizes beyond their cells' travel, which the lower bound counts like turns;
    // ratio_before_connectors = the makespan over the bound without them, the ratio as the sections of
    // docs/benchmarks.md before 2026-11-25 give it.
    double pathSeconds = 0.0;
    double connectorSeconds = 0.0;
    for (const auto& path : plan.paths) {
        pathSeconds += path.timeSeconds;
        connectorSeconds += path.connectorSeconds;
    }
    if (!plan.paths.empty() && pathSeconds > 0.0) {
        const double robots = static_cast<double>(plan.paths.size());
        state.counters["balance"] = plan.metrics.makespanSeconds * robots / pathSeconds;
        state.counters["connector_time_s"] = connectorSeconds;
        // Only where the whole-map bound is the one in force (no pocket, battery or detection bound).
        const double boundBefore = plan.metrics.lowerBoundSeconds - connectorSeconds / robots;
        const bool wholeMapBound = plan.metrics.confinedRobots.empty() && sortieLayerOf(plan) == nullptr &&
                                   detectionLayerOf(plan) == nullptr;
        if (wholeMapBound && boundBefore > 0.0)
            state.counters["ratio_before_connectors"] = plan.metrics.makespanSeconds / boundBefore;
    }
    state.counters["turns"] = turns;
    state.counters["border_km"] = regionBorderKilometres(plan);
    state.counters["makespan_s"] = plan.metrics.makespanSeconds;
    state.counters["turn_time_s"] = turnSeconds;
    state.counters["cells"] = static_cast<double>(plan.cells.size());
    state.counters["covered"] = plan.metrics.coveredFraction;
    if (const SortieLayer* sorties = sortieLayerOf(plan)) {
        int flights = 0;
        for (const RobotSorties& robot : sorties->robots())
            flights += static_cast<int>(robot.sorties.size());
        state.counters["sorties"] = flights;
    }
    if (const DetectionLayer* detection = detectionLayerOf(plan)) {
        state.counters["detection_min"] = detection->summary().minimum;
        state.counters["detection_mean"] = detection->summary().mean;
        state.counters["share_met"] = detection->summary().shareMet;
        // Balance: the longest robot time over the mean one.
        double sum = 0.0;
        for (const auto& path : plan.paths)
            sum += path.timeSeconds;
        state.counters["longest_over_mean"] =
            plan.paths.empty() ? 0.0
                               : plan.metrics.makespanSeconds * static_cast<double>(plan.paths.size()) / sum;
    }
    if (const TimelineLayer* timeline = timelineLayerOf(plan)) {
        const TimelineLayer::Summary& summary = timeline->summary();
        state.counters["under_events_s"] = summary.makespanSeconds;
        state.counters["static_s"] = summary.staticMakespanSeconds;
        state.counters["over_static"] = summary.makespanSeconds / summary.staticMakespanSeconds;
    }
    state.counters["peak_rss_mb"] = peakResidentMegabytes();
    for (const auto& [stage, milliseconds] : plan.metrics.stageMilliseconds)
        state.counters[stage + "_ms"] = milliseconds;
}

void uniformGrid(benchmark::State& state, const std::string& planner) {
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        planner);
}

// Turns free (turn_s 0): the times and ratios of plans before turns were timed.
void uniformGridFreeTurns(benchmark::State& state, const std::string& planner) {
    ParameterValues freeTurns;
    freeTurns.set("turn_s", 0.0);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        planner, freeTurns);
}

// MCPP-MLCT on the grid of range(0) cells a side with range(1) robots, the percent parameter `key` set to
// range(2) tenths of a percent.
void uniformGridWithPercent(benchmark::State& state, const std::string& key) {
    ParameterValues percent;
    percent.set(key, static_cast<double>(state.range(2)) / 10.0);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "mcpp-mlct", percent);
}

// MCPP-MLCT's balance-for-turns trade.
void uniformGridTurnSlack(benchmark::State& state) {
    uniformGridWithPercent(state, "fewer_turns_slack");
}

// MCPP-MLCT's regions grown on tree pieces of a share of a robot's fair share (0: cell by cell).
void uniformGridTreePieces(benchmark::State& state) {
    uniformGridWithPercent(state, "tree_piece_share");
}

void multiCoverMapFreeTurns(benchmark::State& state) {
    ParameterValues freeTurns;
    freeTurns.set("turn_s", 0.0);
    runPlanner(state, multiCover(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 7),
               "mcpp-mlct", freeTurns);
}

// MSTC with balanced pieces (its `balanced` parameter).
void uniformGridBalancedMstc(benchmark::State& state) {
    ParameterValues balanced;
    balanced.set("balanced", true);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "mstc", balanced);
}

// MSTC with balanced pieces also cut as subtrees around the starts (its `subtree_pieces` parameter).
void uniformGridSubtreeMstc(benchmark::State& state) {
    ParameterValues subtrees;
    subtrees.set("balanced", true);
    subtrees.set("subtree_pieces", true);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "mstc", subtrees);
}
// Wavefront coverage on a battery of range(2) seconds with 600 s recharges (1 m/s: a 49 x 49 grid of 10 m
// pixels is 48 000 s of work).
void uniformGridBattery(benchmark::State& state) {
    ParameterValues battery;
    battery.set("battery_s", static_cast<double>(state.range(2)));
    battery.set("recharge_s", 600.0);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "wavefront-battery", battery);
}

// CPPIED with a sensor of range(2) percent p0 on the uniform grids (one land cover, FOV one pixel), every
// cell to be seen with 0.95.
void uniformGridDetection(benchmark::State& state) {
    ParameterValues detection;
    detection.set("detection_probability", static_cast<double>(state.range(2)) / 100.0);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "cppied", detection);
}

// CPPIED on the multi-cover maps: three land covers of different fields of view.
void multiCoverDetection(benchmark::State& state) {
    runPlanner(state, multiCover(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 7),
               "cppied");
}

// MDSTC on the uniform grids without events: its makespan over the static MCPP-MLCT plan's (over_static).
void uniformGridMdstc(benchmark::State& state) {
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "mdstc");
}

// The same with turns free (turn_s 0), for MDSTC and its static plan alike.
void uniformGridMdstcFreeTurns(benchmark::State& state) {
    ParameterValues freeTurns;
    freeTurns.set("turn_s", 0.0);
    runPlanner(
        state,
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020),
        "mdstc", freeTurns);
}

// MDSTC with robot 0 at half speed from a quarter of its makespan without events, against the static plan
// run through the same event.
void uniformGridMdstcSlowRobot(benchmark::State& state) {
    PlanningProblem problem =
        test::obstacleGridProblem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 2020);
    problem.planner = defaultPlannerChoice("mdstc");
    const Plan calm = makePlanner("mdstc")->plan(problem, {});
    problem.events = {{timelineLayerOf(calm)->summary().makespanSeconds / 4.0, 0, 0.5}};
    runPlanner(state, problem, "mdstc");
}

// MDSTC without events on the multi-cover maps (FOVs 5, 10 and 20 m): quadtree cells of several sizes.
void multiCoverMdstc(benchmark::State& state) {
    runPlanner(state, multiCover(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 7),
               "mdstc");
}

void multiCoverMap(benchmark::State& state) {
    runPlanner(state, multiCover(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 7));
}

} // namespace

// The DARP / DMSTC grids for every planner that takes several robots; single-robot planners on one.
BENCHMARK_CAPTURE(uniformGrid, mcpp_mlct, std::string("mcpp-mlct"))
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniformGridFreeTurns, mcpp_mlct_free_turns, std::string("mcpp-mlct"))
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridTurnSlack)
    ->ArgsProduct({{49, 200}, {8, 20}, {0, 2, 10, 50}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridTreePieces)
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}, {0, 30, 60, 120, 250}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridMdstc)->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridMdstcFreeTurns)
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(multiCoverMdstc)->ArgsProduct({{128, 256, 512}, {2, 8, 32}})->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridMdstcSlowRobot)
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniformGrid, darp, std::string("darp"))
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniformGrid, darp_turns, std::string("darp-turns"))
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniformGrid, mstc, std::string("mstc"))
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridBattery)
    ->ArgsProduct({{49, 100, 200}, {1, 4, 20}, {1200, 3600}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridDetection)
    ->ArgsProduct({{49, 100, 200}, {1, 4, 20}, {90, 100}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(multiCoverDetection)->ArgsProduct({{128, 512}, {4, 16}})->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridBalancedMstc)
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(uniformGridSubtreeMstc)
    ->ArgsProduct({{49, 100, 200}, {2, 4, 8, 14, 20}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniformGrid, spiral_stc, std::string("spiral-stc"))
    ->ArgsProduct({{49, 100, 200}, {1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(uniformGrid, full_spiral_stc, std::string("full-spiral-stc"))
    ->ArgsProduct({{49, 100, 200}, {1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(multiCoverMap)->ArgsProduct({{128}, {2, 4, 8, 16, 32}})->Unit(benchmark::kMillisecond);
BENCHMARK(multiCoverMapFreeTurns)->ArgsProduct({{128}, {2, 4, 8, 16, 32}})->Unit(benchmark::kMillisecond);
BENCHMARK(multiCoverMap)->ArgsProduct({{256, 512, 1024}, {16}})->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
