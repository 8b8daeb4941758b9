#pragma once

#include "core/model/CellGraph.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
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
    // 8 bytes: the second end's number shares a word with the side and the straight mark, so regions hold
    // fewer than mostNodes cells (far more than any memory this planner is let use).
    struct Edge {
        int first = 0;
        int second : 29 = 0;
        CellSide sideOfFirst : 2 = CellSide::East; // where `second` lies, seen from `first`
        bool straight : 1 = false;
    };
    static_assert(sizeof(Edge) == 8);
    static constexpr std::size_t mostNodes = std::size_t{1} << 28U;
    struct Incidence {
        int edge = 0;
        int other = 0;
        CellSide side = CellSide::East;
    };
    // A node's incidences, kept as edge numbers (4 bytes where a whole incidence takes 12: on a region of
    // tens of millions of cells, hundreds of megabytes) and read back whole from the edges.
    class IncidenceRange {
      public:
        class Iterator {
          public:
            Iterator(const Edge* edges, const int* at, int node) : edges_(edges), at_(at), node_(node) {}
            [[nodiscard]] Incidence operator*() const {
                const Edge& edge = edges_[*at_];
                return edge.first == node_ ? Incidence{*at_, edge.second, edge.sideOfFirst}
                                           : Incidence{*at_, edge.first, oppositeSide(edge.sideOfFirst)};
            }
            Iterator& operator++() {
                ++at_;
                return *this;
            }
            [[nodiscard]] bool operator==(const Iterator& other) const { return at_ == other.at_; }

          private:
            const Edge* edges_;
            const int* at_;
            int node_;
        };
        IncidenceRange(const Edge* edges, const int* begin, const int* end, int node)
            : edges_(edges), begin_(begin), end_(end), node_(node) {}
        [[nodiscard]] Iterator begin() const { return {edges_, begin_, node_}; }
        [[nodiscard]] Iterator end() const { return {edges_, end_, node_}; }

      private:
        const Edge* edges_;
        const int* begin_;
        const int* end_;
        int node_;
    };

    // localIndex: the region's position of every graph cell, -1 outside (a CellIndexScope).
    template <typename LocalIndex>
    RegionAdjacency(const CellGraph& graph, const std::vector<int>& cells, const LocalIndex& localIndex) {
        // Half the cells' neighbours, at most one edge each: a region of millions of cells would otherwise
        // grow its edges through a dozen copies, each into memory never touched before.
        if (cells.size() >= mostNodes)
            throw std::length_error("a region of " + std::to_string(cells.size()) +
                                    " cells is more than a region's adjacency can number");
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
    [[nodiscard]] IncidenceRange incident(int node) const {
        const int* edgeNumbers = incidences_.data();
        return {edges_.data(), edgeNumbers + offsets_[static_cast<std::size_t>(node)],
                edgeNumbers + offsets_[static_cast<std::size_t>(node) + 1], node};
    }

  private:
    void add(const CellRecord& from, const CellRecord& to, int a, int b);
    void index(std::size_t nodes);

    std::vector<Edge> edges_;
    std::vector<int> offsets_;
    std::vector<int> incidences_; // edge numbers, node by node
};

} // namespace mcpp
