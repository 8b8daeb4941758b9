#pragma once

#include "core/coverage/PathClock.hpp"
#include "core/model/CellGraph.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mcpp {

// One robot's DSTC (seed 003): Spiral-STC planned as the robot drives, so the cells ahead of it stay free
// for the exchange. Its spanning tree grows one cell at a time into cells of its region nobody has entered.
// Round each cell it passes the four sub-cells counter-clockwise and, between two of them, the neighbours
// along that side (several where cells differ in size); it enters each new neighbour as it passes it
// (Gabriely and Rimon's online rule), goes round it the same way from just after the cell it came from,
// and carries on where it was. The walk round a finished tree is the one TreeCircumnavigation makes of it.
// When its tree is done and its region still holds cells nobody entered (given to it later, or cut off), it
// drives the shortest way over cells to the nearest and grows a new tree there. Every sub-cell of the
// graph's cells must be free.
class DynamicTreeWalk {
  public:
    // The start cell is marked entered.
    DynamicTreeWalk(const CellGraph& graph, int robot, MapPoint start, int startCell,
                    std::vector<char>& entered);

    // Grows its trees along planned ones where it can. `plannedParent`, by cell: the cell a planned tree
    // enters it from, -1 for none. A cell is left for its planned parent while that parent is this robot's
    // and will still come to it; cells no plan foresees (taken over, or whose planned parent went to another
    // robot) are entered by the online rule. Marks in `entered`: 0 nobody, 1 open, 2 done.
    void followPlannedTrees(const std::vector<int>* plannedParent) { plannedParent_ = plannedParent; }

    // One move: into a new cell, or out of a finished one, or on to a new tree. False when nothing of its
    // region is left to enter and its trees are done.
    bool advance(const std::vector<int>& owner, std::vector<char>& entered);

    [[nodiscard]] const std::vector<Waypoint>& waypoints() const { return clock_.waypoints(); }
    // Full-speed seconds from the start to each waypoint, as the plan's measurement will time them.
    [[nodiscard]] const std::vector<double>& nominalSecondsAt() const { return nominalSecondsAt_; }
    // Work it has committed to: the cover time of the sub-cells of cells it has entered and not yet passed.
    [[nodiscard]] double committedSeconds() const { return committedSeconds_; }
    // Whether its current tree is done (it must look for more of its region before it moves again).
    [[nodiscard]] bool treeDone() const { return frames_.empty(); }
    // How many cells it has entered so far.
    [[nodiscard]] std::size_t cellsEntered() const { return cellsEntered_; }
    // Lets go of the cells it has not covered whole by its first `reachedWaypoints` points (it stopped
    // there, during its last move): open cells with a sub-cell not yet passed by then, and the last cell it
    // finished, when its last sub-cell was passed after that. Open cells it had passed whole stay its own.
    [[nodiscard]] std::vector<int> abandonUnfinishedCells(std::size_t reachedWaypoints);
    [[nodiscard]] std::vector<Waypoint> takeWaypoints() { return clock_.take(); }

  private:
    // A cell's round: its items in arena_[start, end), the next to pass at `next`. Items >= 0 are
    // neighbouring cells, items < 0 sub-cells (-1 - SubCell).
    struct Frame {
        int cell = 0;
        std::size_t start = 0; // where its items begin in arena_ (the first is skipped below a tree's root)
        std::size_t end = 0;
        std::size_t next = 0;
        std::uint8_t passed = 0;      // bit per sub-cell (SubCell order) the robot has passed
        std::size_t wholeAt = notYet; // the waypoint that passed its last sub-cell
    };
    static constexpr std::size_t notYet = static_cast<std::size_t>(-1);

    void appendRound(int cell);
    void enter(int cell, int parent, std::vector<char>& entered);
    void pass(int cell, SubCell subCell);
    void stepTo(int cell, SubCell subCell);
    void markPassed(Frame& frame, SubCell subCell);
    void closeFrame(std::vector<char>& entered);
    [[nodiscard]] bool mayEnter(int from, int cell, const std::vector<int>& owner,
                                const std::vector<char>& entered) const;
    [[nodiscard]] bool startTree(const std::vector<int>& owner, std::vector<char>& entered);
    [[nodiscard]] std::vector<int> wayToNearestFreeCell(const std::vector<int>& owner,
                                                        const std::vector<char>& entered) const;

    const CellGraph& graph_;
    int robot_;
    PathClock clock_;
    std::vector<double> nominalSecondsAt_;
    std::vector<Frame> frames_;
    std::vector<int> arena_;                           // the open cells' rounds, a stack
    std::unordered_map<int, std::size_t> frameOfCell_; // the open cells' places in frames_
    std::vector<int> passedThrough_; // cells the tree went through since the last point, to bridge
    const std::vector<int>* plannedParent_ = nullptr;
    double committedSeconds_ = 0.0;
    std::size_t cellsEntered_ = 0;
    int lastClosedCell_ = -1;                // the last cell it finished
    std::size_t lastClosedWholeAt_ = notYet; // the waypoint that passed its last sub-cell
};

} // namespace mcpp
