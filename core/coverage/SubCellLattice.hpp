#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <optional>
#include <vector>

namespace mcpp {

// The sub-cells of some cells of a single-level grid (every cell of span 1) as a lattice of squares of side
// Fd_min, the robot's swath: where it may step, and the shortest way between two of them.
class SubCellLattice {
  public:
    struct Position {
        int x = 0; // lattice column, 0 at the west
        int y = 0; // lattice row, 0 at the north
        friend bool operator==(const Position&, const Position&) = default;
    };

    SubCellLattice(const CellGraph& graph, const std::vector<int>& cells);

    // A free sub-cell of one of the lattice's cells.
    [[nodiscard]] bool isFree(Position position) const;
    // The sub-cell a point of one of the lattice's cells lies in.
    [[nodiscard]] std::optional<Position> at(MapPoint point) const;
    [[nodiscard]] Waypoint waypointAt(Position position) const;
    // The free sub-cells reachable from `start` by steps to a side neighbour.
    [[nodiscard]] std::vector<Position> reachableFrom(Position start) const;
    // The sub-cells after `from` up to and including `to` on a shortest way through free sub-cells; empty
    // when there is none.
    [[nodiscard]] std::vector<Position> shortestWay(Position from, Position to) const;

  private:
    [[nodiscard]] int cellAt(Position position) const;
    [[nodiscard]] std::size_t index(Position position) const;

    const CellGraph& graph_;
    int width_ = 0;
    int height_ = 0;
    std::vector<int> cellOfPlacement_;  // by bottom-grid position; -1 where no lattice cell lies
    mutable std::vector<int> cameFrom_; // scratch for the searches, by lattice index
    mutable std::vector<std::size_t> touched_;
};

} // namespace mcpp
