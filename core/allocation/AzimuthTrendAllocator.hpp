#pragma once

#include "core/allocation/RegionAllocator.hpp"
#include "core/parameters/ParameterSpec.hpp"

namespace mcpp {

// The azimuth trend method of spec section 4: the least loaded robot grows towards its own centre and
// away from the others; a robot with no free cell next to it takes border cells from a richer neighbour;
// afterwards cells move along chains of adjacent regions from the most to the least loaded robot while
// the maximum cost falls.
class AzimuthTrendAllocator final : public RegionAllocator {
  public:
    // rebalanceIterations: cap on cell moves after growth; 0 picks one from the problem size.
    explicit AzimuthTrendAllocator(int rebalanceIterations = 0) : rebalanceIterations_(rebalanceIterations) {}

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
};

} // namespace mcpp
