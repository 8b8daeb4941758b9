#pragma once

#include "core/coverage/OwnSpeeds.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/LocalConnectivity.hpp"
#include "core/model/RegionAllocation.hpp"
#include "core/parameters/ParameterSpec.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// Region borders that cut straight runs cost turns: a cell whose region holds neither both its east and
// west nor both its north and south neighbours cannot lie inside a straight run, and a coverage walk turns
// twice there. Border cells change region where that leaves fewer such cells, alone or with the next cell
// in line behind them (a step in a staircase border), never splitting a region, never moving a start and
// never raising any region's cost above the most loaded one's times (1 + slack). On the uniform benchmark
// grids this takes up to 10 % of the turns away at a slack of 0.2 %.
class BorderStraightening {
  public:
    // How the first pass finds the border: cells found off every border beforehand, on every core, are
    // skipped unless a move changed them or a neighbour since; or each cell is asked in turn, as before that
    // was done (kept to check that both move the same cells).
    enum class FirstPass { SkipsInsides, AsksEveryCell };

    // slack: the share of the most loaded region's cost any region may grow to beyond it.
    BorderStraightening(const CellGraph& graph, double slack, FirstPass firstPass = FirstPass::SkipsInsides);

    // The planner parameter, in percent.
    [[nodiscard]] static ParameterSpec slackParameter();

    // By robot, its seconds for a second of cell cost (robotPaces): the regions' costs are then their robots'
    // own times (AzimuthTrendAllocator::setPaces). Empty (the default): every robot at pace 1.
    void setPaces(std::vector<double> paces) { paces_ = std::move(paces); }

    // Moves cells until a pass over the border moves none; returns how many moved.
    int straighten(RegionAllocation& regions) const;

  private:
    [[nodiscard]] bool blocksRuns(int cell, const std::vector<int>& owner) const;
    [[nodiscard]] int blockedAround(int cell, const std::vector<int>& owner) const;
    [[nodiscard]] int straightNeighbour(int cell, std::size_t side) const;
    [[nodiscard]] int blockedNear(const std::vector<int>& cells, const std::vector<int>& owner) const;
    // Moves the cell with a partner when that helps; returns the partner, -1 when nothing moved.
    int movePair(int cell, RegionAllocation& regions, double ceiling, LocalConnectivity& connectivity) const;
    [[nodiscard]] bool onBorder(int cell, const std::vector<int>& owner) const;
    // Which cells lie on a border before any moves, found on every core.
    [[nodiscard]] std::vector<std::uint8_t> bordersBeforeMoves(const std::vector<int>& owner) const;
    [[nodiscard]] static bool isStart(int cell, const RegionAllocation& regions);
    // The region the cell is best moved to, -1 if none lowers the count; `refused` is set when a
    // neighbouring region could not take it for its cost.
    [[nodiscard]] int bestMove(int cell, std::vector<int>& owner, const std::vector<double>& cost,
                               double ceiling, bool& refused) const;

    [[nodiscard]] double pace(int robot) const { return paceOf(paces_, static_cast<std::size_t>(robot)); }

    const CellGraph& graph_;
    double slack_;
    FirstPass firstPass_;
    std::vector<double> paces_; // by robot; empty: all 1
};

} // namespace mcpp
