#pragma once

#include "core/allocation/RegionAllocator.hpp"

namespace mcpp {

// The azimuth trend method of spec section 4: the least loaded robot grows towards its own centre and
// away from the others; a robot with no free cell next to it takes border cells from a richer neighbour;
// afterwards cells move along chains of adjacent regions from the most to the least loaded robot while
// the maximum cost falls.
class AzimuthTrendAllocator final : public RegionAllocator {
  public:
    [[nodiscard]] RegionAllocation allocate(const CellGraph& graph, const std::vector<int>& startCells,
                                            const PlannerSettings& settings,
                                            const ProgressReporter& progress) const override;
};

} // namespace mcpp
