#include "core/planners/MlctPlanner.hpp"

#include "core/allocation/AzimuthTrendAllocator.hpp"
#include "core/decomposition/NeighbourTopologyBuilder.hpp"
#include "core/planners/PlanMetricsCalculator.hpp"
#include "core/model/PlanningError.hpp"
#include "core/decomposition/QuadTreeBuilder.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

std::string robotAt(std::size_t robot, MapPoint point) {
    std::ostringstream text;
    text.precision(12);
    text << "robot " << robot << " start (" << point.x << ", " << point.y << ")";
    return text.str();
}

class StageTimer {
public:
    explicit StageTimer(PlanMetrics& metrics) : metrics_(metrics) {}
    template <typename Work>
    auto run(const char* stage, Work&& work) {
        const auto begin = std::chrono::steady_clock::now();
        auto result = work();
        const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - begin;
        timings_.emplace_back(stage, elapsed.count());
        return result;
    }
    void commit() { metrics_.stageMilliseconds = timings_; }

private:
    PlanMetrics& metrics_;
    std::vector<std::pair<std::string, double>> timings_;
};

} // namespace

namespace {

bool insideRaster(const ClassGrid& grid, MapPoint point) {
    return point.x >= grid.originX && point.x < grid.maxX() && point.y > grid.minY() && point.y <= grid.originY;
}

// Starts that are no point or off the raster are wrong whatever the quadtree: say so before building it.
void checkStartsBeforeBuilding(const PlanningProblem& problem) {
    for (std::size_t robot = 0; robot < problem.starts.size(); ++robot) {
        const MapPoint start = problem.starts[robot];
        if (!std::isfinite(start.x) || !std::isfinite(start.y))
            throw PlanningError(Kind::InvalidParameter, robotAt(robot, start) + " is not a number");
        if (!problem.settings.snapStartsToFreeCells && !insideRaster(problem.grid, start))
            throw PlanningError(Kind::StartOutsideArea, robotAt(robot, start) + " is outside the map");
    }
}

} // namespace

std::vector<int> locateStartCells(const QuadTree& tree, const PlanningProblem& problem, std::vector<MapPoint>& starts,
                                  std::vector<std::string>& warnings) {
    const ClassGrid& grid = problem.grid;
    const bool snap = problem.settings.snapStartsToFreeCells;
    std::vector<int> startCells;
    std::vector<int> ownerOfCell(tree.activeCount(), -1);
    for (std::size_t robot = 0; robot < starts.size(); ++robot) {
        MapPoint& start = starts[robot];
        if (!std::isfinite(start.x) || !std::isfinite(start.y))
            throw PlanningError(Kind::InvalidParameter, robotAt(robot, start) + " is not a number");
        const int leaf = tree.leafAt(start.x, start.y);
        std::string problemText;
        Kind kind = Kind::StartOnObstacle;
        if (!insideRaster(grid, start) || leaf < 0) {
            problemText = robotAt(robot, start) + " is outside the map";
            kind = Kind::StartOutsideArea;
        } else if (tree.cells[static_cast<std::size_t>(leaf)].state != CellState::Active) {
            const int column = static_cast<int>((start.x - grid.originX) / grid.pixelWidth);
            const int row = static_cast<int>((grid.originY - start.y) / grid.pixelHeight);
            if (grid.isOutside(column, row)) {
                problemText = robotAt(robot, start) + " is outside the task area (nodata)";
                kind = Kind::StartOutsideArea;
            } else {
                const auto* landCover = problem.classes.find(grid.valueAt(column, row));
                if (landCover != nullptr && landCover->isTraversable()) {
                    problemText = robotAt(robot, start) + " is in a cell that is mostly obstacle or outside the area "
                                  "(more than " + std::to_string(static_cast<int>(problem.settings.blockedThreshold * 100.0)) + "%)";
                } else {
                    problemText = robotAt(robot, start) + " is on an obstacle" +
                                  (landCover != nullptr ? " (" + landCover->name + ", class " + std::to_string(landCover->value) + ")"
                                                        : std::string());
                }
            }
        } else if (ownerOfCell[static_cast<std::size_t>(tree.cells[static_cast<std::size_t>(leaf)].activeIndex)] >= 0) {
            const int other = ownerOfCell[static_cast<std::size_t>(tree.cells[static_cast<std::size_t>(leaf)].activeIndex)];
            problemText = robotAt(robot, start) + " is in the same cell as robot " + std::to_string(other);
            kind = Kind::StartsShareCell;
        }
        int cell = problemText.empty() ? tree.cells[static_cast<std::size_t>(leaf)].activeIndex : -1;
        if (cell < 0) {
            if (!snap) throw PlanningError(kind, problemText);
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t candidate = 0; candidate < tree.activeCount(); ++candidate) {
                if (ownerOfCell[candidate] >= 0) continue;
                const QuadCell& quadCell = tree.active(static_cast<int>(candidate));
                const double d = std::hypot(quadCell.centreX() - start.x, quadCell.centreY() - start.y);
                if (d < best) {
                    best = d;
                    cell = static_cast<int>(candidate);
                }
            }
            if (cell < 0) throw PlanningError(Kind::TooManyRobots, problemText + " and no free cell is left");
            const QuadCell& target = tree.active(cell);
            start = {target.centreX(), target.centreY()};
            std::ostringstream moved;
            moved.precision(12);
            moved << problemText << "; moved to (" << start.x << ", " << start.y << ")";
            warnings.push_back(moved.str());
        }
        ownerOfCell[static_cast<std::size_t>(cell)] = static_cast<int>(robot);
        startCells.push_back(cell);
    }
    return startCells;
}

Plan MlctPlanner::plan(const PlanningProblem& problem, const ProgressReporter& progress) const {
    if (problem.starts.empty()) throw PlanningError(Kind::InvalidParameter, "no robots: give at least one start point");
    checkStartsBeforeBuilding(problem);
    Plan plan;
    plan.planner = name();
    StageTimer timer(plan.metrics);
    plan.quadTree = timer.run("quadtree", [&] { return QuadTreeBuilder{}.build(problem.grid, problem.classes, problem.settings, progress); });
    if (plan.quadTree.activeCount() == 0)
        throw PlanningError(Kind::NoPassableCell, "no cell of the quadtree is passable: every bottom cell is more than " +
                                                      std::to_string(problem.settings.blockedThreshold * 100.0) +
                                                      "% obstacle or outside the area");
    if (problem.starts.size() > plan.quadTree.activeCount())
        throw PlanningError(Kind::TooManyRobots, std::to_string(problem.starts.size()) + " robots but only " +
                                                     std::to_string(plan.quadTree.activeCount()) + " passable cells");
    progress.throwIfCancelled();
    plan.topology = timer.run("topology", [&] {
        progress.report("topology", 0.0);
        return NeighbourTopologyBuilder{}.build(plan.quadTree);
    });
    std::vector<MapPoint> starts = problem.starts;
    const std::vector<int> startCells = locateStartCells(plan.quadTree, problem, starts, plan.warnings);
    progress.throwIfCancelled();
    plan.allocation = timer.run("allocation", [&] {
        return AzimuthTrendAllocator{}.allocate(plan.quadTree, plan.topology, startCells, problem.settings, progress);
    });
    plan.paths = timer.run("paths", [&] {
        return SpanningTreeCoverage{}.plan(plan.quadTree, plan.topology, plan.allocation, starts, problem.settings, progress);
    });
    timer.run("metrics", [&] {
        PlanMetricsCalculator{}.compute(plan);
        return 0;
    });
    timer.commit();
    if (plan.metrics.unreachableAreaSquareMetres > 0.0) {
        std::ostringstream text;
        text.precision(6);
        text << plan.metrics.unreachableAreaSquareMetres << " m2 of passable land cannot be reached by any robot";
        plan.warnings.push_back(text.str());
    }
    progress.report("done", 1.0);
    return plan;
}

} // namespace mcpp
