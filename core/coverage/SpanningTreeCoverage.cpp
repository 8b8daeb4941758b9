#include "core/coverage/SpanningTreeCoverage.hpp"

#include "core/coverage/OwnSpeeds.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/model/ParallelFor.hpp"

#include <algorithm>
#include <mutex>

namespace mcpp {
namespace {

// How many cells each robot has.
std::vector<std::size_t> cellCounts(const RegionAllocation& regions) {
    std::vector<std::size_t> counts(regions.startCell.size(), 0);
    for (const int robot : regions.robotOfCell)
        if (robot >= 0 && static_cast<std::size_t>(robot) < counts.size())
            ++counts[static_cast<std::size_t>(robot)];
    return counts;
}

} // namespace

std::vector<std::vector<int>> cellsByRobot(const RegionAllocation& regions) {
    const std::size_t robots = regions.startCell.size();
    // Counted first: a region of millions of cells would otherwise grow through a dozen copies.
    const std::vector<std::size_t> counts = cellCounts(regions);
    std::vector<std::vector<int>> cells(robots);
    for (std::size_t robot = 0; robot < robots; ++robot)
        cells[robot].reserve(counts[robot]);
    for (std::size_t cell = 0; cell < regions.robotOfCell.size(); ++cell) {
        const int robot = regions.robotOfCell[cell];
        if (robot >= 0 && static_cast<std::size_t>(robot) < cells.size())
            cells[static_cast<std::size_t>(robot)].push_back(static_cast<int>(cell));
    }
    return cells;
}

namespace {

// One robot's cells, ascending (`count` of them): on a large map a region's list is made when the region is
// planned, not all regions' lists beforehand (a gigabyte on a map of 69 million cells).
std::vector<int> cellsOfRobot(const RegionAllocation& regions, int robot, std::size_t count) {
    std::vector<int> cells;
    cells.reserve(count);
    for (std::size_t cell = 0; cell < regions.robotOfCell.size(); ++cell)
        if (regions.robotOfCell[cell] == robot)
            cells.push_back(static_cast<int>(cell));
    return cells;
}

// Walks and measured paths add the same times in other orders: a tie must not be decided by rounding.
constexpr double relativeMargin = 1e-9;

// The longest of the trees' walks, in seconds.
double longestWalkSeconds(const std::vector<SpanningTreeCoverage::RegionTree>& trees) {
    double longest = 0.0;
    for (const SpanningTreeCoverage::RegionTree& planned : trees)
        longest = std::max(longest, planned.shape.seconds());
    return longest;
}

} // namespace

bool walksQuicker(const std::vector<SpanningTreeCoverage::RegionTree>& trees,
                  const std::vector<SpanningTreeCoverage::RegionTree>& than) {
    return longestWalkSeconds(trees) < longestWalkSeconds(than) * (1.0 - relativeMargin);
}

std::vector<double> turningSecondsOf(const std::vector<SpanningTreeCoverage::RegionTree>& trees) {
    std::vector<double> seconds;
    seconds.reserve(trees.size());
    for (const SpanningTreeCoverage::RegionTree& planned : trees)
        seconds.push_back(planned.shape.turningSeconds());
    return seconds;
}

ParameterSpec SpanningTreeCoverage::closedTourParameter() {
    return booleanParameter("closed_tour", "Return to start", true,
                            "Closed tours end where they start; open paths stop at the last cell");
}

std::pair<SpanningTree, PathShape>
SpanningTreeCoverage::bestTree(const CellGraph& graph, std::vector<int> cells, int startCell, MapPoint start,
                               std::vector<int>& scratchIndex, bool timed) const {
    RegionTree best = bestRegionTree(graph, std::move(cells), startCell, -1, start, scratchIndex, timed, 0);
    return {std::move(best.tree), best.shape};
}

SpanningTreeCoverage::RegionTree
SpanningTreeCoverage::bestRegionTree(const CellGraph& graph, std::vector<int> cells, int startCell, int robot,
                                     MapPoint start, std::vector<int>& scratchIndex, bool timed,
                                     std::size_t walkLimit, const ProgressReporter* progress) const {
    const SpanningTreeBuilder trees(graph, scratchIndex, 0, progress);
    TreeCircumnavigation walker(graph);
    const int candidates = trees.candidatesFor(cells);
    if (candidates == 1 && walkLimit > 0) {
        RegionTree lone{trees.candidate(0, std::move(cells), startCell), {}, std::nullopt};
        auto [shape, path] = walker.walkShapeAndPath(lone.tree, robot, start, closedTour_, timed, walkLimit);
        lone.shape = shape;
        lone.walked = std::move(path);
        if (lone.walked)
            lone.tree = SpanningTree(); // the path is made: the tree is not walked again
        return lone;
    }
    // Candidate trees are judged by the shape of their walk, which is measured without being stored.
    RegionTree best;
    bool haveBest = false;
    for (int candidate = 0; candidate < candidates; ++candidate) {
        if (progress != nullptr)
            progress->throwIfCancelled();
        // The last candidate takes the cells: a region of millions of cells is not held twice.
        SpanningTree tree = candidate + 1 == candidates
                                ? trees.candidate(candidate, std::move(cells), startCell)
                                : trees.candidate(candidate, cells, startCell);
        // A lone candidate needs no time: its shape only sizes the path.
        const PathShape shape = walker.walkShape(tree, start, closedTour_, timed || candidates > 1);
        if (!haveBest || isQuicker(shape, best.shape)) {
            best.tree = std::move(tree);
            best.shape = shape;
            haveBest = true;
        }
    }
    return best;
}

CoveragePath SpanningTreeCoverage::regionPath(const CellGraph& graph, const std::vector<int>& cells,
                                              int startCell, int robot, MapPoint start,
                                              std::vector<int>& scratchIndex) const {
    const auto [tree, shape] = bestTree(graph, cells, startCell, start, scratchIndex);
    TreeCircumnavigation walker(graph);
    CoveragePath path =
        pathFromWalk(robot, start, walker.walk(tree, start, closedTour_, shape.points()), closedTour_);
    setOwnSpeed(path, ownSpeedOf(robotSpeeds_, static_cast<std::size_t>(robot)));
    measurePath(path, graph);
    return path;
}

std::vector<SpanningTreeCoverage::RegionTree>
SpanningTreeCoverage::planTrees(const CellGraph& graph, const RegionAllocation& regions,
                                const std::vector<MapPoint>& starts, const ProgressReporter& progress,
                                bool timed) const {
    return planTreesKeeping(graph, regions, starts, progress, timed,
                            std::vector<const RegionTree*>(regions.startCell.size(), nullptr), true);
}

std::vector<SpanningTreeCoverage::RegionTree> SpanningTreeCoverage::replanTrees(
    const CellGraph& graph, const RegionAllocation& regions, const RegionAllocation& earlier,
    const std::vector<RegionTree>& earlierTrees, const std::vector<MapPoint>& starts,
    const ProgressReporter& progress, bool timed) const {
    const std::size_t robots = regions.startCell.size();
    std::vector<const RegionTree*> kept(robots, nullptr);
    const bool comparable = earlier.robotOfCell.size() == regions.robotOfCell.size() &&
                            earlier.startCell == regions.startCell && earlierTrees.size() == robots;
    if (comparable) {
        std::vector<char> changed(robots, 0);
        for (std::size_t id = 0; id < regions.robotOfCell.size(); ++id) {
            const int before = earlier.robotOfCell[id];
            const int now = regions.robotOfCell[id];
            if (before == now)
                continue;
            for (const int robot : {before, now})
                if (robot >= 0 && static_cast<std::size_t>(robot) < robots)
                    changed[static_cast<std::size_t>(robot)] = 1;
        }
        for (std::size_t robot = 0; robot < robots; ++robot)
            if (changed[robot] == 0)
                kept[robot] = &earlierTrees[robot];
    }
    return planTreesKeeping(graph, regions, starts, progress, timed, kept, false);
}

std::vector<SpanningTreeCoverage::RegionTree>
SpanningTreeCoverage::planTreesKeeping(const CellGraph& graph, const RegionAllocation& regions,
                                       const std::vector<MapPoint>& starts, const ProgressReporter& progress,
                                       bool timed, const std::vector<const RegionTree*>& kept,
                                       bool walkSmallPaths) const {
    const std::size_t robots = regions.startCell.size();
    const bool largeMap = graph.size() >= cellsForMergedRuns_;
    auto regionCells = largeMap ? std::vector<std::vector<int>>(robots) : cellsByRobot(regions);
    const std::vector<std::size_t> counts = largeMap ? cellCounts(regions) : std::vector<std::size_t>{};
    // Regions are planned side by side, each into its own slot: the same trees whatever the thread count.
    std::vector<std::vector<int>> scratchIndex(static_cast<std::size_t>(workerThreads()));
    std::vector<RegionTree> trees(robots);
    std::mutex progressMutex;
    std::size_t finished = 0;
    progress.report("paths", 0.0);
    parallelFor(robots, [&](std::size_t robot, int worker) {
        progress.throwIfCancelled();
        if (kept[robot] != nullptr) {
            trees[robot] = *kept[robot];
        } else {
            std::vector<int>& scratch = scratchIndex[static_cast<std::size_t>(worker)];
            // On large maps a region's cells are numbered by rank (CellIndexScope) instead of in an array
            // of the whole map's size for each thread.
            if (!largeMap && scratch.size() != graph.size())
                scratch.assign(graph.size(), -1);
            if (largeMap)
                regionCells[robot] = cellsOfRobot(regions, static_cast<int>(robot), counts[robot]);
            // The tree holds its cells now. On large maps a path of few waypoints is made as the tree's
            // walk is measured; otherwise the tree waits packed beside the regions still planned.
            trees[robot] =
                bestRegionTree(graph, std::move(regionCells[robot]), regions.startCell[robot],
                               static_cast<int>(robot), starts[robot], scratch, timed,
                               largeMap && walkSmallPaths ? walkedPathLimit(counts[robot]) : 0, &progress);
            if (largeMap && !trees[robot].walked)
                trees[robot].tree.pack();
        }
        const std::lock_guard lock(progressMutex);
        progress.report("paths", static_cast<double>(++finished) / static_cast<double>(robots));
    });
    progress.report("paths", 1.0);
    return trees;
}

std::vector<CoveragePath> SpanningTreeCoverage::walkTrees(const CellGraph& graph,
                                                          std::vector<RegionTree> trees,
                                                          const std::vector<MapPoint>& starts,
                                                          const ProgressReporter& progress) const {
    std::vector<CoveragePath> paths(trees.size());
    std::mutex progressMutex;
    std::size_t finished = 0;
    progress.report("waypoints", 0.0);
    parallelFor(trees.size(), [&](std::size_t robot, int) {
        progress.throwIfCancelled();
        TreeCircumnavigation walker(graph);
        RegionTree& planned = trees[robot];
        planned.tree.unpack(); // an empty tree, where the path was walked, has nothing to unpack
        if (planned.walked) {
            paths[robot] = std::move(*planned.walked);
        } else if (graph.size() >= cellsForMergedRuns_) {
            paths[robot] =
                walker.measuredWalk(planned.tree, static_cast<int>(robot), starts[robot], closedTour_);
        } else {
            // The walk already begins (and a closed one ends) at the start: pathFromWalk moves no waypoint.
            paths[robot] = pathFromWalk(
                static_cast<int>(robot), starts[robot],
                walker.walkFromStart(planned.tree, starts[robot], closedTour_, planned.shape.points()),
                closedTour_);
            timePath(paths[robot], graph);
        }
        planned.tree = SpanningTree(); // freed once walked: all trees and all paths are never held together
        const std::lock_guard lock(progressMutex);
        progress.report("waypoints", static_cast<double>(++finished) / static_cast<double>(paths.size()));
    });
    return paths;
}

std::vector<CoveragePath> SpanningTreeCoverage::plan(const CellGraph& graph, const RegionAllocation& regions,
                                                     const std::vector<MapPoint>& starts,
                                                     const ProgressReporter& progress) const {
    std::vector<CoveragePath> paths = timedPlan(graph, regions, starts, progress);
    parallelFor(paths.size(), [&](std::size_t robot, int) { measurePath(paths[robot], graph); });
    return paths;
}

std::vector<CoveragePath> SpanningTreeCoverage::timedPlan(const CellGraph& graph,
                                                          const RegionAllocation& regions,
                                                          const std::vector<MapPoint>& starts,
                                                          const ProgressReporter& progress) const {
    return walkTrees(graph, planTrees(graph, regions, starts, progress, false), starts, progress);
}

} // namespace mcpp
