#include "core/planners/PlanningRun.hpp"

#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/StartPointCheck.hpp"

#include <cmath>
#include <limits>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

std::string blockedShare(const ParameterValues& parameters) {
    if (!parameters.has("blocked_threshold"))
        return "mostly";
    const long percent = std::lround(parameters.real("blocked_threshold") * 100.0);
    return "more than " + std::to_string(percent) + "%";
}

// Why the start lies on no cell of the graph: the pixel under it, or the cell rule that dropped its cell.
StartPointProblem whyNoCell(const PlanningProblem& problem, const ParameterValues& parameters, MapPoint start,
                            const std::string& leftOutBecause) {
    if (auto problemAtPixel = startPointProblem(problem.grid, problem.classes, start))
        return *problemAtPixel;
    const std::string reason = leftOutBecause.empty()
                                   ? "is " + blockedShare(parameters) + " obstacle or outside the area"
                                   : leftOutBecause;
    return {Kind::StartOnObstacle, describePoint(start) + " is in a cell that " + reason};
}

int nearestFreeCell(const CellGraph& graph, const std::vector<int>& ownerOfCell, MapPoint point) {
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t candidate = 0; candidate < graph.size(); ++candidate) {
        if (ownerOfCell[candidate] >= 0)
            continue;
        const Cell& cell = graph.cell(static_cast<int>(candidate));
        const double d = std::hypot(cell.centreX() - point.x, cell.centreY() - point.y);
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<int>(candidate);
        }
    }
    return best;
}

} // namespace

// How far one flight of a robot reaches out and back; infinite where its trips are not counted.
double PlanningRun::reachMetres(std::size_t robot) const {
    return robot < problem_.robotFlights.size() ? problem_.robotFlights[robot].reachMetres()
                                                : std::numeric_limits<double>::infinity();
}

// An aircraft takes off where it stands and flies to its path.
void PlanningRun::takeOffAt(int robot, MapPoint given, MapPoint pathStart, const std::string& why) {
    const double metres = std::hypot(pathStart.x - given.x, pathStart.y - given.y);
    const auto index = static_cast<std::size_t>(robot);
    takeOffs_.resize(starts_.size());
    takeOffs_[index] = given;
    // The problem's detail begins with the point: "(x, y) is not in the task area: ...".
    const std::string point = describePoint(given);
    const std::string what =
        why.rfind(point, 0) == 0 ? why.substr(point.size()) : " is not on a free cell (" + why + ")";
    const bool tripsCounted =
        index < problem_.robotFlights.size() && problem_.robotFlights[index].makesTrips();
    addIssue(IssueSeverity::Information, "take-off-outside",
             "robot " + std::to_string(robot + 1) + " takes off at its start " + point + ", which" + what +
                 "; it flies " + formatDistance(metres) + " to the nearest free cell's centre " +
                 describePoint(pathStart) + ", where its path begins" +
                 (tripsCounted ? ", and each flight's trip from its start and back is counted" : ""));
}

// Why a start cannot have its own cell: on none, or on one an earlier robot holds.
std::optional<StartPointProblem> PlanningRun::startCellProblem(MapPoint start, int cell,
                                                               const std::vector<int>& ownerOfCell,
                                                               const std::string& leftOutBecause) const {
    const CellGraph& graph = plan_.cells;
    if (cell < 0)
        return whyNoCell(problem_, parameters_, start, leftOutBecause);
    const int owner = ownerOfCell[static_cast<std::size_t>(cell)];
    if (owner < 0)
        return std::nullopt;
    return StartPointProblem{Kind::StartsShareCell, describePoint(start) + " is in the same cell as robot " +
                                                        std::to_string(owner + 1) + "'s start (a cell " +
                                                        formatDistance(graph.cell(cell).size) + " across)"};
}

std::vector<int> PlanningRun::locateStarts(const std::string& leftOutBecause) {
    const CellGraph& graph = plan_.cells;
    if (graph.empty())
        throw PlanningError(Kind::NoPassableCell, "no cell of the map is passable: every smallest cell is " +
                                                      blockedShare(parameters_) +
                                                      " obstacle or outside the area");
    if (starts_.size() > graph.size())
        throw PlanningError(Kind::TooManyRobots, std::to_string(starts_.size()) + " robots but only " +
                                                     std::to_string(graph.size()) + " passable cells");
    for (std::size_t robot = 0; robot < starts_.size(); ++robot)
        if (!std::isfinite(starts_[robot].x) || !std::isfinite(starts_[robot].y))
            throw PlanningError::aboutStart(Kind::InvalidParameter, static_cast<int>(robot),
                                            describePoint(starts_[robot]) + " is not a number");
    // Robots standing on cells of their own hold them first: one moved or taking off must not take the
    // cell of a robot after it that stands there.
    std::vector<int> startCells(starts_.size(), -1);
    std::vector<int> ownerOfCell(graph.size(), -1);
    for (std::size_t robot = 0; robot < starts_.size(); ++robot) {
        const int cell = graph.cellAt(starts_[robot]);
        if (cell >= 0 && ownerOfCell[static_cast<std::size_t>(cell)] < 0) {
            ownerOfCell[static_cast<std::size_t>(cell)] = static_cast<int>(robot);
            startCells[robot] = cell;
        }
    }
    for (std::size_t robot = 0; robot < starts_.size(); ++robot)
        if (startCells[robot] < 0)
            startCells[robot] = placeBlockedStart(robot, ownerOfCell, leftOutBecause);
    return startCells;
}

// The cell of a robot whose start has none of its own: the nearest free one, where it takes off (a flying
// robot) or is moved to (snapping); else its start is refused.
int PlanningRun::placeBlockedStart(std::size_t robot, std::vector<int>& ownerOfCell,
                                   const std::string& leftOutBecause) {
    const CellGraph& graph = plan_.cells;
    const auto robotIndex = static_cast<int>(robot);
    MapPoint& start = starts_[robot];
    const StartPointProblem problem =
        *startCellProblem(start, graph.cellAt(start), ownerOfCell, leftOutBecause);
    const bool snap = parameters_.boolean("snap_starts_to_free_cells");
    bool takesOff =
        takeOffsAllowed_ && robotTakesOffThere(problem_.flyingRobots, robot, problem_.grid, start, problem);
    if (!snap && !takesOff)
        throw PlanningError::aboutStart(problem.kind, robotIndex,
                                        startRefusal(problem_.grid, problem_.classes, start, problem));
    const int cell = nearestFreeCell(graph, ownerOfCell, start);
    if (cell < 0)
        throw PlanningError::aboutStart(Kind::TooManyRobots, robotIndex,
                                        problem.detail + " and no free cell is left");
    const Cell& target = graph.cell(cell);
    const MapPoint given = start;
    start = {target.centreX(), target.centreY()};
    const double metres = std::hypot(start.x - given.x, start.y - given.y);
    // Beyond one flight's reach it cannot take off there: moved with a warning where snapping, else refused.
    if (takesOff && metres > reachMetres(robot)) {
        if (!snap)
            throw PlanningError::aboutStart(
                problem.kind, robotIndex,
                problem.detail + ", and its path would begin " + formatDistance(metres) +
                    " away, farther than one flight can go and come back (" +
                    formatDistance(reachMetres(robot)) +
                    " each way): start it nearer the area, or give it a longer flight time");
        takesOff = false;
    }
    if (takesOff)
        takeOffAt(robotIndex, given, start, problem.detail);
    else
        addIssue(IssueSeverity::Warning, "start-moved",
                 "robot " + std::to_string(robot + 1) + " start " + problem.detail + "; moved " +
                     formatDistance(metres) + " to the nearest free cell's centre " + describePoint(start));
    ownerOfCell[static_cast<std::size_t>(cell)] = robotIndex;
    return cell;
}

} // namespace mcpp
