#pragma once

#include "core/allocation/RegionAllocator.hpp"
#include "core/parameters/ParameterSpec.hpp"

#include <cstddef>

namespace mcpp {

// The azimuth trend method of spec section 4: the least loaded robot grows towards its own centre and
// away from the others; a robot with no free cell next to it takes border cells from a richer neighbour;
// afterwards cells move along chains of adjacent regions from the most to the least loaded robot while
// the maximum cost falls. On a map of more than mostCellsGrownOneByOne cells the regions first grow and
// even out on blocks of blockSide x blockSide bottom cells (CellBlocks); each cell then takes its block's
// robot and cells cut off from their region's start join a neighbouring region (reconnectRegions). Growing
// 69 million cells one at a time took about a minute, most of it waiting on memory; blocks of 16 take a
// tenth of that. Where a region ends further than a block's cost from the mean, the map is grown cell by
// cell after all, as evening out cell by cell would leave a notch for every cell it moves.
class AzimuthTrendAllocator final : public RegionAllocator {
  public:
    static constexpr std::size_t defaultMostCellsGrownOneByOne = 8'000'000;
    static constexpr int blockSide = 4;

    // rebalanceIterations: cap on cell moves after growth; 0 picks one from the problem size.
    explicit AzimuthTrendAllocator(int rebalanceIterations = 0,
                                   std::size_t mostCellsGrownOneByOne = defaultMostCellsGrownOneByOne)
        : rebalanceIterations_(rebalanceIterations), mostCellsGrownOneByOne_(mostCellsGrownOneByOne) {}

    [[nodiscard]] static ParameterSpec rebalanceIterationsParameter();

    [[nodiscard]] RegionAllocation allocate(const CellGraph& graph, const std::vector<int>& startCells,
                                            const ProgressReporter& progress) const override;
    // `division` evened out again after the cells' costs changed: its cells move along chains of adjacent
    // regions while the largest cost falls, as after growth (at most rebalance_iterations moves), without
    // growing the regions anew. Grown anew when the division does not cover the map from these starts or is
    // too far from even for moves one cell at a time.
    [[nodiscard]] RegionAllocation rebalance(const CellGraph& graph, const std::vector<int>& startCells,
                                             const RegionAllocation& division,
                                             const ProgressReporter& progress) const;

  private:
    int rebalanceIterations_;
    std::size_t mostCellsGrownOneByOne_;
};

} // namespace mcpp
