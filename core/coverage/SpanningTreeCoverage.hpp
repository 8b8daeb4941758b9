#pragma once

#include "core/coverage/CoveragePathPlanner.hpp"

namespace mcpp {

// Improved STC on mixed-size cells (spec section 5): a spanning tree over each region from its start cell,
// circumnavigated counter-clockwise through the centres of every cell's four sub-cells. Two trees are
// tried per region, one preferring east-west edges and one north-south, and the path with fewer turns kept.
class SpanningTreeCoverage final : public CoveragePathPlanner {
public:
    [[nodiscard]] std::vector<CoveragePath> plan(const QuadTree& tree, const NeighbourTopology& topology,
                                                 const RegionAllocation& allocation, const std::vector<MapPoint>& starts,
                                                 const PlannerSettings& settings,
                                                 const ProgressReporter& progress) const override;
};

// Counts direction changes along a polyline (zero-length steps ignored).
[[nodiscard]] int countTurns(const std::vector<Waypoint>& waypoints);
// Length, time and cumulative times of a path: each segment is travelled half at the speed of the cell it
// leaves and half at the speed of the cell it enters.
void measurePath(CoveragePath& path);

} // namespace mcpp
