// What reopening a saved mission costs instead of planning again: writing and reading the plan beside the
// mission (io/PlanFile) for plans of the core benchmarks' multi-cover maps (compare with multiCoverMap in
// mcpp_core_benchmarks, the time to plan the same map) and, with MCPP_BENCH_MISSION=mission.json, for the
// plan of a real mission, whose planning time is reported beside as plan_s.
#include "core/planners/PlannerRegistry.hpp"
#include "io/MissionInputs.hpp"
#include "io/PlanFile.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>

using namespace mcpp;

namespace {

// The map of mcpp_core_benchmarks' multiCoverMap, planned once.
const Plan& plannedMap(int size, int robots) {
    static std::map<std::pair<int, int>, Plan> plans;
    auto found = plans.find({size, robots});
    if (found != plans.end())
        return found->second;
    PlanningProblem problem = test::randomProblem(test::multiCoverSpec(size, robots));
    problem.planner = defaultPlannerChoice("mcpp-mlct");
    return plans.emplace(std::pair{size, robots}, makePlanner("mcpp-mlct")->plan(problem, {})).first->second;
}

struct MissionPlan {
    Plan plan;
    double planSeconds = 0.0;
};

// The plan of the mission named by MCPP_BENCH_MISSION, made as batch mode makes it; nothing without one.
const MissionPlan* missionPlan() {
    static std::optional<MissionPlan> planned = []() -> std::optional<MissionPlan> {
        const char* path = std::getenv("MCPP_BENCH_MISSION");
        if (path == nullptr)
            return std::nullopt;
        auto mission = io::loadMission(path);
        auto raster = mission ? io::loadMissionRaster(mission.value(), path)
                              : io::Result<io::LoadedRaster>::failure(mission.error());
        if (!raster) {
            std::cerr << raster.error() << "\n";
            return std::nullopt;
        }
        const auto names = io::missionFileFields(path);
        auto classes = io::missionClasses(mission.value(), raster.value(), names);
        auto starts =
            classes ? io::missionStarts(mission.value(), raster.value(), io::StartUnits::PlanningCrs, names)
                    : io::Result<std::vector<MapPoint>>::failure(classes.error());
        auto prepared = starts ? io::planningProblem(raster.value(), classes.value(),
                                                     mission.value().missingClassesAsObstacles,
                                                     starts.value(), mission.value().planner, names)
                               : io::Result<io::PreparedProblem>::failure(starts.error());
        if (!prepared) {
            std::cerr << prepared.error() << "\n";
            return std::nullopt;
        }
        const auto started = std::chrono::steady_clock::now();
        MissionPlan result;
        result.plan = makePlanner(mission.value().planner.planner)->plan(prepared.value().problem, {});
        result.planSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        return result;
    }();
    return planned ? &*planned : nullptr;
}

std::string scratchFile() {
    return (std::filesystem::temp_directory_path() / "mcpp-bench.mcpp-plan").string();
}

void savePlan(benchmark::State& state) {
    const Plan& plan = plannedMap(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    const std::string path = scratchFile();
    for (auto _ : state) {
        if (!io::savePlanFile(plan, "bench", path).ok())
            state.SkipWithError("cannot write the plan file");
    }
    state.counters["cells"] = static_cast<double>(plan.cells.size());
    state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    std::filesystem::remove(path);
}

void loadPlan(benchmark::State& state) {
    const Plan& plan = plannedMap(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    const std::string path = scratchFile();
    if (!io::savePlanFile(plan, "bench", path).ok())
        state.SkipWithError("cannot write the plan file");
    for (auto _ : state) {
        auto loaded = io::loadPlanFile(path, "bench");
        if (!loaded.ok() || !loaded.value())
            state.SkipWithError("cannot read the plan file");
        benchmark::DoNotOptimize(loaded);
    }
    state.counters["cells"] = static_cast<double>(plan.cells.size());
    std::filesystem::remove(path);
}

void saveAndLoadMissionPlan(benchmark::State& state) {
    const MissionPlan* mission = missionPlan();
    if (mission == nullptr) {
        state.SkipWithError("set MCPP_BENCH_MISSION to a mission file");
        return;
    }
    const std::string path = scratchFile();
    const bool save = state.range(0) == 0;
    if (!save && !io::savePlanFile(mission->plan, "bench", path).ok())
        state.SkipWithError("cannot write the plan file");
    for (auto _ : state) {
        if (save && !io::savePlanFile(mission->plan, "bench", path).ok())
            state.SkipWithError("cannot write the plan file");
        if (!save) {
            auto loaded = io::loadPlanFile(path, "bench");
            if (!loaded.ok() || !loaded.value())
                state.SkipWithError("cannot read the plan file");
            benchmark::DoNotOptimize(loaded);
        }
    }
    state.counters["cells"] = static_cast<double>(mission->plan.cells.size());
    state.counters["plan_s"] = mission->planSeconds;
    state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
}

} // namespace

// Argument 0 saves, 1 reads what was saved.
BENCHMARK(saveAndLoadMissionPlan)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(savePlan)->ArgsProduct({{256, 1024}, {16}})->Unit(benchmark::kMillisecond);
BENCHMARK(loadPlan)->ArgsProduct({{256, 1024}, {16}})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
