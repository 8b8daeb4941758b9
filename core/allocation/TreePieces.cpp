#include "core/allocation/TreePieces.hpp"

#include "core/coverage/RegionAdjacency.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mcpp {
namespace {

// Every cell is its own region position: the whole graph is one region.
struct WholeGraphIndex {
    int operator[](int cell) const { return cell; }
};

// The tree (a forest where the map falls apart) as parent links, with its cells in breadth-first order
// from each part's lowest cell: parents come before their children.
struct RootedForest {
    std::vector<int> order;
    std::vector<int> parent;
};

RootedForest rootForest(std::size_t cellCount, const std::vector<std::pair<int, int>>& edges) {
    std::vector<int> offsets(cellCount + 1, 0);
    for (const auto& [a, b] : edges) {
        ++offsets[static_cast<std::size_t>(a) + 1];
        ++offsets[static_cast<std::size_t>(b) + 1];
    }
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    std::vector<int> next(offsets.begin(), offsets.end() - 1);
    std::vector<int> linked(edges.size() * 2);
    for (const auto& [a, b] : edges) {
        linked[static_cast<std::size_t>(next[static_cast<std::size_t>(a)]++)] = b;
        linked[static_cast<std::size_t>(next[static_cast<std::size_t>(b)]++)] = a;
    }
    RootedForest forest;
    forest.parent.assign(cellCount, -1);
    forest.order.reserve(cellCount);
    std::vector<char> seen(cellCount, 0);
    for (std::size_t root = 0; root < cellCount; ++root) {
        if (seen[root] != 0)
            continue;
        seen[root] = 1;
        forest.order.push_back(static_cast<int>(root));
        for (std::size_t head = forest.order.size() - 1; head < forest.order.size(); ++head) {
            const auto cell = static_cast<std::size_t>(forest.order[head]);
            for (int at = offsets[cell]; at < offsets[cell + 1]; ++at) {
                const int other = linked[static_cast<std::size_t>(at)];
                if (seen[static_cast<std::size_t>(other)] == 0) {
                    seen[static_cast<std::size_t>(other)] = 1;
                    forest.parent[static_cast<std::size_t>(other)] = static_cast<int>(cell);
                    forest.order.push_back(other);
                }
            }
        }
    }
    return forest;
}

// A piece may reach this many times the side of a square of its cost. A turn-minimising tree over a whole
// map runs straight across it, and uncut, its subtrees are strips: on the Zion sample, regions grown from
// them interlocked in strips a few cells high and 5 km long (three times the border of compact regions).
constexpr double longestPieceSideOverSquareSide = 2.0;

// Extent on the bottom grid of each subtree summed so far (by the cell that heads it).
struct SubtreeExtents {
    std::vector<int> west, east, north, south;

    explicit SubtreeExtents(const CellGraph& graph) {
        const std::size_t cellCount = graph.size();
        west.resize(cellCount);
        east.resize(cellCount);
        north.resize(cellCount);
        south.resize(cellCount);
        for (std::size_t at = 0; at < cellCount; ++at) {
            const Cell& cell = graph.cell(static_cast<int>(at));
            west[at] = cell.column;
            east[at] = cell.column + cell.span;
            north[at] = cell.row;
            south[at] = cell.row + cell.span;
        }
    }
    [[nodiscard]] int longestSide(std::size_t at) const {
        return std::max(east[at] - west[at], south[at] - north[at]);
    }
    void add(std::size_t into, std::size_t from) {
        west[into] = std::min(west[into], west[from]);
        east[into] = std::max(east[into], east[from]);
        north[into] = std::min(north[into], north[from]);
        south[into] = std::max(south[into], south[from]);
    }
};

// Bottom cells a second of cover time takes on this map, on average: what turns a piece's cost into its size.
double bottomCellsPerSecond(const CellGraph& graph) {
    double seconds = 0.0;
    double bottomCells = 0.0;
    for (std::size_t at = 0; at < graph.size(); ++at) {
        const Cell& cell = graph.cell(static_cast<int>(at));
        seconds += cell.coverSeconds();
        bottomCells += static_cast<double>(cell.span) * cell.span;
    }
    return seconds > 0.0 ? bottomCells / seconds : std::numeric_limits<double>::infinity();
}

// The cells that head a piece: a subtree becomes a piece once it costs pieceCost or reaches the longest
// side, or where joining its parent's would put two starts in one piece (worked bottom-up). A finer level
// sums its costs across the coarser level's cuts and then cuts there too: respecting those cuts in the sums
// gave as few turns, but on a 480 x 480 grid with 8 robots a division the evening out took 13 s over instead
// of 0.3 s.
std::vector<char> pieceHeads(const CellGraph& graph, const RootedForest& forest,
                             const std::vector<int>& startCells, double pieceCost, double cellsPerSecond) {
    const std::size_t cellCount = graph.size();
    std::vector<double> open(cellCount);
    std::vector<char> holdsStart(cellCount, 0);
    for (std::size_t cell = 0; cell < cellCount; ++cell)
        open[cell] = graph.cell(static_cast<int>(cell)).coverSeconds();
    // The side, in bottom cells, beyond which a subtree is cut off as a piece.
    const double longestSide = longestPieceSideOverSquareSide * std::sqrt(pieceCost * cellsPerSecond);
    SubtreeExtents extents(graph);
    for (int start : startCells)
        holdsStart[static_cast<std::size_t>(start)] = 1;
    std::vector<char> heads(cellCount, 0);
    for (auto at = forest.order.rbegin(); at != forest.order.rend(); ++at) {
        const auto cell = static_cast<std::size_t>(*at);
        const int parent = forest.parent[cell];
        if (parent < 0) {
            heads[cell] = 1;
            continue;
        }
        const auto parentIndex = static_cast<std::size_t>(parent);
        if (open[cell] >= pieceCost || extents.longestSide(cell) >= longestSide ||
            (holdsStart[cell] != 0 && holdsStart[parentIndex] != 0)) {
            heads[cell] = 1;
            continue;
        }
        open[parentIndex] += open[cell];
        extents.add(parentIndex, cell);
        holdsStart[parentIndex] = static_cast<char>(holdsStart[parentIndex] | holdsStart[cell]);
    }
    return heads;
}

CellBlocks piecesOf(const CellGraph& graph, const RootedForest& forest, const std::vector<char>& heads) {
    std::vector<int> pieceOfCell(graph.size(), -1);
    int pieces = 0;
    for (int cell : forest.order) {
        const auto at = static_cast<std::size_t>(cell);
        pieceOfCell[at] =
            heads[at] != 0 ? pieces++ : pieceOfCell[static_cast<std::size_t>(forest.parent[at])];
    }
    return groupIntoConnectedBlocks(graph, std::move(pieceOfCell), pieces);
}

} // namespace

std::vector<CellBlocks> treePieces(const CellGraph& graph, const std::vector<int>& startCells,
                                   const std::vector<double>& pieceCosts, const ProgressReporter* progress) {
    const std::size_t cellCount = graph.size();
    std::vector<int> cells(cellCount);
    std::iota(cells.begin(), cells.end(), 0);
    std::vector<std::pair<int, int>> edges;
    {
        const RegionAdjacency adjacency(graph, cells, WholeGraphIndex{});
        edges = fewestTurnEdges(graph, cells, adjacency, !graph.hasOneCellSize(), 0, progress);
    }
    const RootedForest forest = rootForest(cellCount, edges);
    std::vector<CellBlocks> levels;
    std::vector<char> coarserHeads(cellCount, 0);
    const double cellsPerSecond = bottomCellsPerSecond(graph); // once for every level
    for (double pieceCost : pieceCosts) {
        std::vector<char> heads = pieceHeads(graph, forest, startCells, pieceCost, cellsPerSecond);
        for (std::size_t cell = 0; cell < cellCount; ++cell)
            heads[cell] = static_cast<char>(heads[cell] | coarserHeads[cell]);
        levels.push_back(piecesOf(graph, forest, heads));
        coarserHeads = std::move(heads);
    }
    return levels;
}

} // namespace mcpp
