#include "core/allocation/CellBlocks.hpp"

#include "core/model/ParallelFor.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <span>

namespace mcpp {

namespace {

// Adds a cell's figures to its block's: the centre summed weighted by area until divideCentres.
void addFigures(const Cell& cell, CellFigures& block) {
    const CellFigures figures = figuresOf(cell);
    block.x += figures.x * figures.area;
    block.y += figures.y * figures.area;
    block.area += figures.area;
    block.cost += figures.cost;
}

void divideCentres(std::vector<CellFigures>& blocks) {
    for (CellFigures& block : blocks) {
        block.x /= block.area;
        block.y /= block.area;
    }
}

// Block ids by cell, numbered in the order of each block's first cell, and the blocks' figures: one pass
// over cells that on a large map fill gigabytes.
void numberBlocks(const CellGraph& graph, int side, CellBlocks& blocks) {
    const GridFrame& frame = graph.frame();
    const std::int64_t blockColumns = (static_cast<std::int64_t>(frame.columns) + side - 1) / side;
    const std::int64_t blockRows = (static_cast<std::int64_t>(frame.rows) + side - 1) / side;
    std::vector<int> idOfPlace(static_cast<std::size_t>(blockColumns * blockRows), -1);
    blocks.blockOfCell.resize(graph.size());
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        const auto place = static_cast<std::size_t>(cell.row / side * blockColumns + cell.column / side);
        if (idOfPlace[place] < 0) {
            idOfPlace[place] = static_cast<int>(blocks.figures.size());
            blocks.figures.emplace_back();
        }
        blocks.blockOfCell[id] = idOfPlace[place];
        addFigures(cell, blocks.figures[static_cast<std::size_t>(idOfPlace[place])]);
    }
    divideCentres(blocks.figures);
}

// Cell ids listed block by block (a counting sort): cellsOf[offsets[b] ... offsets[b + 1]).
void cellsByBlock(const std::vector<int>& blockOfCell, int blockCount, std::vector<int>& offsets,
                  std::vector<int>& cellsOf) {
    offsets.assign(static_cast<std::size_t>(blockCount) + 1, 0);
    for (int block : blockOfCell)
        ++offsets[static_cast<std::size_t>(block) + 1];
    for (std::size_t block = 0; block < static_cast<std::size_t>(blockCount); ++block)
        offsets[block + 1] += offsets[block];
    std::vector<int> next(offsets.begin(), offsets.end() - 1);
    cellsOf.resize(blockOfCell.size());
    for (std::size_t id = 0; id < blockOfCell.size(); ++id)
        cellsOf[static_cast<std::size_t>(next[static_cast<std::size_t>(blockOfCell[id])]++)] =
            static_cast<int>(id);
}

// Whether `cells`, all of `block`'s (a few), are linked through each other alone. A neighbour's block
// says whether it is one of them, and its place among them whether it was reached: on millions of blocks,
// searching the cells and the reached list for every neighbour took most of the blocks' grouping.
// `members` and `reached` are scratch.
bool linkedWithin(const CellGraph& graph, std::span<const int> cells, int block,
                  const std::vector<int>& blockOfCell, std::vector<int>& members,
                  std::vector<char>& reached) {
    reached.assign(cells.size(), 0);
    reached[0] = 1;
    members.assign(1, cells.front());
    for (std::size_t head = 0; head < members.size(); ++head)
        for (int neighbour : graph.neighbours(members[head])) {
            if (blockOfCell[static_cast<std::size_t>(neighbour)] != block)
                continue;
            const auto place =
                static_cast<std::size_t>(std::find(cells.begin(), cells.end(), neighbour) - cells.begin());
            if (reached[place] == 0) {
                reached[place] = 1;
                members.push_back(neighbour);
            }
        }
    return members.size() == cells.size();
}

// Appends the blocks that `block` touches, sorted, to `neighbours`.
void addTouchingBlocks(const CellGraph& graph, std::span<const int> cells, int block,
                       const std::vector<int>& blockOfCell, std::vector<int>& neighbours) {
    const auto first = static_cast<std::ptrdiff_t>(neighbours.size());
    for (int cell : cells)
        for (int neighbour : graph.neighbours(cell)) {
            const int other = blockOfCell[static_cast<std::size_t>(neighbour)];
            if (other != block &&
                std::find(neighbours.begin() + first, neighbours.end(), other) == neighbours.end())
                neighbours.push_back(other);
        }
    std::sort(neighbours.begin() + first, neighbours.end());
}

// Which blocks touch, and whether each block's cells are linked among themselves (not checked where
// `linksKnown`: the caller made them so). Spans of blocks are looked at side by side, each into lists of
// its own joined in order after: the same lists whatever the number of threads.
NeighbourTopology blockAdjacency(const CellGraph& graph, const std::vector<int>& blockOfCell, int blockCount,
                                 bool& everyBlockConnected, bool linksKnown = false) {
    constexpr std::size_t blocksPerTask = std::size_t{1} << 15;
    std::vector<int> cellOffsets;
    std::vector<int> cellsOf;
    cellsByBlock(blockOfCell, blockCount, cellOffsets, cellsOf);
    const auto blocks = static_cast<std::size_t>(blockCount);
    const std::size_t tasks = (blocks + blocksPerTask - 1) / blocksPerTask;
    std::vector<int> offsets(blocks + 1, 0);
    std::vector<std::vector<int>> neighboursOfTask(tasks);
    std::atomic<bool> allConnected{true};
    parallelForRanges(blocks, blocksPerTask, [&](std::size_t task, std::size_t begin, std::size_t end) {
        std::vector<int>& neighbours = neighboursOfTask[task];
        neighbours.reserve((end - begin) * 4);
        std::vector<int> members;
        std::vector<char> reached;
        for (std::size_t block = begin; block < end; ++block) {
            const std::span<const int> cells(
                cellsOf.data() + cellOffsets[block],
                static_cast<std::size_t>(cellOffsets[block + 1] - cellOffsets[block]));
            const std::size_t before = neighbours.size();
            addTouchingBlocks(graph, cells, static_cast<int>(block), blockOfCell, neighbours);
            offsets[block + 1] = static_cast<int>(neighbours.size() - before);
            if (!linksKnown && cells.size() > 1 && allConnected.load(std::memory_order_relaxed) &&
                !linkedWithin(graph, cells, static_cast<int>(block), blockOfCell, members, reached))
                allConnected.store(false, std::memory_order_relaxed);
        }
    });
    everyBlockConnected = allConnected.load();
    for (std::size_t block = 0; block < blocks; ++block)
        offsets[block + 1] += offsets[block];
    std::vector<int> neighbours;
    neighbours.reserve(static_cast<std::size_t>(offsets.back()));
    for (std::vector<int>& list : neighboursOfTask) {
        neighbours.insert(neighbours.end(), list.begin(), list.end());
        std::vector<int>().swap(list);
    }
    return {std::move(offsets), std::move(neighbours)};
}

} // namespace

CellBlocks groupIntoBlocks(const CellGraph& graph, int side) {
    CellBlocks blocks;
    numberBlocks(graph, side, blocks);
    const auto blockCount = static_cast<int>(blocks.figures.size());
    blocks.adjacency = blockAdjacency(graph, blocks.blockOfCell, blockCount, blocks.everyBlockConnected);
    return blocks;
}

CellBlocks groupIntoConnectedBlocks(const CellGraph& graph, std::vector<int> blockOfCell, int blockCount) {
    CellBlocks blocks;
    blocks.blockOfCell = std::move(blockOfCell);
    blocks.figures.assign(static_cast<std::size_t>(blockCount), {});
    for (std::size_t id = 0; id < graph.size(); ++id)
        addFigures(graph.cell(static_cast<int>(id)),
                   blocks.figures[static_cast<std::size_t>(blocks.blockOfCell[id])]);
    divideCentres(blocks.figures);
    blocks.adjacency =
        blockAdjacency(graph, blocks.blockOfCell, blockCount, blocks.everyBlockConnected, true);
    return blocks;
}

} // namespace mcpp
