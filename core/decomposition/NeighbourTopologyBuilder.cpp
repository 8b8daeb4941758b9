#include "core/decomposition/NeighbourTopologyBuilder.hpp"

#include <array>
#include <cstdint>

namespace mcpp {
namespace {

enum Side { North = 0, East = 1, South = 2, West = 3 };
constexpr std::array<int, 4> rowStep{-1, 0, 1, 0};
constexpr std::array<int, 4> columnStep{0, 1, 0, -1};
// Children touching each side, in the order north-west, north-east, south-east, south-west.
constexpr std::array<std::array<int, 2>, 4> childrenOnSide{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};

} // namespace

NeighbourTopology NeighbourTopologyBuilder::build(const QuadTree& tree) const {
    // Index of the cell at each (level, row, column), -1 where the level has no cell there.
    std::vector<std::vector<int>> indexAt(static_cast<std::size_t>(tree.levels));
    for (int level = 1; level <= tree.levels; ++level)
        indexAt[static_cast<std::size_t>(level - 1)].assign(static_cast<std::size_t>(tree.columnsAt(level)) *
                                                                static_cast<std::size_t>(tree.rowsAt(level)),
                                                            -1);
    for (std::size_t index = 0; index < tree.cells.size(); ++index) {
        const QuadCell& cell = tree.cells[index];
        indexAt[static_cast<std::size_t>(cell.level - 1)]
               [static_cast<std::size_t>(cell.row) * static_cast<std::size_t>(tree.columnsAt(cell.level)) +
                static_cast<std::size_t>(cell.column)] = static_cast<int>(index);
    }

    std::vector<int> offsets;
    std::vector<int> neighbours;
    offsets.reserve(tree.activeCells.size() + 1);
    neighbours.reserve(tree.activeCells.size() * 4);
    offsets.push_back(0);
    std::vector<int> descent;
    for (int cellIndex : tree.activeCells) {
        const QuadCell& cell = tree.cells[static_cast<std::size_t>(cellIndex)];
        for (int side = North; side <= West; ++side) {
            const int row = cell.row + rowStep[static_cast<std::size_t>(side)];
            const int column = cell.column + columnStep[static_cast<std::size_t>(side)];
            if (row < 0 || column < 0 || row >= tree.rowsAt(cell.level) ||
                column >= tree.columnsAt(cell.level))
                continue;
            const int same =
                indexAt[static_cast<std::size_t>(cell.level - 1)]
                       [static_cast<std::size_t>(row) * static_cast<std::size_t>(tree.columnsAt(cell.level)) +
                        static_cast<std::size_t>(column)];
            if (same < 0) {
                // The position lies inside a larger leaf: climb to the level where it exists.
                for (int level = cell.level - 1; level >= 1; --level) {
                    const int shift = cell.level - level;
                    const int ancestor = indexAt[static_cast<std::size_t>(level - 1)]
                                                [static_cast<std::size_t>(row >> shift) *
                                                     static_cast<std::size_t>(tree.columnsAt(level)) +
                                                 static_cast<std::size_t>(column >> shift)];
                    if (ancestor >= 0) {
                        if (tree.cells[static_cast<std::size_t>(ancestor)].state == CellState::Active)
                            neighbours.push_back(tree.cells[static_cast<std::size_t>(ancestor)].activeIndex);
                        break;
                    }
                }
                continue;
            }
            // Descend into the children of the neighbour that face this cell.
            const int facing = (side + 2) % 4;
            descent.clear();
            descent.push_back(same);
            while (!descent.empty()) {
                const int index = descent.back();
                descent.pop_back();
                const QuadCell& candidate = tree.cells[static_cast<std::size_t>(index)];
                if (candidate.state == CellState::Active) {
                    neighbours.push_back(candidate.activeIndex);
                } else if (candidate.state == CellState::Auxiliary) {
                    // Pushed in reverse so the neighbours come out in a fixed order along the side.
                    const auto& pair = childrenOnSide[static_cast<std::size_t>(facing)];
                    descent.push_back(candidate.child(pair[1]));
                    descent.push_back(candidate.child(pair[0]));
                }
            }
        }
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    return NeighbourTopology(std::move(offsets), std::move(neighbours));
}

NeighbourTopology NeighbourTopologyBuilder::build(const OneLevelQuadTree& grid) const {
    const auto columns = static_cast<std::size_t>(grid.frame.columns);
    std::vector<int> indexAt(columns * static_cast<std::size_t>(grid.frame.rows), -1);
    for (std::size_t index = 0; index < grid.cells.size(); ++index)
        indexAt[static_cast<std::size_t>(grid.cells[index].row) * columns +
                static_cast<std::size_t>(grid.cells[index].column)] = static_cast<int>(index);
    std::vector<int> offsets;
    std::vector<int> neighbours;
    offsets.reserve(grid.cells.size() + 1);
    neighbours.reserve(grid.cells.size() * 4);
    offsets.push_back(0);
    for (const CellRecord& cell : grid.cells) {
        for (int side = North; side <= West; ++side) {
            const int row = cell.row + rowStep[static_cast<std::size_t>(side)];
            const int column = cell.column + columnStep[static_cast<std::size_t>(side)];
            if (row < 0 || column < 0 || row >= grid.frame.rows || column >= grid.frame.columns)
                continue;
            const int neighbour =
                indexAt[static_cast<std::size_t>(row) * columns + static_cast<std::size_t>(column)];
            if (neighbour >= 0)
                neighbours.push_back(neighbour);
        }
        offsets.push_back(static_cast<int>(neighbours.size()));
    }
    return NeighbourTopology(std::move(offsets), std::move(neighbours));
}

} // namespace mcpp
