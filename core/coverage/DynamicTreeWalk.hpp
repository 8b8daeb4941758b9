#pragma once

#include "core/coverage/PathClock.hpp"
#include "core/coverage/SubCellNodes.hpp"
#include "core/model/CellGraph.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// One robot's DSTC (seed 003): Spiral-STC planned as the robot drives, so the cells ahead of it stay free
// for the exchange. Its spanning tree grows one cell at a time into cells of its region nobody has entered:
// in each cell it circles the four sub-cells counter-clockwise and enters each new side neighbour as it
// passes it (Gabriely and Rimon's online rule), then returns to the cell it came from. When its tree is done
// and its region still holds cells nobody entered (given to it later, or cut off), it drives the shortest
// way over sub-cells to the nearest and grows a new tree there.
class DynamicTreeWalk {
  public:
    // `nodes` holds every sub-cell of the graph; the start cell is marked entered.
    DynamicTreeWalk(const CellGraph& graph, const SubCellNodes& nodes, int robot, MapPoint start,
                    int startCell, std::vector<char>& entered);

    // One move: into a new cell, back to the cell before, round a tree's first cell, or on to a new tree.
    // False when nothing of its region is left to enter and its trees are done.
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
    // Lets go of the cells it has not finished by its first `reachedWaypoints` points (it stopped there):
    // those it has entered and not circled, and one it was finishing on the way out. Nobody covered them
    // whole.
    [[nodiscard]] std::vector<int> abandonUnfinishedCells(std::size_t reachedWaypoints);
    [[nodiscard]] std::vector<Waypoint> takeWaypoints() { return clock_.take(); }

  private:
    struct Frame {
        int cell = 0;
        int parentDirection = 0; // for a tree's first cell, the side before the sub-cell it began in
        int scanned = 0;         // sides looked at so far
        bool root = false;
        int children = 0;
        std::uint8_t passed = 0; // bit per sub-cell (SubCell order) the robot has passed
    };

    [[nodiscard]] int subCellIndexOf(int node) const;
    void stepTo(int node);
    void markPassed(Frame& frame, int subCellIndex);
    void circleTo(int subCellIndex);
    void enter(int cell, int node, int parentDirection, bool root, std::vector<char>& entered);
    [[nodiscard]] int openSide(int cell, int direction, const std::vector<int>& owner,
                               const std::vector<char>& entered) const;
    [[nodiscard]] bool startTree(const std::vector<int>& owner, std::vector<char>& entered);

    const CellGraph& graph_;
    const SubCellNodes& nodes_;
    int robot_;
    PathClock clock_;
    std::vector<double> nominalSecondsAt_;
    std::vector<Frame> frames_;
    int node_ = SubCellNodes::none;
    int treeStartSubCell_ = 0;
    double committedSeconds_ = 0.0;
    std::size_t cellsEntered_ = 0;
    int lastClosedCell_ = -1;            // the cell the last move finished circling
    std::size_t lastClosedWaypoint_ = 0; // its last point
};

} // namespace mcpp
