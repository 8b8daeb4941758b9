#pragma once

#include "core/coverage/CoveragePathPlanner.hpp"
#include "core/coverage/PathShape.hpp"
#include "core/coverage/SpanningTree.hpp"
#include "core/parameters/ParameterSpec.hpp"

#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace mcpp {

// Improved STC on mixed-size cells (spec section 5): a spanning tree over each region from its start cell,
// circumnavigated counter-clockwise through the centres of every cell's four sub-cells. Each region tries
// the builder's candidate trees (the turn-minimising one first) and keeps the quickest walk.
class SpanningTreeCoverage final : public CoveragePathPlanner {
  public:
    // Where a planner's paths may have their straight runs merged (mergeStraightRuns): on maps of this
    // many cells or more. On the 69 M-cell tile every waypoint of all paths, held at once, took 6.6 GB.
    static constexpr std::size_t fewestCellsForMergedRuns = 4'000'000;
    static constexpr std::size_t neverMergeRuns = std::numeric_limits<std::size_t>::max();

    // closedTour: tours end where they start; otherwise paths stop at the last sub-cell.
    // cellsForMergedRuns: from how many cells on paths merge their straight runs (made by walkTrees, or by
    // planTrees when small: RegionTree::walked); by default never, as planners that follow their robots
    // waypoint by waypoint (MDSTC) need them all.
    explicit SpanningTreeCoverage(bool closedTour = true, std::size_t cellsForMergedRuns = neverMergeRuns)
        : closedTour_(closedTour), cellsForMergedRuns_(cellsForMergedRuns) {}

    [[nodiscard]] static ParameterSpec closedTourParameter();

    // By robot, its own speed (PlanningProblem::robotSpeeds): regionPath's paths are driven at it. Empty
    // (the default): the class table's speeds.
    void setRobotSpeeds(std::vector<double> speeds) { robotSpeeds_ = std::move(speeds); }

    [[nodiscard]] std::vector<CoveragePath> plan(const CellGraph& graph, const RegionAllocation& regions,
                                                 const std::vector<MapPoint>& starts,
                                                 const ProgressReporter& progress) const override;
    // The same paths timed only (timePath), for a planner whose metrics stage measures them at the end.
    [[nodiscard]] std::vector<CoveragePath> timedPlan(const CellGraph& graph, const RegionAllocation& regions,
                                                      const std::vector<MapPoint>& starts,
                                                      const ProgressReporter& progress) const;

    // One robot's path over its region's cells: the quickest candidate tree's. scratchIndex: one int per
    // graph cell, all -1, left so; or empty (SpanningTreeBuilder).
    [[nodiscard]] CoveragePath regionPath(const CellGraph& graph, const std::vector<int>& cells,
                                          int startCell, int robot, MapPoint start,
                                          std::vector<int>& scratchIndex) const;

    // A region's quickest tree with its walk's shape, timed: what its path is made from, or the path itself.
    struct RegionTree {
        SpanningTree tree;
        PathShape shape;
        // On maps of cellsForMergedRuns cells or more, the path walkTrees would make, when the walk that
        // measured the shape kept few waypoints (walkedPathLimit); the tree is then dropped, not walked
        // again.
        std::optional<CoveragePath> walked;
    };
    // The most waypoints a path walked while its tree was chosen may keep, for a tree of `cells` cells: one
    // for 8 cells (3 bytes a cell), less than the packed tree that waits otherwise. While walked, the path
    // also takes a byte a cell of the whole map to count repeated visits (RepeatedVisitCounter), as a walk
    // of walkTrees does.
    [[nodiscard]] static std::size_t walkedPathLimit(std::size_t cells) { return cells / 8; }
    // Every region's quickest tree, not yet walked, or on large maps its path when that is small
    // (RegionTree::walked): two divisions are compared by their trees' shapes while holding a quarter of
    // what their whole paths would take (24 bytes a cell against four 24-byte waypoints).
    // `timed`: every shape timed, for comparing; otherwise only where candidates were compared.
    [[nodiscard]] std::vector<RegionTree> planTrees(const CellGraph& graph, const RegionAllocation& regions,
                                                    const std::vector<MapPoint>& starts,
                                                    const ProgressReporter& progress, bool timed) const;
    // planTrees for a division evened out from `earlier`: a region whose cells and start are those it had
    // there keeps its tree (a copy: a tree depends on nothing else), with its path if it was walked; the
    // others are planned anew and not walked beyond their shapes: a division made to be compared is often
    // let go.
    [[nodiscard]] std::vector<RegionTree> replanTrees(const CellGraph& graph, const RegionAllocation& regions,
                                                      const RegionAllocation& earlier,
                                                      const std::vector<RegionTree>& earlierTrees,
                                                      const std::vector<MapPoint>& starts,
                                                      const ProgressReporter& progress, bool timed) const;
    // The paths round the trees, each tree freed once walked (progress reported as "waypoints"); a path
    // already walked (RegionTree::walked) is handed over. Timed only (timePath): a planner's metrics stage
    // measures every path once, at the end. On maps of cellsForMergedRuns cells or more each path is
    // measured as walked and its straight runs merged.
    [[nodiscard]] std::vector<CoveragePath> walkTrees(const CellGraph& graph, std::vector<RegionTree> trees,
                                                      const std::vector<MapPoint>& starts,
                                                      const ProgressReporter& progress) const;
    // The candidate tree whose walk is quickest (travel and turns; then turns least, then is shortest), with
    // that walk's shape; timed when there was more than one candidate, or always when `timed`.
    [[nodiscard]] std::pair<SpanningTree, PathShape> bestTree(const CellGraph& graph, std::vector<int> cells,
                                                              int startCell, MapPoint start,
                                                              std::vector<int>& scratchIndex,
                                                              bool timed = false) const;

  private:
    // bestTree, and with `walkLimit` above 0 the lone candidate's path kept when it is that small.
    // progress, where given: a cancel request stops it between its candidates and within the build of the
    // turn-minimising one.
    [[nodiscard]] RegionTree bestRegionTree(const CellGraph& graph, std::vector<int> cells, int startCell,
                                            int robot, MapPoint start, std::vector<int>& scratchIndex,
                                            bool timed, std::size_t walkLimit,
                                            const ProgressReporter* progress = nullptr) const;
    // planTrees, where a robot with a tree in `kept` takes a copy of it instead; `walkSmallPaths`: on large
    // maps, paths of few waypoints made as the trees are measured (RegionTree::walked).
    [[nodiscard]] std::vector<RegionTree>
    planTreesKeeping(const CellGraph& graph, const RegionAllocation& regions,
                     const std::vector<MapPoint>& starts, const ProgressReporter& progress, bool timed,
                     const std::vector<const RegionTree*>& kept, bool walkSmallPaths) const;

    bool closedTour_;
    std::size_t cellsForMergedRuns_;
    std::vector<double> robotSpeeds_; // by robot; empty: the class table's speeds
};

// Whether the trees' longest walk is shorter than the other trees', beyond rounding.
[[nodiscard]] bool walksQuicker(const std::vector<SpanningTreeCoverage::RegionTree>& trees,
                                const std::vector<SpanningTreeCoverage::RegionTree>& than);
// Each tree's walk's time spent turning, by robot.
[[nodiscard]] std::vector<double>
turningSecondsOf(const std::vector<SpanningTreeCoverage::RegionTree>& trees);

// The cells of each robot's region, in cell-id order.
[[nodiscard]] std::vector<std::vector<int>> cellsByRobot(const RegionAllocation& regions);

} // namespace mcpp
