#include "core/coverage/ChargerTransit.hpp"

#include "core/coverage/PathClock.hpp"
#include "core/coverage/ReturnTree.hpp"
#include "core/coverage/SubCellNodes.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/StartPointCheck.hpp"

#include <cmath>
#include <numeric>

namespace mcpp {
namespace {

// A node's waypoint moved to a point of its sub-cell (the start), keeping its land cover.
Waypoint pointIn(const SubCellNodes& nodes, int node, MapPoint point) {
    Waypoint waypoint = nodes.waypoint(node);
    waypoint.x = point.x;
    waypoint.y = point.y;
    return waypoint;
}

bool samePlace(const Waypoint& a, const Waypoint& b) {
    return std::hypot(a.x - b.x, a.y - b.y) <= 1e-9;
}

std::unique_ptr<SubCellNodes> everySubCell(const CellGraph& graph) {
    std::vector<int> everyCell(graph.size());
    std::iota(everyCell.begin(), everyCell.end(), 0);
    return std::make_unique<SubCellNodes>(graph, everyCell);
}

} // namespace

ChargerTransit::ChargerTransit(const CellGraph& graph) : graph_(graph), nodes_(everySubCell(graph)) {}

ChargerTransit::~ChargerTransit() = default;

std::vector<Waypoint> ChargerTransit::way(int robot, MapPoint start, int startCell, MapPoint charger,
                                          int chargerCell, double enduranceSeconds) const {
    const SubCellNodes& nodes = *nodes_;
    const int root = nodes.startNode(robot, chargerCell, charger);
    const int from = nodes.startNode(robot, startCell, start);
    const ReturnTree tree(nodes, graph_, std::vector<char>(static_cast<std::size_t>(nodes.size()), 1), root,
                          charger);
    const std::string who = "robot " + std::to_string(robot + 1);
    if (!tree.reaches(from))
        throw PlanningError(PlanningError::Kind::InvalidParameter,
                            who + " cannot reach its charger " + describePoint(charger) + " from its start " +
                                describePoint(start) + ": no passable way joins them");
    std::vector<Waypoint> points{pointIn(nodes, from, start)};
    const auto add = [&](const Waypoint& point) {
        if (!samePlace(points.back(), point))
            points.push_back(point);
    };
    add(nodes.waypoint(from));
    for (const int node : tree.wayHome(from))
        add(nodes.waypoint(node));
    add(tree.charger());
    PathClock clock(graph_);
    for (const Waypoint& point : points)
        clock.append(point);
    if (clock.elapsed() > enduranceSeconds)
        throw PlanningError(
            PlanningError::Kind::InvalidParameter,
            who + " needs " + formatDuration(clock.elapsed()) +
                " to fly from its start to its charger, more than one charge of its battery (" +
                formatDuration(enduranceSeconds) + ")");
    return points;
}

} // namespace mcpp
