#include "tests/support/PlanInvariants.hpp"

#include "core/allocation/StartComponents.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/SortieLayer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
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

std::string cellName(int id) {
    return "cell " + std::to_string(id);
}

// Which cell owns each bottom position of the frame (-1: none); reports overlaps.
std::vector<int> occupancy(const CellGraph& graph, std::vector<std::string>& violations) {
    const GridFrame& frame = graph.frame();
    std::vector<int> owner(static_cast<std::size_t>(frame.columns) * static_cast<std::size_t>(frame.rows),
                           -1);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        for (long long r = cell.row; r < cell.row + cell.span && r < frame.rows; ++r)
            for (long long c = cell.column; c < cell.column + cell.span && c < frame.columns; ++c) {
                int& slot = owner[static_cast<std::size_t>(r * frame.columns + c)];
                if (slot >= 0) {
                    violations.push_back(cellName(static_cast<int>(id)) + " overlaps " + cellName(slot));
                    return owner;
                }
                slot = static_cast<int>(id);
            }
    }
    return owner;
}

bool onPlacement(const GridFrame& frame, const Cell& cell) {
    const double tolerance = 1e-6 * frame.bottomCellSize;
    return cell.span >= 1 && cell.column >= 0 && cell.row >= 0 && cell.column + cell.span <= frame.columns &&
           cell.row + cell.span <= frame.rows && cell.column % cell.span == 0 && cell.row % cell.span == 0 &&
           std::abs(cell.minX - frame.x(cell.column)) < tolerance &&
           std::abs(cell.maxY() - frame.y(cell.row)) < tolerance &&
           std::abs(cell.size - cell.span * frame.bottomCellSize) < tolerance;
}

// Cells connected to a start cell through the graph.
std::vector<char> reachableFromStarts(const Plan& plan) {
    const CellGraph& graph = plan.cells;
    std::vector<char> reachable(graph.size(), 0);
    std::vector<int> queue;
    for (int start : plan.regions.startCell) {
        if (start < 0 || static_cast<std::size_t>(start) >= graph.size() ||
            reachable[static_cast<std::size_t>(start)])
            continue;
        reachable[static_cast<std::size_t>(start)] = 1;
        queue.push_back(start);
    }
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int neighbour : graph.neighbours(queue[head]))
            if (!reachable[static_cast<std::size_t>(neighbour)]) {
                reachable[static_cast<std::size_t>(neighbour)] = 1;
                queue.push_back(neighbour);
            }
    return reachable;
}

bool insideCell(const Cell& cell, MapPoint point) {
    const double tolerance = 1e-6 * cell.size;
    return point.x >= cell.minX - tolerance && point.x <= cell.maxX() + tolerance &&
           point.y >= cell.minY - tolerance && point.y <= cell.maxY() + tolerance;
}

// (cell, sub-cell) when the waypoint sits on a sub-cell centre of its cell.
std::optional<std::pair<int, int>> subCellCentreAt(const CellGraph& graph, const Waypoint& waypoint) {
    const Cell& cell = graph.cell(waypoint.cell);
    const SubCell subCell = cell.subCellAt({waypoint.x, waypoint.y});
    const MapPoint centre = cell.subCellCentre(subCell);
    if (std::hypot(centre.x - waypoint.x, centre.y - waypoint.y) > 1e-6 * cell.size)
        return std::nullopt;
    return std::make_pair(waypoint.cell, static_cast<int>(subCell));
}

// Whether the first and last waypoints on sub-cell centres mark the same sub-cell.
bool returnsToFirstCentre(const CellGraph& graph, const CoveragePath& path) {
    std::optional<std::pair<int, int>> first;
    for (const Waypoint& waypoint : path.waypoints)
        if ((first = subCellCentreAt(graph, waypoint)))
            break;
    std::optional<std::pair<int, int>> last;
    for (auto it = path.waypoints.rbegin(); it != path.waypoints.rend(); ++it)
        if ((last = subCellCentreAt(graph, *it)))
            break;
    return first && last && *first == *last;
}

bool snapsStarts(const PlanningProblem& problem) {
    const ParameterValue* snap = problem.planner.parameters.find("snap_starts_to_free_cells");
    return snap != nullptr && std::get<bool>(*snap);
}

} // namespace

std::vector<std::string> checkCells(const Plan& plan) {
    std::vector<std::string> violations;
    const CellGraph& graph = plan.cells;
    const GridFrame& frame = graph.frame();
    for (std::size_t id = 0; id < graph.size(); ++id)
        for (const int neighbour : graph.neighbours(static_cast<int>(id)))
            if (neighbour < 0 || static_cast<std::size_t>(neighbour) >= graph.size() ||
                !graph.areNeighbours(neighbour, static_cast<int>(id)))
                return {cellName(static_cast<int>(id)) + " lists " + std::to_string(neighbour) +
                        " as a neighbour, which does not list it back"};
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        if (!onPlacement(frame, cell))
            violations.push_back(cellName(static_cast<int>(id)) + " is not where its placement says");
        if (!(cell.speedMetresPerSecond > 0.0))
            violations.push_back(cellName(static_cast<int>(id)) + " has no positive speed");
        if (cell.freeSubCells == 0 || cell.freeSubCells > allSubCells)
            violations.push_back(cellName(static_cast<int>(id)) + " has no free sub-cell");
    }
    if (!violations.empty())
        return violations;
    const std::vector<int> owner = occupancy(graph, violations);
    if (!violations.empty())
        return violations;
    // Neighbours are exactly the cells with free sub-cells facing each other across a shared border, judged
    // on the lattice of half bottom cells, where every sub-cell of every cell is one or more squares.
    std::set<std::pair<int, int>> expected;
    const long long latticeColumns = 2LL * frame.columns;
    const long long latticeRows = 2LL * frame.rows;
    const auto cellAt = [&](long long x, long long y) {
        return owner[static_cast<std::size_t>((y / 2) * frame.columns + x / 2)];
    };
    const auto freeAt = [&](int id, long long x, long long y) {
        const Cell& cell = graph.cell(id);
        const bool east = x - 2LL * cell.column >= cell.span;
        const bool south = y - 2LL * cell.row >= cell.span;
        const SubCell subCell = south ? (east ? SubCell::SouthEast : SubCell::SouthWest)
                                      : (east ? SubCell::NorthEast : SubCell::NorthWest);
        return cell.isFree(subCell);
    };
    for (long long y = 0; y < latticeRows; ++y)
        for (long long x = 0; x < latticeColumns; ++x) {
            const int a = cellAt(x, y);
            if (a < 0 || !freeAt(a, x, y))
                continue;
            for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (x + dx >= latticeColumns || y + dy >= latticeRows)
                    continue;
                const int b = cellAt(x + dx, y + dy);
                if (b >= 0 && b != a && freeAt(b, x + dx, y + dy))
                    expected.insert({std::min(a, b), std::max(a, b)});
            }
        }
    std::set<std::pair<int, int>> listed;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        std::set<int> unique;
        for (int neighbour : graph.neighbours(static_cast<int>(id))) {
            if (!unique.insert(neighbour).second)
                violations.push_back(cellName(static_cast<int>(id)) + " lists a neighbour twice");
            if (!graph.areNeighbours(neighbour, static_cast<int>(id)))
                violations.push_back("neighbour relation " + std::to_string(id) + "-" +
                                     std::to_string(neighbour) + " is one-sided");
            listed.insert(
                {std::min(static_cast<int>(id), neighbour), std::max(static_cast<int>(id), neighbour)});
        }
    }
    for (const auto& pair : expected)
        if (!listed.count(pair))
            violations.push_back("cells " + std::to_string(pair.first) + " and " +
                                 std::to_string(pair.second) + " touch but are not neighbours");
    for (const auto& pair : listed)
        if (!expected.count(pair))
            violations.push_back("cells " + std::to_string(pair.first) + " and " +
                                 std::to_string(pair.second) + " are neighbours but do not touch");
    return violations;
}

namespace {

// Each robot's cells lie in the connected part of its start cell: the metrics' pocket bound relies on it.
void checkRobotsStayInTheirPart(const Plan& plan, std::vector<std::string>& violations) {
    const std::vector<int>& starts = plan.regions.startCell;
    for (const int start : starts)
        if (start < 0 || static_cast<std::size_t>(start) >= plan.cells.size())
            return;
    std::vector<int> partOfCell(plan.cells.size(), -1);
    std::vector<int> partOfRobot(starts.size(), -1);
    const std::vector<StartComponent> parts = componentsWithStarts(plan.cells, starts);
    for (std::size_t part = 0; part < parts.size(); ++part) {
        for (const int cell : parts[part].cells)
            partOfCell[static_cast<std::size_t>(cell)] = static_cast<int>(part);
        for (const int robot : parts[part].robots)
            partOfRobot[static_cast<std::size_t>(robot)] = static_cast<int>(part);
    }
    for (std::size_t cell = 0; cell < plan.cells.size(); ++cell) {
        const int robot = plan.regions.robotOfCell[cell];
        if (robot >= 0 && static_cast<std::size_t>(robot) < starts.size() &&
            partOfCell[cell] != partOfRobot[static_cast<std::size_t>(robot)])
            violations.push_back(cellName(static_cast<int>(cell)) + " of robot " + std::to_string(robot) +
                                 " lies outside its start's connected part");
    }
}

} // namespace

std::vector<std::string> checkRegions(const Plan& plan, const PlannerPromises& promises) {
    std::vector<std::string> violations;
    const auto& owner = plan.regions.robotOfCell;
    const CellGraph& graph = plan.cells;
    const std::size_t cells = graph.size();
    const std::size_t robots = plan.regions.startCell.size();
    if (owner.size() != cells)
        return {"regions cover " + std::to_string(owner.size()) + " of " + std::to_string(cells) + " cells"};
    const std::vector<char> reachable = reachableFromStarts(plan);
    for (std::size_t cell = 0; cell < cells; ++cell) {
        if (owner[cell] >= static_cast<int>(robots))
            violations.push_back(cellName(static_cast<int>(cell)) + " names robot " +
                                 std::to_string(owner[cell]));
        if (promises.everyReachableCellCovered && reachable[cell] && owner[cell] < 0)
            violations.push_back("reachable " + cellName(static_cast<int>(cell)) + " has no robot");
        if (!reachable[cell] && owner[cell] >= 0)
            violations.push_back("unreachable " + cellName(static_cast<int>(cell)) + " has a robot");
    }
    checkRobotsStayInTheirPart(plan, violations);
    if (!promises.regionsConnected)
        return violations;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        const int start = plan.regions.startCell[robot];
        if (start < 0 || static_cast<std::size_t>(start) >= cells ||
            owner[static_cast<std::size_t>(start)] != static_cast<int>(robot)) {
            violations.push_back("robot " + std::to_string(robot) + " does not hold its start cell");
            continue;
        }
        std::vector<char> seen(cells, 0);
        std::vector<int> region{start};
        seen[static_cast<std::size_t>(start)] = 1;
        for (std::size_t head = 0; head < region.size(); ++head)
            for (int neighbour : graph.neighbours(region[head]))
                if (!seen[static_cast<std::size_t>(neighbour)] &&
                    owner[static_cast<std::size_t>(neighbour)] == static_cast<int>(robot)) {
                    seen[static_cast<std::size_t>(neighbour)] = 1;
                    region.push_back(neighbour);
                }
        const auto size =
            static_cast<std::size_t>(std::count(owner.begin(), owner.end(), static_cast<int>(robot)));
        if (region.size() != size)
            violations.push_back("region of robot " + std::to_string(robot) + " is not connected (" +
                                 std::to_string(region.size()) + " of " + std::to_string(size) +
                                 " cells reached from the start)");
    }
    return violations;
}

std::vector<std::string> checkPaths(const PlanningProblem& problem, const Plan& plan,
                                    const PlannerPromises& promises) {
    std::vector<std::string> violations;
    const CellGraph& graph = plan.cells;
    const auto& owner = plan.regions.robotOfCell;
    if (plan.paths.size() != plan.regions.startCell.size())
        return {"one path per robot expected"};
    if (owner.size() != graph.size())
        return {"regions do not match the cells"};
    std::map<std::pair<int, int>, std::set<int>> visitors; // (cell, sub-cell) -> robots passing its centre
    for (std::size_t robot = 0; robot < plan.paths.size(); ++robot) {
        const CoveragePath& path = plan.paths[robot];
        const std::string who = "robot " + std::to_string(robot);
        if (path.robot != static_cast<int>(robot))
            violations.push_back(who + " path is numbered " + std::to_string(path.robot));
        if (path.waypoints.empty()) {
            violations.push_back(who + " has an empty path");
            continue;
        }
        const Waypoint& first = path.waypoints.front();
        const MapPoint start = problem.starts[robot];
        // An aircraft whose start is on no free cell takes off there; its path begins elsewhere.
        if (path.takeOff && !(*path.takeOff == start))
            violations.push_back(text(who + " takes off elsewhere than its start", path.takeOff->x, start.x));
        const bool flies = robot < problem.flyingRobots.size() && problem.flyingRobots[robot];
        if (path.takeOff && !flies)
            violations.push_back(who + " takes off, but it does not fly");
        if (!snapsStarts(problem) && !path.takeOff && std::hypot(first.x - start.x, first.y - start.y) > 1e-6)
            violations.push_back(text(who + " path does not begin at its start point", first.x, start.x));
        if (path.closed) {
            const Waypoint& last = path.waypoints.back();
            if (std::hypot(last.x - first.x, last.y - first.y) > 1e-6)
                violations.push_back(who + " closed tour does not return");
        }
        std::map<std::pair<int, int>, int> ownVisits;
        for (std::size_t i = 0; i < path.waypoints.size(); ++i) {
            const Waypoint& waypoint = path.waypoints[i];
            const std::string where = who + " waypoint " + std::to_string(i);
            if (waypoint.cell < 0 || static_cast<std::size_t>(waypoint.cell) >= graph.size()) {
                violations.push_back(where + " names no cell");
                continue;
            }
            const Cell& cell = graph.cell(waypoint.cell);
            const MapPoint point{waypoint.x, waypoint.y};
            if (!insideCell(cell, point))
                violations.push_back(where + " is not in the cell it names");
            if (owner[static_cast<std::size_t>(waypoint.cell)] < 0)
                violations.push_back(where + " is in a cell no robot covers");
            if (promises.pathsCoverOwnRegion &&
                owner[static_cast<std::size_t>(waypoint.cell)] != static_cast<int>(robot))
                violations.push_back(where + " names a cell outside its region");
            // The start point itself may lie anywhere on its pixel; the walk proper keeps to free sub-cells.
            const bool isStartPoint = std::hypot(waypoint.x - first.x, waypoint.y - first.y) < 1e-9;
            if (!isStartPoint && !cell.isFree(cell.subCellAt(point)))
                violations.push_back(where + " enters a blocked sub-cell");
            if (i > 0) {
                const int a = path.waypoints[i - 1].cell;
                if (a != waypoint.cell && a >= 0 && !graph.areNeighbours(a, waypoint.cell))
                    violations.push_back(who + " jumps between cells that do not touch at waypoint " +
                                         std::to_string(i));
            }
            if (const auto visited = subCellCentreAt(graph, waypoint)) {
                visitors[*visited].insert(static_cast<int>(robot));
                ++ownVisits[*visited];
            }
        }
        int repeats = 0;
        for (const auto& [subCell, count] : ownVisits)
            repeats += count - 1;
        // A closed tour's return to the sub-cell it began in is no repeated coverage.
        if (path.closed && returnsToFirstCentre(graph, path) && repeats > 0)
            --repeats;
        if (repeats != path.repeatedSubCellVisits)
            violations.push_back(who + " reports " + std::to_string(path.repeatedSubCellVisits) +
                                 " repeated visits but makes " + std::to_string(repeats));
    }
    for (std::size_t id = 0; id < graph.size() && promises.passesEverySubCell; ++id) {
        const int robot = owner[id];
        if (robot < 0)
            continue;
        const Cell& cell = graph.cell(static_cast<int>(id));
        for (SubCell subCell : subCellsCounterClockwise) {
            if (!cell.isFree(subCell))
                continue;
            const auto found = visitors.find({static_cast<int>(id), static_cast<int>(subCell)});
            const bool passed =
                found != visitors.end() && (!promises.pathsCoverOwnRegion || found->second.count(robot) != 0);
            if (!passed) {
                const MapPoint centre = cell.subCellCentre(subCell);
                violations.push_back(text("robot " + std::to_string(robot) + " misses a sub-cell centre of " +
                                              cellName(static_cast<int>(id)),
                                          centre.x, centre.y));
                break;
            }
        }
    }
    return violations;
}

// The makespan no plan can beat, found apart from the planner's code: the cell graph splits into connected
// pieces, and the cost of a piece's covered cells is shared only by the robots that start in it (a robot
// may own no cell of its piece when others cover it for it, as MSTC's do).
double connectedPartsLowerBound(const Plan& plan) {
    const auto& owner = plan.regions.robotOfCell;
    std::vector<int> piece(plan.cells.size(), -1);
    double bound = 0.0;
    int piecesWithStarts = 0;
    for (std::size_t seed = 0; seed < piece.size(); ++seed) {
        if (piece[seed] >= 0)
            continue;
        std::vector<int> stack{static_cast<int>(seed)};
        piece[seed] = static_cast<int>(seed);
        double cost = 0.0;
        std::set<int> cells;
        while (!stack.empty()) {
            const int cell = stack.back();
            stack.pop_back();
            const auto index = static_cast<std::size_t>(cell);
            if (index < owner.size() && owner[index] >= 0)
                cost += plan.cells.cell(cell).travelSeconds();
            cells.insert(cell);
            for (const int next : plan.cells.neighbours(cell)) {
                if (piece[static_cast<std::size_t>(next)] < 0) {
                    piece[static_cast<std::size_t>(next)] = static_cast<int>(seed);
                    stack.push_back(next);
                }
            }
        }
        long robots = 0;
        for (std::size_t robot = 0; robot < plan.regions.startCell.size(); ++robot) {
            if (cells.count(plan.regions.startCell[robot]) == 0)
                continue;
            ++robots;
            if (robot < plan.paths.size())
                cost += plan.paths[robot].turnSeconds + plan.paths[robot].connectorSeconds;
        }
        if (robots > 0) {
            ++piecesWithStarts;
            bound = std::max(bound, cost / static_cast<double>(robots));
        }
    }
    return piecesWithStarts > 1 ? bound : 0.0;
}

// The time lost turning at waypoint i before leaving it, found apart from the planner's code: the angle
// between the way in and the way out (steps of no length skipped), at the point's cell's price per 90
// degrees.
double turnSecondsAt(const CoveragePath& path, std::size_t i, const CellGraph& cells) {
    const auto& points = path.waypoints;
    const Waypoint& here = points[i];
    if (here.cell < 0 || i + 1 >= points.size())
        return 0.0;
    std::size_t next = i + 1;
    if (points[next].x == here.x && points[next].y == here.y)
        return 0.0; // the turn is made at the last of the repeated points
    std::size_t before = i;
    while (before > 0 && points[before - 1].x == here.x && points[before - 1].y == here.y)
        --before;
    if (before == 0)
        return 0.0;
    const Waypoint& previous = points[before - 1];
    const double inAngle = std::atan2(here.y - previous.y, here.x - previous.x);
    const double outAngle = std::atan2(points[next].y - here.y, points[next].x - here.x);
    double angle = std::abs(outAngle - inAngle);
    if (angle > std::numbers::pi)
        angle = 2.0 * std::numbers::pi - angle;
    // A robot of its own speed (Plan::robotSpeeds) turns at it: the price then follows from that speed.
    const Cell cell = cells.cell(here.cell);
    const double price = here.speedMetresPerSecond == cell.speedMetresPerSecond
                             ? double(cell.turnSecondsPer90Degrees)
                             : double(cells.turnSeconds(here.cell, here.speedMetresPerSecond));
    return angle / (std::numbers::pi / 2.0) * price;
}

// Steps between cells of different sizes that share a side, timed half at each end's speed, less a quarter
// of each cell's side at its speed; worked out from the cells' squares, not the graph's links.
double connectorSecondsOf(const CoveragePath& path, const CellGraph& cells) {
    double seconds = 0.0;
    for (std::size_t i = 1; i < path.waypoints.size(); ++i) {
        const Waypoint& a = path.waypoints[i - 1];
        const Waypoint& b = path.waypoints[i];
        if (a.cell < 0 || b.cell < 0 || a.cell == b.cell)
            continue;
        const Cell& from = cells.cell(a.cell);
        const Cell& to = cells.cell(b.cell);
        const double tolerance = 1e-9 * std::max(from.size, to.size);
        const double overlapX = std::min(from.maxX(), to.maxX()) - std::max(from.minX, to.minX);
        const double overlapY = std::min(from.maxY(), to.maxY()) - std::max(from.minY, to.minY);
        const bool shareSide = (std::abs(overlapX) < tolerance && overlapY > tolerance) ||
                               (std::abs(overlapY) < tolerance && overlapX > tolerance);
        if (from.size == to.size || !shareSide)
            continue;
        const double step = std::hypot(b.x - a.x, b.y - a.y);
        seconds += step / 2.0 / a.speedMetresPerSecond + step / 2.0 / b.speedMetresPerSecond -
                   from.size / 4.0 / a.speedMetresPerSecond - to.size / 4.0 / b.speedMetresPerSecond;
    }
    return seconds;
}

double turnSecondsOf(const CoveragePath& path, const CellGraph& cells) {
    double seconds = 0.0;
    for (std::size_t i = 0; i < path.waypoints.size(); ++i)
        seconds += turnSecondsAt(path, i, cells);
    return seconds;
}

// The bound with robots of their own speeds, recounted: robot r needs its cells' travel at its speed (their
// length over it) and its turns and connectors; weighted by 1 over what r would take for every covered cell,
// the weighted sum of what the robots need, cells given each to the robot for which they weigh least, is
// no more than the makespan times the sum of the weights.
double ownSpeedsLowerBound(const Plan& plan) {
    const std::size_t robots = plan.paths.size();
    std::vector<double> alone(robots, 0.0); // what each robot would take for every covered cell
    for (std::size_t id = 0; id < plan.regions.robotOfCell.size(); ++id) {
        if (plan.regions.robotOfCell[id] < 0)
            continue;
        const Cell cell = plan.cells.cell(static_cast<int>(id));
        for (std::size_t robot = 0; robot < robots; ++robot) {
            const double speed = robot < plan.robotSpeeds.size() ? plan.robotSpeeds[robot] : 0.0;
            alone[robot] +=
                speed > 0.0 ? cell.travelSeconds() * cell.speedMetresPerSecond / speed : cell.travelSeconds();
        }
    }
    double weighted = 0.0;
    for (std::size_t id = 0; id < plan.regions.robotOfCell.size(); ++id) {
        if (plan.regions.robotOfCell[id] < 0)
            continue;
        const Cell cell = plan.cells.cell(static_cast<int>(id));
        double least = std::numeric_limits<double>::infinity();
        for (std::size_t robot = 0; robot < robots; ++robot) {
            const double speed = robot < plan.robotSpeeds.size() ? plan.robotSpeeds[robot] : 0.0;
            const double seconds =
                speed > 0.0 ? cell.travelSeconds() * cell.speedMetresPerSecond / speed : cell.travelSeconds();
            least = std::min(least, seconds / alone[robot]);
        }
        weighted += least;
    }
    double weights = 0.0;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        weights += 1.0 / alone[robot];
        weighted += (plan.paths[robot].turnSeconds + plan.paths[robot].connectorSeconds) / alone[robot];
    }
    return weighted / weights;
}

std::vector<std::string> checkTimes(const Plan& plan) {
    std::vector<std::string> violations;
    double totalCost = 0.0;
    double totalTravel = 0.0; // the covered cells' travel time, and below, the turns' and connectors'
    for (std::size_t cell = 0; cell < plan.regions.robotOfCell.size(); ++cell) {
        if (plan.regions.robotOfCell[cell] < 0)
            continue;
        const Cell& covered = plan.cells.cell(static_cast<int>(cell));
        totalCost += covered.coverSeconds();
        totalTravel += covered.travelSeconds();
        const double turns = covered.coverSeconds() - covered.travelSeconds();
        const double expected = double(covered.expectedTurnsPerSubCell) * covered.freeSubCellCount() *
                                double(covered.turnSecondsPer90Degrees);
        if (!(covered.expectedTurnsPerSubCell >= 0.0F))
            violations.push_back("cell " + std::to_string(cell) + " expects a negative turn rate");
        if (std::abs(turns - expected) > 1e-9 * std::max(1.0, expected))
            violations.push_back(text("cell " + std::to_string(cell) + " turn cost", turns, expected));
        // The price follows the plan's turn parameters (a planner that forgot it would price turns at 0).
        const double price =
            TurnTimeModel::from(plan.parameters).secondsPer90Degrees(covered.speedMetresPerSecond);
        if (std::abs(double(covered.turnSecondsPer90Degrees) - price) > 1e-6 * std::max(1.0, price))
            violations.push_back(
                text("cell " + std::to_string(cell) + " turn price", covered.turnSecondsPer90Degrees, price));
    }
    double sumOfRegions = 0.0;
    for (double cost : plan.regions.costSeconds)
        sumOfRegions += cost;
    if (std::abs(sumOfRegions - totalCost) > 1e-6 * std::max(1.0, totalCost))
        violations.push_back(text("region costs do not add up to the total", sumOfRegions, totalCost));
    double makespan = 0.0;
    for (const auto& path : plan.paths) {
        double length = 0.0;
        double time = 0.0;
        const double turning = turnSecondsOf(path, plan.cells);
        if (std::abs(turning - path.turnSeconds) > 1e-6 * std::max(1.0, turning))
            violations.push_back(
                text("robot " + std::to_string(path.robot) + " turn time", path.turnSeconds, turning));
        totalTravel += turning;
        const double connectors = connectorSecondsOf(path, plan.cells);
        if (std::abs(connectors - path.connectorSeconds) > 1e-6 * std::max(1.0, connectors))
            violations.push_back(text("robot " + std::to_string(path.robot) + " connector time",
                                      path.connectorSeconds, connectors));
        totalTravel += connectors;
        const std::vector<double> reached = cumulativeSeconds(path, plan.cells);
        for (std::size_t i = 1; i < path.waypoints.size(); ++i) {
            const Waypoint& a = path.waypoints[i - 1];
            const Waypoint& b = path.waypoints[i];
            const double segment = std::hypot(b.x - a.x, b.y - a.y);
            length += segment;
            for (const PathPause& pause : path.pauses)
                time += pause.waypoint == i - 1 ? pause.seconds : 0.0;
            time += segment / 2.0 / a.speedMetresPerSecond + segment / 2.0 / b.speedMetresPerSecond +
                    turnSecondsAt(path, i - 1, plan.cells);
            if (std::abs(reached[i] - time) > 1e-6 * std::max(1.0, time))
                violations.push_back(text("robot " + std::to_string(path.robot) +
                                              " cumulative time wrong at waypoint " + std::to_string(i),
                                          reached[i], time));
        }
        if (std::abs(length - path.lengthMetres) > 1e-6 * std::max(1.0, length))
            violations.push_back(
                text("robot " + std::to_string(path.robot) + " length", path.lengthMetres, length));
        if (std::abs(time - path.timeSeconds) > 1e-6 * std::max(1.0, time))
            violations.push_back(
                text("robot " + std::to_string(path.robot) + " time", path.timeSeconds, time));
        makespan = std::max(makespan, time);
    }
    const PlanMetrics& metrics = plan.metrics;
    if (std::abs(metrics.makespanSeconds - makespan) > 1e-6 * std::max(1.0, makespan))
        violations.push_back(text("makespan", metrics.makespanSeconds, makespan));
    double lowerBound = plan.paths.empty() ? 0.0
                                           : std::max(totalTravel / static_cast<double>(plan.paths.size()),
                                                      connectedPartsLowerBound(plan));
    if (std::any_of(plan.robotSpeeds.begin(), plan.robotSpeeds.end(),
                    [](double speed) { return speed > 0.0; }))
        lowerBound = ownSpeedsLowerBound(plan);
    // A detection plan's bound counts the passes its targets need instead of every sub-cell's; it must
    // still hold.
    if (const DetectionLayer* detection = detectionLayerOf(plan);
        detection != nullptr && !plan.paths.empty()) {
        double turning = 0.0;
        int turns = 0;
        for (const CoveragePath& path : plan.paths) {
            turning += path.turnSeconds;
            turns += path.turns;
        }
        lowerBound = (detection->summary().travelSecondsNoPlanBeats(turns, plan.paths.size()) + turning) /
                     static_cast<double>(plan.paths.size());
        if (makespan < lowerBound * (1.0 - 1e-9))
            violations.push_back(text("makespan beats the detection lower bound", makespan, lowerBound));
    }
    // On batteries the busiest robot also charges between the sorties its share takes at least; the trips
    // out to the work may raise the bound further, never above what a plan flies.
    const SortieLayer* sorties = sortieLayerOf(plan);
    if (sorties != nullptr && !sorties->robots().empty()) {
        double longest = 0.0;
        double shortestCharge = std::numeric_limits<double>::infinity();
        for (const RobotSorties& robot : sorties->robots()) {
            longest = std::max(longest, robot.enduranceSeconds);
            shortestCharge = std::min(shortestCharge, robot.rechargeSeconds);
        }
        const auto flights = static_cast<int>(std::ceil(lowerBound / longest));
        if (flights > 1)
            lowerBound += (flights - 1) * shortestCharge;
    }
    const bool tripsPriced = sorties != nullptr && !sorties->robots().empty();
    if (tripsPriced && metrics.lowerBoundSeconds < lowerBound * (1.0 - 1e-6))
        violations.push_back(text("lower bound below its charges", metrics.lowerBoundSeconds, lowerBound));
    else if (tripsPriced && metrics.lowerBoundSeconds > makespan * (1.0 + 1e-6))
        violations.push_back(text("lower bound above the makespan", metrics.lowerBoundSeconds, makespan));
    else if (!tripsPriced &&
             std::abs(metrics.lowerBoundSeconds - lowerBound) > 1e-6 * std::max(1.0, lowerBound))
        violations.push_back(text("lower bound", metrics.lowerBoundSeconds, lowerBound));
    const double bound = tripsPriced ? metrics.lowerBoundSeconds : lowerBound;
    if (bound > 0 && std::abs(metrics.ratio - makespan / bound) > 1e-9)
        violations.push_back(text("ratio", metrics.ratio, makespan / bound));
    return violations;
}

namespace {

// A sortie's travel and turning, recounted from its waypoints.
double sortieSecondsOf(const CoveragePath& path, const Sortie& sortie, const CellGraph& cells) {
    double seconds = 0.0;
    for (std::size_t i = sortie.firstWaypoint + 1; i <= sortie.lastWaypoint; ++i) {
        const Waypoint& a = path.waypoints[i - 1];
        const Waypoint& b = path.waypoints[i];
        const double segment = std::hypot(b.x - a.x, b.y - a.y);
        seconds += segment / 2.0 / a.speedMetresPerSecond + segment / 2.0 / b.speedMetresPerSecond +
                   turnSecondsAt(path, i - 1, cells);
    }
    return seconds;
}

std::vector<std::string> checkRobotSorties(const Plan& plan, const RobotSorties& robot) {
    std::vector<std::string> violations;
    const std::string who = "robot " + std::to_string(robot.robot);
    const CoveragePath& path = plan.paths[static_cast<std::size_t>(robot.robot)];
    if (robot.sorties.empty() || robot.sorties.front().firstWaypoint != 0 ||
        robot.sorties.back().lastWaypoint + 1 != path.waypoints.size())
        return {who + " sorties do not span its path"};
    if (path.pauses.size() != robot.sorties.size() - 1)
        violations.push_back(who + " charges " + std::to_string(path.pauses.size()) + " times in " +
                             std::to_string(robot.sorties.size()) + " sorties");
    for (std::size_t j = 0; j < robot.sorties.size(); ++j) {
        const Sortie& sortie = robot.sorties[j];
        const std::string which = who + " sortie " + std::to_string(j + 1);
        if (j > 0 && sortie.firstWaypoint != robot.sorties[j - 1].lastWaypoint)
            violations.push_back(which + " does not begin where the one before ended");
        for (const std::size_t end : {sortie.firstWaypoint, sortie.lastWaypoint}) {
            const Waypoint& point = path.waypoints[end];
            if (std::hypot(point.x - robot.charger.x, point.y - robot.charger.y) > 1e-6)
                violations.push_back(
                    text(which + " has an end away from the charger", point.x, robot.charger.x));
        }
        const double seconds = sortieSecondsOf(path, sortie, plan.cells);
        if (seconds > robot.enduranceSeconds * (1.0 + 1e-9))
            violations.push_back(text(which + " outlasts the battery", seconds, robot.enduranceSeconds));
        if (j + 1 < robot.sorties.size() &&
            (j >= path.pauses.size() || path.pauses[j].waypoint != sortie.lastWaypoint ||
             path.pauses[j].seconds != robot.rechargeSeconds))
            violations.push_back(which + " is not followed by a charge");
    }
    for (const int cell : robot.outOfRangeCells)
        if (plan.regions.robotOfCell[static_cast<std::size_t>(cell)] >= 0)
            violations.push_back(who + " leaves cell " + std::to_string(cell) +
                                 " out of range, yet it is covered");
    return violations;
}

} // namespace

// Every sortie starts and ends at its robot's charger, lasts no longer than the battery, and is followed by
// a charge; together they make the path.
std::vector<std::string> checkSorties(const Plan& plan) {
    const SortieLayer* layer = sortieLayerOf(plan);
    if (layer == nullptr)
        return {};
    if (layer->robots().size() != plan.paths.size())
        return {"sorties are given for " + std::to_string(layer->robots().size()) + " of " +
                std::to_string(plan.paths.size()) + " robots"};
    std::vector<std::string> violations;
    for (const RobotSorties& robot : layer->robots()) {
        const auto found = checkRobotSorties(plan, robot);
        violations.insert(violations.end(), found.begin(), found.end());
    }
    return violations;
}

namespace {

// The integral from 0 to x >= 0 of the sensor profile: p0 to half the field of view, then down to 0 at it.
double profileIntegral(double p0, double fieldOfView, double x) {
    const double half = fieldOfView / 2.0;
    if (x <= half)
        return p0 * x;
    const double y = std::min(x, fieldOfView);
    return p0 * half + p0 / half * (fieldOfView * (y - half) - (y * y - half * half) / 2.0);
}

// The profile's exact mean over the lattice cell `offset` cells to the side of a pass.
double cellMean(double p0, double fieldOfView, double cellSize, int offset) {
    const int k = std::abs(offset);
    if (k == 0)
        return 2.0 * profileIntegral(p0, fieldOfView, cellSize / 2.0) / cellSize;
    return (profileIntegral(p0, fieldOfView, (k + 0.5) * cellSize) -
            profileIntegral(p0, fieldOfView, (k - 0.5) * cellSize)) /
           cellSize;
}

struct RecountedDetection {
    std::vector<double> probability;
    std::vector<int> cellAt; // the cell whose free sub-cell is there, or -1
};

// Every pass of every path, recounted on the layer's lattice: straight through a centre one pass in the
// heading, at a turn one in each, at an end one in the heading of its step, a path on one centre both.
RecountedDetection recountDetection(const PlanningProblem& problem, const Plan& plan,
                                    const DetectionGrid& grid) {
    RecountedDetection recount;
    const auto size = static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows);
    recount.probability.assign(size, 0.0);
    recount.cellAt.assign(size, -1);
    auto centre = [&](int column, int row) {
        return MapPoint{grid.originX + (column + 0.5) * grid.cellSize,
                        grid.originY - (row + 0.5) * grid.cellSize};
    };
    double widest = 0.0;
    for (const LandCoverClass& landCover : problem.classes.classes())
        widest = std::max(widest, landCover.fieldOfViewMetres);
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            const MapPoint point = centre(column, row);
            const int cell = plan.cells.cellAt(point);
            if (cell >= 0 && plan.cells.cell(cell).isFree(plan.cells.cell(cell).subCellAt(point)))
                recount.cellAt[static_cast<std::size_t>(row * grid.columns + column)] = cell;
        }
    const double fallback = plan.parameters.real("detection_probability");
    const int reach = static_cast<int>(std::ceil(widest / grid.cellSize)) + 1;
    auto pass = [&](int column, int row, bool horizontal) {
        for (int offset = -reach; offset <= reach; ++offset) {
            const int c = horizontal ? column : column + offset;
            const int r = horizontal ? row + offset : row;
            if (c < 0 || r < 0 || c >= grid.columns || r >= grid.rows)
                continue;
            const auto index = static_cast<std::size_t>(r * grid.columns + c);
            if (recount.cellAt[index] < 0)
                continue;
            const LandCoverClass* landCover =
                problem.classes.find(plan.cells.cell(recount.cellAt[index]).classValue);
            const double chance = cellMean(landCover->detectionProbability.value_or(fallback),
                                           landCover->fieldOfViewMetres, grid.cellSize, offset);
            recount.probability[index] += (1.0 - recount.probability[index]) * chance;
        }
    };
    for (const CoveragePath& path : plan.paths) {
        std::vector<std::pair<int, int>> centres;
        for (const Waypoint& waypoint : path.waypoints) {
            const int column = static_cast<int>(std::floor((waypoint.x - grid.originX) / grid.cellSize));
            const int row = static_cast<int>(std::floor((grid.originY - waypoint.y) / grid.cellSize));
            const MapPoint at = centre(column, row);
            if (std::hypot(at.x - waypoint.x, at.y - waypoint.y) > 1e-6 * grid.cellSize)
                continue;
            if (centres.empty() || centres.back() != std::make_pair(column, row))
                centres.emplace_back(column, row);
        }
        for (std::size_t i = 0; i < centres.size(); ++i) {
            std::set<bool> headings; // true: east-west
            if (i > 0)
                headings.insert(centres[i - 1].second == centres[i].second);
            if (i + 1 < centres.size())
                headings.insert(centres[i + 1].second == centres[i].second);
            if (centres.size() == 1)
                headings = {true, false};
            for (const bool horizontal : headings)
                pass(centres[i].first, centres[i].second, horizontal);
        }
    }
    return recount;
}

} // namespace

std::vector<std::string> checkDetection(const PlanningProblem& problem, const Plan& plan) {
    const DetectionLayer* layer = detectionLayerOf(plan);
    if (layer == nullptr)
        return {};
    std::vector<std::string> violations;
    const DetectionGrid& grid = layer->grid();
    const RecountedDetection recount = recountDetection(problem, plan, grid);
    const double required = layer->summary().requiredProbability;
    for (std::size_t index = 0; index < recount.probability.size(); ++index) {
        const std::string where = "detection cell " + std::to_string(index);
        const int cell = recount.cellAt[index];
        if (cell < 0) {
            if (!std::isnan(grid.probability[index]) || !std::isnan(grid.required[index]))
                violations.push_back(where + " has values off the free sub-cells");
            continue;
        }
        const bool covered = plan.regions.robotOfCell[static_cast<std::size_t>(cell)] >= 0;
        if (covered != !std::isnan(grid.probability[index]))
            violations.push_back(where +
                                 " has a probability where no robot covers it, or none where one does");
        if (covered && std::abs(grid.probability[index] - recount.probability[index]) > 1e-4)
            violations.push_back(
                text(where + " probability", grid.probability[index], recount.probability[index]));
        if (covered != !std::isnan(grid.required[index]))
            violations.push_back(where + " is a target where no robot covers it, or the reverse");
        if (covered && grid.required[index] > 0.0F && recount.probability[index] < required - 1e-6)
            violations.push_back(
                text(where + " stays below the required probability", recount.probability[index], required));
    }
    if (violations.size() > 10)
        violations.resize(10);
    return violations;
}

std::vector<std::string> checkAllInvariants(const PlanningProblem& problem, const Plan& plan,
                                            const PlannerPromises& promises) {
    std::vector<std::string> all;
    for (auto&& part : {checkCells(plan), checkRegions(plan, promises), checkPaths(problem, plan, promises),
                        checkTimes(plan), checkSorties(plan), checkDetection(problem, plan)})
        all.insert(all.end(), part.begin(), part.end());
    return all;
}

std::vector<std::string> checkQuadTreeTiling(const PlanningProblem& problem, const QuadTree& tree) {
    std::vector<std::string> violations;
    const int bottom = tree.levels;
    const long long columns = tree.columnsAt(bottom);
    const long long rows = tree.rowsAt(bottom);
    std::vector<unsigned char> covered(static_cast<std::size_t>(columns * rows), 0);
    for (std::size_t index = 0; index < tree.cells.size(); ++index) {
        const QuadCell& cell = tree.cells[index];
        if (cell.state == CellState::Auxiliary) {
            if (cell.firstChild < 0 || static_cast<std::size_t>(cell.firstChild) + 4 > tree.cells.size())
                violations.push_back("auxiliary cell " + std::to_string(index) + " lacks its children");
            continue;
        }
        const int span = 1 << (bottom - cell.level);
        for (long long r = static_cast<long long>(cell.row) * span;
             r < static_cast<long long>(cell.row + 1) * span; ++r)
            for (long long c = static_cast<long long>(cell.column) * span;
                 c < static_cast<long long>(cell.column + 1) * span; ++c)
                ++covered[static_cast<std::size_t>(r * columns + c)];
        if (cell.state == CellState::Active &&
            (cell.activeIndex < 0 ||
             tree.activeCells[static_cast<std::size_t>(cell.activeIndex)] != static_cast<int>(index)))
            violations.push_back("active cell " + std::to_string(index) +
                                 " is not listed under its active index");
    }
    for (std::size_t i = 0; i < covered.size(); ++i)
        if (covered[i] != 1) {
            violations.push_back("bottom position " + std::to_string(i) + " is covered by " +
                                 std::to_string(covered[i]) + " leaves");
            break;
        }
    const ParameterValue* purity = problem.planner.parameters.find("purity_tolerance");
    if (purity != nullptr && std::get<double>(*purity) != 0.0)
        return violations;
    std::map<std::int32_t, double> rounded;
    for (const auto& entry : tree.roundedFieldsOfView)
        rounded[entry.classValue] = entry.roundedMetres;
    const ClassGrid& grid = problem.grid;
    for (int cellIndex : tree.activeCells) {
        const QuadCell& cell = tree.cells[static_cast<std::size_t>(cellIndex)];
        if (cell.level == bottom)
            continue;
        const int firstColumn =
            std::max(0, static_cast<int>(std::ceil((cell.minX - grid.originX) / grid.pixelWidth - 0.5)));
        const int lastColumn = std::min(
            grid.columns, static_cast<int>(std::ceil((cell.maxX() - grid.originX) / grid.pixelWidth - 0.5)));
        const int firstRow =
            std::max(0, static_cast<int>(std::ceil((grid.originY - cell.maxY()) / grid.pixelHeight - 0.5)));
        const int lastRow = std::min(
            grid.rows, static_cast<int>(std::ceil((grid.originY - cell.minY) / grid.pixelHeight - 0.5)));
        for (int r = firstRow; r < lastRow; ++r) {
            for (int c = firstColumn; c < lastColumn; ++c) {
                const auto found = rounded.find(grid.valueAt(c, r));
                if (grid.isOutside(c, r) || found == rounded.end() ||
                    found->second < cell.fieldOfView() - 1e-9) {
                    violations.push_back("active cell " + std::to_string(cellIndex) + " at level " +
                                         std::to_string(cell.level) + " holds pixel (" + std::to_string(c) +
                                         ", " + std::to_string(r) + ") that needs a smaller cell");
                    r = lastRow;
                    break;
                }
            }
        }
    }
    return violations;
}

std::string describe(const std::vector<std::string>& violations, std::size_t limit) {
    std::string out;
    for (std::size_t i = 0; i < violations.size() && i < limit; ++i)
        out += violations[i] + "\n";
    if (violations.size() > limit)
        out += "... and " + std::to_string(violations.size() - limit) + " more\n";
    return out;
}

bool regionIsConnected(const CellGraph& graph, const std::vector<int>& owner, int region) {
    const auto first = std::find(owner.begin(), owner.end(), region);
    if (first == owner.end())
        return false;
    const auto members = static_cast<std::size_t>(std::count(owner.begin(), owner.end(), region));
    std::vector<char> seen(owner.size(), 0);
    std::vector<int> queue{static_cast<int>(first - owner.begin())};
    seen[static_cast<std::size_t>(queue.front())] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int next : graph.neighbours(queue[head]))
            if (owner[static_cast<std::size_t>(next)] == region &&
                seen[static_cast<std::size_t>(next)] == 0) {
                seen[static_cast<std::size_t>(next)] = 1;
                queue.push_back(next);
            }
    return queue.size() == members;
}

} // namespace mcpp::test
