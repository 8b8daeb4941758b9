#pragma once

#include "core/model/CellGraph.hpp"

#include <vector>

namespace mcpp {

// The quickest ways from a cell to every cell of its connected part, turning least among the quickest: a
// robot's way to a piece of work that lies elsewhere (balanced MSTC). A step between neighbours costs the
// travel between their centres, and a change of direction the turn's time at the cell and a hair more
// (so that, turns free, of two equal ways the straighter is taken). The steps are worked out once per
// graph; each search reuses them and keeps only what is asked for, so that many robots on a big map cost a
// float a cell each.
class ApproachRoutes {
  public:
    explicit ApproachRoutes(const CellGraph& graph);

    // Seconds from `cell` to every cell, turns left out (a few a way: what the cuts need, five times
    // quicker to find); infinite where it lies in another part.
    [[nodiscard]] std::vector<float> secondsFrom(int cell) const;
    // The cells passed from `from` to `to`, both included; empty where `to` is not reached.
    [[nodiscard]] std::vector<int> cellsBetween(int from, int to) const;

  private:
    static constexpr int headings = 5; // east, north, west, south, and none (the first cell)

    struct Tree {
        std::vector<float> secondsToCell;
        std::vector<int> cameFrom;  // by search state (cell * headings + heading): the one before, -1 first
        std::vector<int> bestState; // by cell: the state that reached it soonest
    };
    // The search from `from`, stopped once `stopAt` is reached (-1: never); with turnsCount, by cell and
    // heading, each turn timed, and the way back kept.
    [[nodiscard]] Tree search(int from, int stopAt, bool turnsCount) const;

    struct Step {
        int to;
        int heading;
        float seconds;
    };

    std::vector<int> offsets_; // cell i's steps: steps_[offsets_[i] ... offsets_[i + 1])
    std::vector<Step> steps_;
    std::vector<float> turnSeconds_; // by cell, per quarter turn
};

} // namespace mcpp
