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
    // A node's incidences in increasing edge number, read back whole from the edges. Edges are numbered
    // by their first end, so those a node is the first end of are one range and only those it is the
    // second end of are listed: 16 bytes a node where a list of all took 20 (hundreds of megabytes on a
    // region of tens of millions of cells). Those it is the second end of come first, their first ends
    // being lower.
    class IncidenceRange {
      public:
        class Iterator {
          public:
            Iterator(const Edge* edges, const int* listed, const int* listedEnd, int ranged)
                : edges_(edges), listed_(listed), listedEnd_(listedEnd), ranged_(ranged) {}
            [[nodiscard]] Incidence operator*() const {
                if (listed_ != listedEnd_) {
                    const Edge& edge = edges_[*listed_];
                    return {*listed_, edge.first, oppositeSide(edge.sideOfFirst)};
                }
                const Edge& edge = edges_[ranged_];
                return {ranged_, edge.second, edge.sideOfFirst};
            }
            Iterator& operator++() {
                if (listed_ != listedEnd_)
                    ++listed_;
                else
                    ++ranged_;
                return *this;
            }
            [[nodiscard]] bool operator==(const Iterator& other) const {
                return listed_ == other.listed_ && ranged_ == other.ranged_;
            }

          private:
            const Edge* edges_;
            const int* listed_; // the edges the node is the second end of, then listedEnd_
            const int* listedEnd_;
            int ranged_; // then the edges it is the first end of
        };
        IncidenceRange(const Edge* edges, const int* listed, const int* listedEnd, int firstEdge, int endEdge)
            : edges_(edges), listed_(listed), listedEnd_(listedEnd), firstEdge_(firstEdge),
              endEdge_(endEdge) {}
        [[nodiscard]] Iterator begin() const { return {edges_, listed_, listedEnd_, firstEdge_}; }
        [[nodiscard]] Iterator end() const { return {edges_, listedEnd_, listedEnd_, endEdge_}; }

      private:
        const Edge* edges_;
        const int* listed_;
        const int* listedEnd_;
        int firstEdge_;
        int endEdge_;
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
        firstEdges_.reserve(cells.size() + 1);
        for (std::size_t a = 0; a < cells.size(); ++a) {
            firstEdges_.push_back(static_cast<int>(edges_.size()));
            for (int neighbour : graph.neighbours(cells[a])) {
                const int b = localIndex[neighbour];
                if (b > static_cast<int>(a))
                    add(graph.record(cells[a]), graph.record(neighbour), static_cast<int>(a), b);
            }
        }
        firstEdges_.push_back(static_cast<int>(edges_.size()));
        index(cells.size());
    }

    [[nodiscard]] std::size_t nodeCount() const { return firstEdges_.empty() ? 0 : firstEdges_.size() - 1; }
    [[nodiscard]] const std::vector<Edge>& edges() const { return edges_; }
    [[nodiscard]] IncidenceRange incident(int node) const {
        const auto at = static_cast<std::size_t>(node);
        const int* listed = secondEnds_.data();
        return {edges_.data(), listed + secondOffsets_[at], listed + secondOffsets_[at + 1], firstEdges_[at],
                firstEdges_[at + 1]};
    }

  private:
    void add(const CellRecord& from, const CellRecord& to, int a, int b);
    void index(std::size_t nodes);

    std::vector<Edge> edges_;        // in increasing first end
    std::vector<int> firstEdges_;    // node i is the first end of edges firstEdges_[i] .. [i + 1]
    std::vector<int> secondOffsets_; // and the second end of secondEnds_[secondOffsets_[i] .. [i + 1]]
    std::vector<int> secondEnds_;    // edge numbers, node by node
};

} // namespace mcpp
