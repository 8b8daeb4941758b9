#pragma once

#include "core/coverage/RegionAdjacency.hpp"
#include "core/model/CellGraph.hpp"

#include <vector>

namespace mcpp {

// The time a walk round a spanning tree spends stepping between cells of different sizes beyond their
// cells' travel (secondsBeyondCellTravel, as paths measure it). Going round a large cell, the walk passes
// each side from one corner sub-cell to the next; a smaller tree neighbour on that side is a detour in at its
// near sub-cell and out at its far one, and those steps run slantwise. With one of two half-side neighbours
// joined, the way back to the large cell's next corner is a diagonal of 1.4 times the straight step; with
// both joined, each step is within 6 % of it. The cost of a side therefore depends on which of its smaller
// neighbours the tree joins; it is charged to the larger cell of each pair (equal cells step straight). Two
// joined neighbours that do not touch are costed as one step, where the walk bridges through the cells
// between them.
class SizeChangeConnectors {
  public:
    // cells: the region's graph cells, in the adjacency's node order.
    SizeChangeConnectors(const CellGraph& graph, const std::vector<int>& cells,
                         const RegionAdjacency& adjacency);

    // The larger cell of an edge's two, whose side carries the edge's connector time; -1 for equal cells.
    [[nodiscard]] int largerEnd(int edge) const;
    // Seconds beyond its cells' travel that the walk spends on `side` of `node`, with the tree's edges
    // marked in `inTree`.
    [[nodiscard]] double sideSeconds(int node, CellSide side, const std::vector<char>& inTree) const;
    // How sideSeconds at the edge's larger end changes when the edge goes in or out of the tree.
    [[nodiscard]] double changeOnToggle(int edge, const std::vector<char>& inTree) const;
    // What a 90-degree turn costs in the node's cell (a small floor, so that turns still break ties when
    // they are free).
    [[nodiscard]] double turnSeconds(int node) const;

  private:
    struct Neighbour {
        double along = 0.0; // position in the walk's order
        int node = 0;
        int edge = 0;
    };

    // The smaller neighbours on a side joined in `inTree`, and the one by `alsoEdge` (-1: none), in the
    // walk's order, in a buffer the next call reuses.
    const std::vector<Neighbour>& smallerNeighbours(int node, CellSide side, const std::vector<char>& inTree,
                                                    int alsoEdge) const;
    // The side's seconds with `neighbours` joined, all but the one by `leftOutEdge` (-1: none).
    [[nodiscard]] double passSeconds(int node, CellSide side, const std::vector<Neighbour>& neighbours,
                                     int leftOutEdge) const;
    [[nodiscard]] Cell cellOf(int node) const { return graph_.cell(cells_[static_cast<std::size_t>(node)]); }
    // What the graph keeps of the cell, where its span is all that is asked: no square to work out.
    [[nodiscard]] const CellRecord& recordOf(int node) const {
        return graph_.record(cells_[static_cast<std::size_t>(node)]);
    }

    const CellGraph& graph_;
    const std::vector<int>& cells_;
    const RegionAdjacency& adjacency_;
    // By edge and by node: swaps ask for them at every edge of a cycle.
    std::vector<int> largerEnd_;
    std::vector<double> turnSeconds_;
    mutable std::vector<Neighbour> neighbours_; // smallerNeighbours' buffer: one tree's swaps, one thread
};

} // namespace mcpp
