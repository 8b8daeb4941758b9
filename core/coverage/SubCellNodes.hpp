#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <array>
#include <vector>

namespace mcpp {

// The free sub-cells of some cells of a single-level grid, numbered, each with its side neighbours: the
// places a grid walk steps between, one swath apart.
class SubCellNodes {
  public:
    // Side directions, counter-clockwise from east; opposite(d) = (d + 2) % 4.
    enum Direction : int { East = 0, North = 1, West = 2, South = 3 };
    static constexpr int none = -1;

    struct Node {
        Waypoint waypoint;                                    // the sub-cell centre, with its cell's speed
        std::array<int, 4> neighbour{none, none, none, none}; // by Direction
    };

    // ownSpeed: a robot's own speed over every class (PlanningProblem::robotSpeeds) its nodes carry instead
    // of their cells' speeds; 0 for the cells'.
    SubCellNodes(const CellGraph& graph, const std::vector<int>& cells, double ownSpeed = 0.0);

    [[nodiscard]] int size() const { return static_cast<int>(nodes_.size()); }
    [[nodiscard]] const Node& node(int index) const { return nodes_[static_cast<std::size_t>(index)]; }
    [[nodiscard]] const Waypoint& waypoint(int index) const { return node(index).waypoint; }
    [[nodiscard]] int neighbour(int index, int direction) const {
        return node(index).neighbour[static_cast<std::size_t>(direction)];
    }
    // The node of a free sub-cell of one of the cells, or none.
    [[nodiscard]] int at(int cell, SubCell subCell) const;
    // The node of `cell` nearest the point, or none when the cell has no free sub-cell here.
    [[nodiscard]] int nearestIn(int cell, MapPoint point) const;
    // Where robot `robot` starting at `start` in `cell` begins its walk; throws PlanningError when the cell
    // has no free sub-cell.
    [[nodiscard]] int startNode(int robot, int cell, MapPoint start) const;
    // The nodes of one of the cells, in SubCell order.
    [[nodiscard]] std::vector<int> ofCell(int cell) const;
    // Seconds to travel between two neighbouring nodes (half at each one's speed).
    [[nodiscard]] double stepSeconds(int from, int to) const;

  private:
    // The position of a cell among the sorted cells, or none.
    [[nodiscard]] int slotOf(int cell) const;

    std::vector<Node> nodes_;
    std::vector<int> cells_;         // the cells given, sorted
    std::vector<int> nodeOfSubCell_; // by 4 x slot + SubCell: the node, or none where the sub-cell is blocked
};

} // namespace mcpp
