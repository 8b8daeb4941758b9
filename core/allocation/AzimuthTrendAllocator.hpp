#pragma once

#include "core/allocation/RegionAllocator.hpp"
#include "core/parameters/ParameterSpec.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// The map sizes at which the azimuth-trend allocation changes its ways.
struct AzimuthTrendLimits {
    // Above it, regions grow on blocks of AzimuthTrendAllocator::blockSide cells a side.
    std::size_t mostCellsGrownOneByOne = 8'000'000;
    // Above it a robot, regions grow cell by cell even with a tree piece share.
    std::size_t mostCellsOnTreePiecesPerRobot = 50'000;
    // The largest map grown again with weights where the first division stays uneven (0: none).
    std::size_t mostCellsGrownAgain = 20'000;
    // Above it, a robot queues a cell once as it grows, with its key when first seen, rather than once
    // for each of its cells beside it: the frontiers of a large map hold hundreds of thousands of
    // entries and taking the smallest out is most of the growth (a 4.8-million-cell forest grown in
    // 2.2-3.3 s instead of 6.2-6.7 s, in 520 MB instead of 860 MB, as even and turning as little).
    // Smaller maps keep each key as seen: their plans stay those of the benchmarks.
    std::size_t mostCellsQueuedAtEachStep = 1'000'000;
};

// The azimuth trend method of spec section 4: the least loaded robot grows towards its own centre and
// away from the others; a robot with no free cell next to it takes border cells from a richer neighbour;
// afterwards cells move along chains of adjacent regions from the most to the least loaded robot while
// the maximum cost falls. Where a map of at most mostCellsGrownAgain cells is still more than 1 % (and a
// cell) from even after that (starts crowded together, regions walled in near them by others'), it is grown
// again up to six times, each robot's turn in the growth going by its cost times a weight that falls for
// robots left short, and the most even division is kept. On a map of more than mostCellsGrownOneByOne cells
// the regions first grow and even out on blocks of blockSide x blockSide bottom cells (CellBlocks); each cell
// then takes its block's robot and cells cut off from their region's start join a neighbouring region
// (reconnectRegions). Growing 69 million cells one at a time took about a minute, most of it waiting on
// memory; blocks of 16 take a tenth of that. Where a region ends further than a block's cost from the mean,
// the map is grown cell by cell after all, as evening out cell by cell would leave a notch for every cell it
// moves. With a tree piece share (none by default), a map of at most mostCellsOnTreePiecesPerRobot cells a
// robot grows on pieces of a turn-minimising tree over the whole map instead (treePieces), each costing that
// share of a robot's fair share, is evened out on pieces an eighth of that, then cell by cell: the regions'
// borders follow the tree's cuts, and their paths turn less (1.7 % fewer turns on the uniform benchmark
// grids, 2.0 % on the multi-cover maps, 8 % on the Zion sample, at a share of 3 %), but the regions
// interlock along the tree's runs (47-65 % longer borders on those maps). Where regions are larger their
// borders weigh less: 0.65 % fewer turns on 1.67 M cells with 8 robots, for 2 s more planning. Robots of
// paces of their own (setPaces) grow on blocks too, each block check then in their own times.
class AzimuthTrendAllocator final : public RegionAllocator {
  public:
    static constexpr int blockSide = 4;

    // rebalanceIterations: cap on cell moves after growth; 0 picks one from the problem size.
    // treePieceShare: a tree piece's cost over a robot's fair share, 0 for growth cell by cell.
    explicit AzimuthTrendAllocator(int rebalanceIterations = 0, double treePieceShare = 0.0,
                                   AzimuthTrendLimits limits = {})
        : rebalanceIterations_(rebalanceIterations), treePieceShare_(treePieceShare), limits_(limits) {}

    // By robot, its seconds for a second of cell cost (robotPaces): regions are evened out in each robot's
    // own time, a robot of pace 0.5 taking twice the cost. Empty (the default): every robot at pace 1.
    void setPaces(std::vector<double> paces) { paces_ = std::move(paces); }

    [[nodiscard]] static ParameterSpec rebalanceIterationsParameter();
    // The planner parameter for treePieceShare, in percent.
    [[nodiscard]] static ParameterSpec treePieceShareParameter();

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
    [[nodiscard]] bool growsOnTreePieces(const CellGraph& graph, std::size_t robots) const;
    [[nodiscard]] RegionAllocation grownOnTreePieces(const CellGraph& graph,
                                                     const std::vector<int>& startCells,
                                                     const ProgressReporter& progress) const;

    int rebalanceIterations_;
    double treePieceShare_;
    AzimuthTrendLimits limits_;
    std::vector<double> paces_; // by robot; empty: all 1
};

} // namespace mcpp
