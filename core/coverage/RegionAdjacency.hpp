#pragma once

#include "core/model/CellGraph.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace mcpp {

// The side of a cell a neighbour lies on.
enum class CellSide : std::uint8_t { East = 0, North = 1, West = 2, South = 3 };

[[nodiscard]] inline CellSide oppositeSide(CellSide side) {
    return static_cast<CellSide>((static_cast<unsigned>(side) + 2U) % 4U);
}

// The adjacencies between the cells of one region, numbered 0..n-1 in the order of the region's cell list,
// each with the side it leaves from. `straight` marks a pair of equal cells in one row or column: a walk
// can pass both without turning.
class RegionAdjacency {
  public:
    struct Edge {
        int first = 0;
        int second = 0;
        CellSide sideOfFirst = CellSide::East; // where `second` lies, seen from `first`
        bool straight = false;
    };
    struct Incidence {
        int edge = 0;
        int other = 0;
        CellSide side = CellSide::East;
    };

    // localIndex: the region's position of every graph cell, -1 outside (a CellIndexScope).
    template <typename LocalIndex>
    RegionAdjacency(const CellGraph& graph, const std::vector<int>& cells, const LocalIndex& localIndex) {
        // Half the cells' neighbours, at most one edge each: a region of millions of cells would otherwise
        // grow its edges through a dozen copies, each into memory never touched before.
        std::size_t neighbourEnds = 0;
        for (int cell : cells)
            neighbourEnds += graph.neighbours(cell).size();
        edges_.reserve(neighbourEnds / 2);
        for (std::size_t a = 0; a < cells.size(); ++a)
            for (int neighbour : graph.neighbours(cells[a])) {
                const int b = localIndex[neighbour];
                if (b > static_cast<int>(a))
                    add(graph.record(cells[a]), graph.record(neighbour), static_cast<int>(a), b);
            }
        index(cells.size());
    }

    [[nodiscard]] std::size_t nodeCount() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    [[nodiscard]] const std::vector<Edge>& edges() const { return edges_; }
    [[nodiscard]] std::span<const Incidence> incident(int node) const {
        const auto begin = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(node)]);
        const auto end = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(node) + 1]);
        return {incidences_.data() + begin, end - begin};
    }

  private:
    void add(const CellRecord& from, const CellRecord& to, int a, int b);
    void index(std::size_t nodes);

    std::vector<Edge> edges_;
    std::vector<int> offsets_;
    std::vector<Incidence> incidences_;
};

} // namespace mcpp
