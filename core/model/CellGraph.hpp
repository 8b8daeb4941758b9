#pragma once

#include "core/model/Cell.hpp"
#include "core/model/CellRange.hpp"
#include "core/model/CellRecord.hpp"
#include "core/model/CellTurnFigures.hpp"
#include "core/model/GridFrame.hpp"
#include "core/model/GridOccupancy.hpp"
#include "core/model/NeighbourList.hpp"
#include "core/model/NeighbourTopology.hpp"
#include "core/model/RoundedFieldOfView.hpp"
#include "core/model/TurnTimeModel.hpp"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace mcpp {

// The cells a planner covers and which of them touch: the planner-neutral result of a decomposition.
// Cells are squares on the frame's bottom grid, each aligned to a multiple of its own span; they never
// overlap. Two cells are neighbours when they share a border of positive length.
class CellGraph {
  public:
    CellGraph() = default;
    CellGraph(GridFrame frame, std::vector<CellRecord> records, NeighbourTopology adjacency);
    // Cells made by hand or changed by a planner: each must lie where its column, row and span place it on
    // the frame, as only those are kept.
    CellGraph(GridFrame frame, const std::vector<Cell>& cells, NeighbourTopology adjacency);
    // The cells of a one-level grid, listed row by row (span 1): each cell's neighbours are found on the
    // grid when asked for, and no lists are kept.
    static CellGraph ofGrid(GridFrame frame, std::vector<CellRecord> records);
    // The cells of `sameCells`, in the same places and with the same neighbours, with other figures.
    CellGraph(const CellGraph& sameCells, std::vector<CellRecord> records);

    [[nodiscard]] const GridFrame& frame() const { return frame_; }
    [[nodiscard]] std::size_t size() const { return records_.size(); }
    [[nodiscard]] bool empty() const { return records_.empty(); }
    // Whether `id` numbers a cell of the graph (a waypoint off the map has -1).
    [[nodiscard]] bool contains(int id) const {
        return id >= 0 && static_cast<std::size_t>(id) < records_.size();
    }
    // A cell, whole: its square worked out from the frame.
    [[nodiscard]] Cell cell(int id) const { return cells()[static_cast<std::size_t>(id)]; }
    [[nodiscard]] CellRange cells() const { return {records_, frame_, turns_}; }
    [[nodiscard]] const CellRecord& record(int id) const { return records_[static_cast<std::size_t>(id)]; }
    [[nodiscard]] const std::vector<CellRecord>& records() const { return records_; }
    // What a turn costs in cell `id` (CellGraph::applyTurnTime), without making the whole cell.
    [[nodiscard]] float turnSeconds(int id) const {
        const auto index = static_cast<std::size_t>(id);
        return turns_.turnSeconds(index, records_[index].speedMetresPerSecond);
    }
    // The same for a robot driving through the cell at `speedMetresPerSecond` (its own, not the class's);
    // turn times given cell by cell (a plan file's that no model gives) stay as given.
    [[nodiscard]] float turnSeconds(int id, float speedMetresPerSecond) const {
        return turns_.turnSeconds(static_cast<std::size_t>(id), speedMetresPerSecond);
    }
    [[nodiscard]] const CellTurnFigures& turnFigures() const { return turns_; }
    // The turn figures of a graph of the same cells (as many, with the same speeds).
    void setTurnFigures(CellTurnFigures figures);
    [[nodiscard]] NeighbourList neighbours(int id) const {
        if (occupancy_.empty())
            return NeighbourList(adjacency_.of(id));
        return neighboursOnGrid(id);
    }
    [[nodiscard]] bool areNeighbours(int a, int b) const;
    // Asks the cache for what neighbours(id) will read.
    void prefetchNeighbours(int id) const {
        if (occupancy_.empty())
            __builtin_prefetch(adjacency_.offsets().data() + id);
        else
            __builtin_prefetch(records_.data() + id);
    }
    // Every cell's neighbours as lists (cell i's: neighbours()[offsets()[i] ... offsets()[i + 1])), made
    // for a grid that keeps none.
    [[nodiscard]] NeighbourTopology neighbourLists() const;
    // Whether every cell has the same span (a grid, or a quadtree of one level): then no step joins cells of
    // different sizes.
    [[nodiscard]] bool hasOneCellSize() const { return !occupancy_.empty() || locator_.size() <= 1; }
    // The cell holding the point, or -1 where there is none (obstacle, outside, beyond the grid).
    [[nodiscard]] int cellAt(MapPoint point) const;
    // Gives every cell the time a turn costs there, so its cost counts turns. Decompositions leave it 0.
    void applyTurnTime(const TurnTimeModel& model);
    // Sets the turns each cell's cost expects per sub-cell (cells past the list's end keep theirs).
    void setExpectedTurns(const std::vector<float>& turnsPerSubCell);
    // Gives each cell its own turn time (cells past the list's end get 0).
    void setTurnSeconds(std::vector<float> secondsPerCell);

    // What the decomposition found out about the map, for reports.
    std::vector<RoundedFieldOfView> fieldsOfView;
    double passableAreaSquareMetres = 0.0; // every passable pixel, in a cell or not

  private:
    [[nodiscard]] std::vector<int> idsInPlacementOrder(int span, std::size_t count) const;
    [[nodiscard]] NeighbourList neighboursOnGrid(int id) const {
        // North, east, south, west: the order the quadtree's neighbour lists give. Cells are listed row by
        // row, so a cell's east and west neighbours are the ids beside its own: only the rows above and
        // below need counting.
        const CellRecord& cell = records_[static_cast<std::size_t>(id)];
        NeighbourList found;
        if (const int north = occupancy_.idAt(cell.column, cell.row - 1); north >= 0)
            found.add(north);
        if (occupancy_.holds(cell.column + 1, cell.row))
            found.add(id + 1);
        if (const int south = occupancy_.idAt(cell.column, cell.row + 1); south >= 0)
            found.add(south);
        if (occupancy_.holds(cell.column - 1, cell.row))
            found.add(id - 1);
        return found;
    }

    GridFrame frame_;
    std::vector<CellRecord> records_;
    CellTurnFigures turns_;
    NeighbourTopology adjacency_; // empty where occupancy_ finds the neighbours
    GridOccupancy occupancy_;
    // Per distinct span: its cells sorted by (row / span, column / span), for cellAt. Ids only, the key
    // worked out from the cell: 4 bytes a cell instead of 16 (70 MB instead of 280 MB on 17.6 M cells).
    std::vector<std::pair<int, std::vector<int>>> locator_;
};

} // namespace mcpp
