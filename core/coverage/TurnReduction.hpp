#pragma once

#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"

#include <vector>

namespace mcpp {

// DARP's turn reduction (seed 004). Once regions are divided and covered, a cell sticking out of one region
// into another (its only neighbour in its own region, two or more in the other) is an end shape that costs
// both paths turns. It changes hands when that lowers the two regions' turns together, raises neither
// region's turns and does not lengthen the longest path. Each round tries every such cell once.
class TurnReduction {
  public:
    struct Outcome {
        int cellsMoved = 0;
        int turnsBefore = 0;
        int turnsAfter = 0;
    };

    TurnReduction(const SpanningTreeCoverage& coverage, int rounds) : coverage_(coverage), rounds_(rounds) {}

    // `paths` measured (measurePath): their turns are what it weighs.
    Outcome improve(const CellGraph& graph, RegionAllocation& regions, std::vector<CoveragePath>& paths,
                    const std::vector<MapPoint>& starts, const ProgressReporter& progress) const;

  private:
    const SpanningTreeCoverage& coverage_;
    int rounds_;
};

} // namespace mcpp
