#include "core/coverage/TurnSearch.hpp"

#include "core/coverage/OwnSpeeds.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/model/ParallelFor.hpp"

#include <algorithm>
#include <atomic>

namespace mcpp {
namespace {

// Paths within rounding of each other take as long: the new one then gains only by turning less (which
// counts where turns are free, turn_s 0).
bool isGain(const CoveragePath& walked, const CoveragePath& path) {
    constexpr double relativeMargin = 1e-9;
    if (walked.timeSeconds < path.timeSeconds * (1.0 - relativeMargin))
        return true;
    return walked.timeSeconds <= path.timeSeconds * (1.0 + relativeMargin) &&
           countTurns(walked.waypoints) < countTurns(path.waypoints);
}

} // namespace

ParameterSpec TurnSearch::roundsParameter() {
    return integerParameter(
        "turn_search_rounds", "Turn search rounds", 16, 0, 64,
        "Most rounds of the last search for fewer turns: each region's tree is built "
        "again and its edges swapped where the turns stay as many, then where they fall; "
        "more rounds, fewer turns and longer planning. 0 skips it. Maps above 10 000 "
        "cells get fewer rounds (4 at 40 000 cells, 1 from 160 000), maps above 2 million "
        "none");
}

int TurnSearch::roundsFor(const CellGraph& graph, const ParameterValues& parameters) {
    const int wanted = parameters.integer(roundsParameter().key);
    // A round takes about 1 ms per 10 000 cells (2.7 ms on 200 x 200 with 15 % obstacles), after building
    // the trees again, which costs about five rounds: many rounds where they cost little, one on large maps,
    // none where building the trees again alone would take seconds.
    constexpr std::size_t cellRounds = 160'000;
    constexpr std::size_t mostCells = 2'000'000;
    const std::size_t cells = std::max<std::size_t>(graph.size(), 1);
    if (cells > mostCells || wanted <= 0)
        return 0;
    return static_cast<int>(
        std::min(static_cast<std::size_t>(wanted), std::max<std::size_t>(1, cellRounds / cells)));
}

TurnSearch TurnSearch::forPlan(const CellGraph& graph, const ParameterValues& parameters) {
    return {parameters.boolean(SpanningTreeCoverage::closedTourParameter().key),
            roundsFor(graph, parameters)};
}

int TurnSearch::improve(const CellGraph& graph, const RegionAllocation& regions,
                        std::vector<CoveragePath>& paths, const std::vector<MapPoint>& starts,
                        const ProgressReporter& progress) const {
    if (rounds_ <= 0)
        return 0;
    const std::vector<std::vector<int>> cells = cellsByRobot(regions);
    std::vector<std::vector<int>> scratchByWorker(static_cast<std::size_t>(workerThreads()));
    std::atomic<int> improved = 0;
    const std::size_t robots = std::min({paths.size(), cells.size(), starts.size()});
    parallelFor(robots, [&](std::size_t robot, int worker) {
        progress.throwIfCancelled();
        std::vector<int>& scratch = scratchByWorker[static_cast<std::size_t>(worker)];
        if (scratch.size() != graph.size())
            scratch.assign(graph.size(), -1);
        // The region's path was walked round the tree fewestTurns builds without the search (its only
        // candidate on cells of one size): where the search gains nothing, there is nothing to walk.
        const std::optional<SpanningTree> tree =
            SpanningTreeBuilder(graph, scratch, rounds_, &progress)
                .fewestTurnsSearched(cells[robot], regions.startCell[robot]);
        if (!tree)
            return;
        TreeCircumnavigation walker(graph);
        CoveragePath path =
            pathFromWalk(static_cast<int>(robot), starts[robot],
                         walker.walkFromStart(*tree, starts[robot], closedTour_), closedTour_);
        setOwnSpeed(path, ownSpeedOf(robotSpeeds_, robot));
        timePath(path, graph);
        if (!isGain(path, paths[robot]))
            return;
        paths[robot] = std::move(path);
        ++improved;
    });
    return improved;
}

} // namespace mcpp
