#pragma once

#include "core/coverage/CoveragePathPlanner.hpp"
#include "core/coverage/PathShape.hpp"
#include "core/coverage/SpanningTree.hpp"
#include "core/parameters/ParameterSpec.hpp"

#include <utility>

namespace mcpp {

// Improved STC on mixed-size cells (spec section 5): a spanning tree over each region from its start cell,
// circumnavigated counter-clockwise through the centres of every cell's four sub-cells. Each region tries
// the builder's candidate trees (the turn-minimising one first) and keeps the quickest walk.
class SpanningTreeCoverage final : public CoveragePathPlanner {
  public:
    // closedTour: tours end where they start; otherwise paths stop at the last sub-cell.
    explicit SpanningTreeCoverage(bool closedTour = true) : closedTour_(closedTour) {}

    [[nodiscard]] static ParameterSpec closedTourParameter();

    [[nodiscard]] std::vector<CoveragePath> plan(const CellGraph& graph, const RegionAllocation& regions,
                                                 const std::vector<MapPoint>& starts,
                                                 const ProgressReporter& progress) const override;

    // One robot's path over its region's cells: the quickest candidate tree's. scratchIndex: one int per
    // graph cell, all -1, left so.
    [[nodiscard]] CoveragePath regionPath(const CellGraph& graph, const std::vector<int>& cells,
                                          int startCell, int robot, MapPoint start,
                                          std::vector<int>& scratchIndex) const;

    // The candidate tree whose walk is quickest (travel and turns; then turns least, then is shortest), with
    // that walk's shape.
    [[nodiscard]] std::pair<SpanningTree, PathShape> bestTree(const CellGraph& graph,
                                                              const std::vector<int>& cells, int startCell,
                                                              MapPoint start,
                                                              std::vector<int>& scratchIndex) const;

  private:
    bool closedTour_;
};

// The cells of each robot's region, in cell-id order.
[[nodiscard]] std::vector<std::vector<int>> cellsByRobot(const RegionAllocation& regions);

} // namespace mcpp
