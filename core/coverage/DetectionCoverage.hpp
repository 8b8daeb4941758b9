#pragma once

#include "core/coverage/DetectionLattice.hpp"
#include "core/coverage/DetectionModel.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/ProgressReporter.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// CPPIED for one robot's region (seed 001): straight passes chosen greedily until every target of the
// region is seen with the required probability, flown in the order of a tour over their ends and joined
// by the quickest ways between them through the region. What the finished path sees is measured again,
// turns and joining legs included; passes for whatever is still short are flown after the rest.
class DetectionCoverage {
  public:
    DetectionCoverage(const CellGraph& graph, const DetectionLattice& lattice, const DetectionModel& model,
                      double requiredProbability)
        : graph_(graph), lattice_(lattice), model_(model), required_(requiredProbability) {}

    // cells: the robot's region, holding startCell, of a single-level grid. The path is not yet measured;
    // it is open: it ends after its last pass.
    [[nodiscard]] CoveragePath cover(int robot, const std::vector<int>& cells, int startCell, MapPoint start,
                                     const ProgressReporter& progress) const;

  private:
    const CellGraph& graph_;
    const DetectionLattice& lattice_;
    const DetectionModel& model_;
    double required_;
};

} // namespace mcpp
