#include "tests/support/PlanInvariants.hpp"

#include "core/allocation/RegionAllocator.hpp"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace mcpp::test {
namespace {

std::string text(const std::string& what, double a, double b) {
    std::ostringstream out;
    out.precision(12);
    out << what << " (" << a << " vs " << b << ")";
    return out.str();
}

using SubCellKey = std::pair<long long, long long>;

SubCellKey keyOf(double x, double y, double step) { return {std::llround(x / step), std::llround(y / step)}; }

} // namespace

std::vector<std::string> checkTiling(const PlanningProblem& problem, const Plan& plan) {
    std::vector<std::string> violations;
    const QuadTree& tree = plan.quadTree;
    const int bottom = tree.levels;
    const long long columns = tree.columnsAt(bottom);
    const long long rows = tree.rowsAt(bottom);
    std::vector<unsigned char> covered(static_cast<std::size_t>(columns * rows), 0);
    for (std::size_t index = 0; index < tree.cells.size(); ++index) {
        const QuadCell& cell = tree.cells[index];
        if (cell.state == CellState::Auxiliary) {
            for (int child : cell.children)
                if (child < 0) violations.push_back("auxiliary cell " + std::to_string(index) + " lacks a child");
            continue;
        }
        const int span = 1 << (bottom - cell.level);
        for (long long r = static_cast<long long>(cell.row) * span; r < static_cast<long long>(cell.row + 1) * span; ++r)
            for (long long c = static_cast<long long>(cell.column) * span; c < static_cast<long long>(cell.column + 1) * span; ++c)
                ++covered[static_cast<std::size_t>(r * columns + c)];
        if (cell.state == CellState::Active && (cell.activeIndex < 0 || tree.activeCells[static_cast<std::size_t>(cell.activeIndex)] != static_cast<int>(index)))
            violations.push_back("active cell " + std::to_string(index) + " is not listed under its active index");
        if (cell.state == CellState::Active && !(cell.speedMetresPerSecond > 0.0))
            violations.push_back("active cell " + std::to_string(index) + " has no positive speed");
    }
    for (std::size_t i = 0; i < covered.size(); ++i)
        if (covered[i] != 1) {
            violations.push_back("bottom position " + std::to_string(i) + " is covered by " + std::to_string(covered[i]) + " leaves");
            break;
        }
    // With no purity tolerance, an active cell above the bottom holds only classes whose rounded FOV is
    // at least its sub-cell side, and no obstacle or outside pixel.
    if (problem.settings.purityTolerance == 0.0) {
        std::map<std::int32_t, double> rounded;
        for (const auto& entry : tree.roundedFieldsOfView) rounded[entry.classValue] = entry.roundedMetres;
        const ClassGrid& grid = problem.grid;
        for (int cellIndex : tree.activeCells) {
            const QuadCell& cell = tree.cells[static_cast<std::size_t>(cellIndex)];
            if (cell.level == bottom) continue;
            const int firstColumn = std::max(0, static_cast<int>(std::ceil((cell.minX - grid.originX) / grid.pixelWidth - 0.5)));
            const int lastColumn = std::min(grid.columns, static_cast<int>(std::ceil((cell.maxX() - grid.originX) / grid.pixelWidth - 0.5)));
            const int firstRow = std::max(0, static_cast<int>(std::ceil((grid.originY - cell.maxY()) / grid.pixelHeight - 0.5)));
            const int lastRow = std::min(grid.rows, static_cast<int>(std::ceil((grid.originY - cell.minY) / grid.pixelHeight - 0.5)));
            for (int r = firstRow; r < lastRow; ++r) {
                for (int c = firstColumn; c < lastColumn; ++c) {
                    const auto found = rounded.find(grid.valueAt(c, r));
                    if (grid.isOutside(c, r) || found == rounded.end() || found->second < cell.fieldOfView() - 1e-9) {
                        violations.push_back("active cell " + std::to_string(cellIndex) + " at level " + std::to_string(cell.level) +
                                             " holds pixel (" + std::to_string(c) + ", " + std::to_string(r) +
                                             ") that needs a smaller cell");
                        r = lastRow;
                        break;
                    }
                }
            }
        }
    }
    return violations;
}

std::vector<std::string> checkRegions(const Plan& plan) {
    std::vector<std::string> violations;
    const auto& owner = plan.allocation.robotOfCell;
    const NeighbourTopology& topology = plan.topology;
    const std::size_t cells = plan.quadTree.activeCount();
    if (owner.size() != cells) return {"allocation covers " + std::to_string(owner.size()) + " of " + std::to_string(cells) + " cells"};
    // Reachable = in a component holding a start.
    std::vector<char> reachable(cells, 0);
    std::vector<int> queue;
    for (int start : plan.allocation.startCell) {
        if (!reachable[static_cast<std::size_t>(start)]) queue.push_back(start);
        reachable[static_cast<std::size_t>(start)] = 1;
    }
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int neighbour : topology.of(queue[head]))
            if (!reachable[static_cast<std::size_t>(neighbour)]) {
                reachable[static_cast<std::size_t>(neighbour)] = 1;
                queue.push_back(neighbour);
            }
    for (std::size_t cell = 0; cell < cells; ++cell) {
        if (reachable[cell] && owner[cell] < 0) violations.push_back("reachable cell " + std::to_string(cell) + " has no robot");
        if (!reachable[cell] && owner[cell] >= 0) violations.push_back("unreachable cell " + std::to_string(cell) + " has a robot");
    }
    for (std::size_t robot = 0; robot < plan.allocation.startCell.size(); ++robot) {
        const int start = plan.allocation.startCell[robot];
        if (owner[static_cast<std::size_t>(start)] != static_cast<int>(robot)) {
            violations.push_back("robot " + std::to_string(robot) + " does not hold its start cell");
            continue;
        }
        std::vector<char> seen(cells, 0);
        std::vector<int> region{start};
        seen[static_cast<std::size_t>(start)] = 1;
        for (std::size_t head = 0; head < region.size(); ++head)
            for (int neighbour : topology.of(region[head]))
                if (!seen[static_cast<std::size_t>(neighbour)] && owner[static_cast<std::size_t>(neighbour)] == static_cast<int>(robot)) {
                    seen[static_cast<std::size_t>(neighbour)] = 1;
                    region.push_back(neighbour);
                }
        std::size_t size = 0;
        for (std::size_t cell = 0; cell < cells; ++cell) size += owner[cell] == static_cast<int>(robot) ? 1 : 0;
        if (region.size() != size)
            violations.push_back("region of robot " + std::to_string(robot) + " is not connected (" + std::to_string(region.size()) +
                                 " of " + std::to_string(size) + " cells reached from the start)");
    }
    // Neighbour lists are symmetric and never list a cell twice.
    for (std::size_t cell = 0; cell < cells; ++cell) {
        std::set<int> unique;
        for (int neighbour : topology.of(static_cast<int>(cell))) {
            if (!unique.insert(neighbour).second) violations.push_back("cell " + std::to_string(cell) + " lists a neighbour twice");
            if (!topology.areNeighbours(neighbour, static_cast<int>(cell)))
                violations.push_back("neighbour relation " + std::to_string(cell) + "-" + std::to_string(neighbour) + " is one-sided");
        }
    }
    return violations;
}

std::vector<std::string> checkPaths(const PlanningProblem& problem, const Plan& plan) {
    std::vector<std::string> violations;
    const QuadTree& tree = plan.quadTree;
    const auto& owner = plan.allocation.robotOfCell;
    if (plan.paths.size() != plan.allocation.startCell.size()) return {"one path per robot expected"};
    const double step = tree.fovMin / 64.0;
    for (std::size_t robot = 0; robot < plan.paths.size(); ++robot) {
        const CoveragePath& path = plan.paths[robot];
        const std::string who = "robot " + std::to_string(robot);
        if (path.waypoints.empty()) {
            violations.push_back(who + " has an empty path");
            continue;
        }
        const Waypoint& first = path.waypoints.front();
        const MapPoint start = problem.starts[robot];
        if (!problem.settings.snapStartsToFreeCells && std::hypot(first.x - start.x, first.y - start.y) > 1e-6)
            violations.push_back(text(who + " path does not begin at its start point", first.x, start.x));
        if (path.closed) {
            const Waypoint& last = path.waypoints.back();
            if (std::hypot(last.x - first.x, last.y - first.y) > 1e-6) violations.push_back(who + " closed tour does not return");
        }
        std::set<SubCellKey> visited;
        for (std::size_t i = 0; i < path.waypoints.size(); ++i) {
            const Waypoint& waypoint = path.waypoints[i];
            const int leaf = tree.leafAt(waypoint.x, waypoint.y);
            const bool inOwnCell = leaf >= 0 && tree.cells[static_cast<std::size_t>(leaf)].state == CellState::Active &&
                                   owner[static_cast<std::size_t>(tree.cells[static_cast<std::size_t>(leaf)].activeIndex)] == static_cast<int>(robot);
            // A start point on a cell border may be attributed to the cell on either side.
            if (!inOwnCell && !(i == 0 || i + 1 == path.waypoints.size()))
                violations.push_back(who + " waypoint " + std::to_string(i) + " is outside its region");
            if (waypoint.activeCell < 0 || owner[static_cast<std::size_t>(waypoint.activeCell)] != static_cast<int>(robot))
                violations.push_back(who + " waypoint " + std::to_string(i) + " names a cell outside its region");
            if (i > 0) {
                const int a = path.waypoints[i - 1].activeCell;
                const int b = waypoint.activeCell;
                if (a != b && !plan.topology.areNeighbours(a, b))
                    violations.push_back(who + " jumps between cells that do not touch at waypoint " + std::to_string(i));
            }
            visited.insert(keyOf(waypoint.x, waypoint.y, step));
        }
        for (std::size_t cell = 0; cell < owner.size(); ++cell) {
            if (owner[cell] != static_cast<int>(robot)) continue;
            const QuadCell& quadCell = tree.active(static_cast<int>(cell));
            const double quarter = quadCell.size / 4.0;
            const double xs[2] = {quadCell.minX + quarter, quadCell.maxX() - quarter};
            const double ys[2] = {quadCell.minY + quarter, quadCell.maxY() - quarter};
            for (double x : xs)
                for (double y : ys)
                    if (!visited.count(keyOf(x, y, step))) {
                        violations.push_back(text(who + " misses a sub-cell centre of cell " + std::to_string(cell), x, y));
                        break;
                    }
        }
    }
    return violations;
}

std::vector<std::string> checkTimes(const Plan& plan) {
    std::vector<std::string> violations;
    double totalCost = 0.0;
    for (std::size_t cell = 0; cell < plan.allocation.robotOfCell.size(); ++cell)
        if (plan.allocation.robotOfCell[cell] >= 0) totalCost += cellCostSeconds(plan.quadTree.active(static_cast<int>(cell)));
    double sumOfRegions = 0.0;
    for (double cost : plan.allocation.costSeconds) sumOfRegions += cost;
    if (std::abs(sumOfRegions - totalCost) > 1e-6 * std::max(1.0, totalCost))
        violations.push_back(text("region costs do not add up to the total", sumOfRegions, totalCost));
    double makespan = 0.0;
    for (const auto& path : plan.paths) {
        double length = 0.0;
        double time = 0.0;
        for (std::size_t i = 1; i < path.waypoints.size(); ++i) {
            const Waypoint& a = path.waypoints[i - 1];
            const Waypoint& b = path.waypoints[i];
            const double segment = std::hypot(b.x - a.x, b.y - a.y);
            length += segment;
            time += segment / 2.0 / a.speedMetresPerSecond + segment / 2.0 / b.speedMetresPerSecond;
            if (std::abs(b.cumulativeSeconds - time) > 1e-6 * std::max(1.0, time))
                violations.push_back(text("robot " + std::to_string(path.robot) + " cumulative time wrong at waypoint " + std::to_string(i),
                                          b.cumulativeSeconds, time));
        }
        if (std::abs(length - path.lengthMetres) > 1e-6 * std::max(1.0, length))
            violations.push_back(text("robot " + std::to_string(path.robot) + " length", path.lengthMetres, length));
        if (std::abs(time - path.timeSeconds) > 1e-6 * std::max(1.0, time))
            violations.push_back(text("robot " + std::to_string(path.robot) + " time", path.timeSeconds, time));
        makespan = std::max(makespan, time);
    }
    const PlanMetrics& metrics = plan.metrics;
    if (std::abs(metrics.makespanSeconds - makespan) > 1e-6 * std::max(1.0, makespan))
        violations.push_back(text("makespan", metrics.makespanSeconds, makespan));
    const double lowerBound = plan.paths.empty() ? 0.0 : totalCost / static_cast<double>(plan.paths.size());
    if (std::abs(metrics.lowerBoundSeconds - lowerBound) > 1e-6 * std::max(1.0, lowerBound))
        violations.push_back(text("lower bound", metrics.lowerBoundSeconds, lowerBound));
    if (lowerBound > 0 && std::abs(metrics.ratio - makespan / lowerBound) > 1e-9)
        violations.push_back(text("ratio", metrics.ratio, makespan / lowerBound));
    return violations;
}

std::vector<std::string> checkAllInvariants(const PlanningProblem& problem, const Plan& plan) {
    std::vector<std::string> all;
    for (auto&& part : {checkTiling(problem, plan), checkRegions(plan), checkPaths(problem, plan), checkTimes(plan)})
        all.insert(all.end(), part.begin(), part.end());
    return all;
}

std::string describe(const std::vector<std::string>& violations, std::size_t limit) {
    std::string out;
    for (std::size_t i = 0; i < violations.size() && i < limit; ++i) out += violations[i] + "\n";
    if (violations.size() > limit) out += "... and " + std::to_string(violations.size() - limit) + " more\n";
    return out;
}

} // namespace mcpp::test
