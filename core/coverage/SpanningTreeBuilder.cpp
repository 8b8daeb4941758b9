#include "core/coverage/SpanningTreeBuilder.hpp"

#include "core/coverage/CellIndexScope.hpp"
#include "core/coverage/RegionAdjacency.hpp"
#include "core/coverage/SizeChangeConnectors.hpp"
#include "core/coverage/TurnMinimisingTree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

namespace mcpp {
namespace {

bool sideBySideEastWest(const Cell& from, const Cell& to) {
    const double tolerance = 1e-9 * from.size;
    return to.minX >= from.maxX() - tolerance || to.maxX() <= from.minX + tolerance;
}

// Angle of b's centre seen from a's, counter-clockwise from east, in [0, 2 pi).
double bearing(const Cell& a, const Cell& b) {
    const double angle = std::atan2(b.centreY() - a.centreY(), b.centreX() - a.centreX());
    return angle < 0.0 ? angle + 2.0 * std::numbers::pi : angle;
}

} // namespace

SpanningTree SpanningTreeBuilder::preferring(std::vector<int> cells, int rootCell,
                                             EdgeDirection preferred) const {
    std::vector<std::pair<int, int>> edges;
    int rootNode = 0;
    {
        const CellIndexScope local(index_, cells);
        const std::size_t count = cells.size();
        std::array<std::vector<std::pair<int, int>>, 2>
            buckets; // preferred direction first, in a fixed order
        for (std::size_t a = 0; a < count; ++a) {
            const Cell& from = graph_.cell(cells[a]);
            for (int neighbour : graph_.neighbours(cells[a])) {
                const int b = local[neighbour];
                if (b <= static_cast<int>(a))
                    continue;
                const bool eastWest = sideBySideEastWest(from, graph_.cell(neighbour));
                const std::size_t rank = eastWest == (preferred == EdgeDirection::EastWest) ? 0 : 1;
                buckets[rank].emplace_back(static_cast<int>(a), b);
            }
        }
        std::vector<int> root(count);
        std::iota(root.begin(), root.end(), 0);
        auto find = [&](int x) {
            while (root[static_cast<std::size_t>(x)] != x) {
                root[static_cast<std::size_t>(x)] =
                    root[static_cast<std::size_t>(root[static_cast<std::size_t>(x)])];
                x = root[static_cast<std::size_t>(x)];
            }
            return x;
        };
        edges.reserve(count);
        for (const auto& bucket : buckets) {
            for (const auto& [first, second] : bucket) {
                const int a = find(first);
                const int b = find(second);
                if (a == b)
                    continue;
                root[static_cast<std::size_t>(a)] = b;
                edges.emplace_back(first, second);
            }
        }
        rootNode = local[rootCell];
    } // the scope must clear the shared index before the cells move into the tree
    return SpanningTree(std::move(cells), rootNode, edges);
}

// The tree of the edges `edgesOf` picks over the region's adjacency (given the region's cells too), rooted
// at rootCell; nothing where it picks none.
template <typename EdgesOf>
std::optional<SpanningTree> SpanningTreeBuilder::treeOver(std::vector<int> cells, int rootCell,
                                                          EdgesOf edgesOf) const {
    std::optional<std::vector<std::pair<int, int>>> edges;
    int rootNode = 0;
    {
        const CellIndexScope local(index_, cells);
        const RegionAdjacency adjacency(graph_, cells, local);
        edges = edgesOf(adjacency, cells);
        rootNode = local[rootCell];
    } // the scope must clear the shared index before the cells move into the tree
    if (!edges)
        return std::nullopt;
    return SpanningTree(std::move(cells), rootNode, *edges);
}

std::vector<std::pair<int, int>> fewestTurnEdges(const CellGraph& graph, const std::vector<int>& cells,
                                                 const RegionAdjacency& adjacency, bool cellsDifferInSize,
                                                 int plateauRounds, const ProgressReporter* progress) {
    TurnMinimisingTree::Options options;
    options.progress = progress;
    if (cellsDifferInSize) {
        const SizeChangeConnectors connectors(graph, cells, adjacency);
        return TurnMinimisingTree(adjacency, options, &connectors).edges();
    }
    options.plateauRounds = plateauRounds;
    return TurnMinimisingTree(adjacency, options).edges();
}

SpanningTree SpanningTreeBuilder::fewestTurns(std::vector<int> cells, int rootCell) const {
    const bool mixedSizes = cellsDifferInSize(cells);
    return *treeOver(std::move(cells), rootCell,
                     [&](const RegionAdjacency& adjacency, const std::vector<int>& regionCells) {
                         return std::optional(fewestTurnEdges(graph_, regionCells, adjacency, mixedSizes,
                                                              plateauRounds_, progress_));
                     });
}

std::optional<SpanningTree> SpanningTreeBuilder::fewestTurnsSearched(std::vector<int> cells,
                                                                     int rootCell) const {
    if (plateauRounds_ <= 0 || cells.empty() || cellsDifferInSize(cells))
        return std::nullopt;
    return treeOver(std::move(cells), rootCell,
                    [&](const RegionAdjacency& adjacency,
                        const std::vector<int>&) -> std::optional<std::vector<std::pair<int, int>>> {
                        TurnMinimisingTree::Options options;
                        options.plateauRounds = plateauRounds_;
                        options.progress = progress_;
                        const TurnMinimisingTree tree(adjacency, options);
                        if (!tree.searchLowered())
                            return std::nullopt;
                        return tree.edges();
                    });
}

bool SpanningTreeBuilder::cellsDifferInSize(const std::vector<int>& cells) const {
    if (graph_.hasOneCellSize()) // no need to read millions of cells to learn it
        return false;
    const auto differs = [&](int cell) { return graph_.cell(cell).span != graph_.cell(cells.front()).span; };
    return !cells.empty() && std::any_of(cells.begin(), cells.end(), differs);
}

int SpanningTreeBuilder::candidatesFor(const std::vector<int>& cells) const {
    return cellsDifferInSize(cells) ? candidateCount : 1;
}

SpanningTree SpanningTreeBuilder::candidate(int which, std::vector<int> cells, int rootCell) const {
    if (which == 0)
        return fewestTurns(std::move(cells), rootCell);
    return preferring(std::move(cells), rootCell,
                      which == 1 ? EdgeDirection::EastWest : EdgeDirection::NorthSouth);
}

SpanningTree SpanningTreeBuilder::spiral(std::vector<int> cells, int rootCell) const {
    std::vector<std::pair<int, int>> edges;
    int rootNode = 0;
    {
        const CellIndexScope local(index_, cells);
        const std::size_t count = cells.size();
        std::vector<char> visited(count, 0);
        edges.reserve(count);
        struct Frame {
            int node;
            std::vector<int> order; // unvisited-at-entry neighbours, counter-clockwise from the entry side
            std::size_t next = 0;
        };
        // Every neighbour of `node`, counter-clockwise starting just after the direction it was entered from.
        auto scanOrder = [&](int node, double entryBearing) {
            const Cell& self = graph_.cell(cells[static_cast<std::size_t>(node)]);
            std::vector<std::pair<double, int>> around;
            for (int neighbour : graph_.neighbours(cells[static_cast<std::size_t>(node)])) {
                const int other = local[neighbour];
                if (other < 0)
                    continue;
                double turn = bearing(self, graph_.cell(neighbour)) - entryBearing;
                while (turn <= 1e-9)
                    turn += 2.0 * std::numbers::pi;
                around.emplace_back(turn, other);
            }
            std::sort(around.begin(), around.end());
            std::vector<int> order;
            order.reserve(around.size());
            for (const auto& entry : around)
                order.push_back(entry.second);
            return order;
        };
        rootNode = local[rootCell];
        visited[static_cast<std::size_t>(rootNode)] = 1;
        // The start cell has no parent: scanning begins as if it had been entered from the south.
        std::vector<Frame> stack;
        stack.push_back({rootNode, scanOrder(rootNode, 1.5 * std::numbers::pi)});
        while (!stack.empty()) {
            Frame& frame = stack.back();
            if (frame.next == frame.order.size()) {
                stack.pop_back();
                continue;
            }
            const int next = frame.order[frame.next++];
            if (visited[static_cast<std::size_t>(next)] != 0)
                continue;
            visited[static_cast<std::size_t>(next)] = 1;
            edges.emplace_back(frame.node, next);
            const Cell& from = graph_.cell(cells[static_cast<std::size_t>(next)]);
            const double backToParent =
                bearing(from, graph_.cell(cells[static_cast<std::size_t>(frame.node)]));
            stack.push_back({next, scanOrder(next, backToParent)});
        }
    } // the scope must clear the shared index before the cells move into the tree
    return SpanningTree(std::move(cells), rootNode, edges);
}

} // namespace mcpp
