#include "core/coverage/ChargerTransit.hpp"

#include "core/coverage/PathClock.hpp"
#include "core/coverage/ReturnTree.hpp"
#include "core/coverage/SubCellNodes.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/StartPointCheck.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mcpp {
namespace {

// A node's waypoint moved to a point of its sub-cell (the start), keeping its cell and speed.
Waypoint pointIn(const SubCellNodes& nodes, int node, MapPoint point) {
    Waypoint waypoint = nodes.waypoint(node);
    waypoint.x = point.x;
    waypoint.y = point.y;
    return waypoint;
}

bool samePlace(const Waypoint& a, const Waypoint& b) {
    return std::hypot(a.x - b.x, a.y - b.y) <= 1e-9;
}

// The cells that touch the box around the start and the charger, widened by half its larger side (at least
// two cells): where the way between them almost always lies, a small part of a large map.
std::vector<int> cellsAround(const CellGraph& graph, MapPoint start, MapPoint charger) {
    const double margin =
        std::max(0.5 * std::max(std::abs(start.x - charger.x), std::abs(start.y - charger.y)),
                 2.0 * graph.frame().bottomCellSize);
    const double west = std::min(start.x, charger.x) - margin;
    const double east = std::max(start.x, charger.x) + margin;
    const double south = std::min(start.y, charger.y) - margin;
    const double north = std::max(start.y, charger.y) + margin;
    std::vector<int> cells;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        if (cell.maxX() >= west && cell.minX <= east && cell.maxY() >= south && cell.minY <= north)
            cells.push_back(static_cast<int>(id));
    }
    return cells;
}

} // namespace

ChargerTransit::ChargerTransit(const CellGraph& graph) : graph_(graph) {}

ChargerTransit::~ChargerTransit() = default;

std::vector<Waypoint> ChargerTransit::way(int robot, MapPoint start, int startCell, MapPoint charger,
                                          int chargerCell, double enduranceSeconds, double ownSpeed) const {
    // Near the two first; over the whole map (made once for the cells' speeds) when no way joins them there.
    std::vector<Waypoint> points =
        wayThrough(SubCellNodes(graph_, cellsAround(graph_, start, charger), ownSpeed), robot, start,
                   startCell, charger, chargerCell);
    if (points.empty()) {
        std::vector<int> everyCell(graph_.size());
        std::iota(everyCell.begin(), everyCell.end(), 0);
        if (ownSpeed > 0.0) {
            points = wayThrough(SubCellNodes(graph_, everyCell, ownSpeed), robot, start, startCell, charger,
                                chargerCell);
        } else {
            if (!everySubCell_)
                everySubCell_ = std::make_unique<SubCellNodes>(graph_, everyCell);
            points = wayThrough(*everySubCell_, robot, start, startCell, charger, chargerCell);
        }
    }
    const std::string who = "robot " + std::to_string(robot + 1);
    if (points.empty())
        throw PlanningError(PlanningError::Kind::InvalidParameter,
                            who + " cannot reach its charger " + describePoint(charger) + " from its start " +
                                describePoint(start) + ": no passable way joins them");
    PathClock clock(graph_);
    for (const Waypoint& point : points)
        clock.append(point);
    if (clock.elapsed() > enduranceSeconds)
        throw PlanningError(
            PlanningError::Kind::InvalidParameter,
            who + " needs " + formatDuration(clock.elapsed()) +
                " to travel from its start to its charger, more than one charge of its battery (" +
                formatDuration(enduranceSeconds) + ")");
    return points;
}

std::vector<Waypoint> ChargerTransit::wayThrough(const SubCellNodes& nodes, int robot, MapPoint start,
                                                 int startCell, MapPoint charger, int chargerCell) const {
    const int root = nodes.startNode(robot, chargerCell, charger);
    const int from = nodes.startNode(robot, startCell, start);
    const ReturnTree tree(nodes, graph_, std::vector<char>(static_cast<std::size_t>(nodes.size()), 1), root,
                          charger);
    if (!tree.reaches(from))
        return {};
    std::vector<Waypoint> points{pointIn(nodes, from, start)};
    const auto add = [&](const Waypoint& point) {
        if (!samePlace(points.back(), point))
            points.push_back(point);
    };
    add(nodes.waypoint(from));
    for (const int node : tree.wayHome(from))
        add(nodes.waypoint(node));
    add(tree.charger());
    return points;
}

} // namespace mcpp
