// How long a cancel request takes to stop MCPP-MLCT: the wait a user has after pressing Cancel. Plans the
// raster with its opening class table and one robot per start, asks to stop after each delay in turn, and
// prints where planning was and how long it took to stop.
// Run: build/release/bench/mcpp_cancel_latency RASTER X,Y [X,Y ...] -- DELAY_S [DELAY_S ...]
#include "core/model/PlanningError.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/ClassTableSources.hpp"
#include "io/LoadedRaster.hpp"
#include "io/MissionInputs.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

using namespace mcpp;

namespace {

struct Arguments {
    std::string raster;
    std::vector<MapPoint> starts;
    std::vector<double> delays;
};

std::optional<Arguments> parse(int count, char** values) {
    Arguments arguments;
    bool delays = false;
    for (int i = 1; i < count; ++i) {
        const std::string value = values[i];
        if (value == "--")
            delays = true;
        else if (arguments.raster.empty())
            arguments.raster = value;
        else if (delays)
            arguments.delays.push_back(std::stod(value));
        else if (const auto comma = value.find(','); comma != std::string::npos)
            arguments.starts.push_back(
                {std::stod(value.substr(0, comma)), std::stod(value.substr(comma + 1))});
    }
    if (arguments.raster.empty() || arguments.starts.empty() || arguments.delays.empty())
        return std::nullopt;
    return arguments;
}

// Plans once, asking to stop after `delay` seconds; prints the stage it was in and the wait from the
// request to the stop, or when the plan finished where it finished first.
void cancelAfter(const PlanningProblem& problem, double delay) {
    std::atomic<bool> cancel{false};
    std::mutex mutex;
    std::condition_variable planned;
    bool done = false;
    std::string stage = "start";
    double askedAt = -1.0;
    const auto started = std::chrono::steady_clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    };
    std::thread canceller([&] {
        std::unique_lock lock(mutex);
        if (planned.wait_for(lock, std::chrono::duration<double>(delay), [&] { return done; }))
            return; // finished before the request
        askedAt = seconds();
        std::printf("asked to stop at %.2f s, in %s; ", askedAt, stage.c_str());
        cancel = true;
    });
    const ProgressReporter progress(
        [&](std::string_view now, double) {
            const std::lock_guard lock(mutex);
            stage = now;
        },
        &cancel);
    std::string outcome;
    try {
        (void)MlctPlanner{}.plan(problem, progress);
        outcome = "finished";
    } catch (const PlanningError& error) {
        outcome = error.kind() == PlanningError::Kind::Cancelled ? "stopped"
                                                                 : "failed: " + std::string(error.what());
    }
    const double ended = seconds();
    {
        const std::lock_guard lock(mutex);
        done = true;
    }
    planned.notify_all();
    canceller.join();
    if (outcome == "stopped")
        std::printf("stopped at %.2f s: %.2f s after the request\n", ended, ended - askedAt);
    else
        std::printf("%s at %.2f s, before a request at %.2f s\n", outcome.c_str(), ended, delay);
}

} // namespace

int main(int count, char** values) {
    const auto arguments = parse(count, values);
    if (!arguments) {
        std::fputs("usage: mcpp_cancel_latency RASTER X,Y [X,Y ...] -- DELAY_S [DELAY_S ...]\n", stderr);
        return 2;
    }
    auto raster = io::loadLandCoverRaster(arguments->raster);
    if (!raster) {
        std::fprintf(stderr, "%s\n", raster.error().c_str());
        return 1;
    }
    const ClassTable classes = io::openingClassTable(raster.value()).table;
    auto prepared = io::planningProblem(raster.value(), classes, true, arguments->starts,
                                        defaultPlannerChoice(MlctPlanner::plannerName), {});
    if (!prepared) {
        std::fprintf(stderr, "%s\n", prepared.error().c_str());
        return 1;
    }
    for (const double delay : arguments->delays)
        cancelAfter(prepared.value().problem, delay);
    return 0;
}
