#pragma once

#include "core/coverage/DetectionLattice.hpp"
#include "core/coverage/DetectionModel.hpp"
#include "core/model/CoveragePath.hpp"

#include <vector>

namespace mcpp {

// The chance a target in each lattice cell of a window has been seen, pass by pass: C' = C + (1 - C) p,
// p from the detection model at the cell's lateral offset (seed 001).
class DetectionAccumulator {
  public:
    DetectionAccumulator(const DetectionLattice& lattice, const CellGraph& graph, const DetectionModel& model,
                         LatticeWindow window);

    // One pass over `position` heading east-west (horizontal) or north-south: it sees the cells beside it
    // in the other direction, up to the model's reach.
    void addPass(LatticePosition position, bool horizontal);
    // Every pass a path makes over lattice centres: where it goes straight, one in its heading; where it
    // turns, one in each heading (it sweeps both); at its ends, one in the heading of its only step; a
    // path that stays on one centre, one in each. The start point off every centre makes no pass.
    void addPath(const CoveragePath& path);

    [[nodiscard]] const LatticeWindow& window() const { return window_; }
    [[nodiscard]] double at(LatticePosition position) const { return probability_[window_.index(position)]; }
    [[nodiscard]] const std::vector<double>& probabilities() const { return probability_; }
    // The detection profile of the land cover at a window index, or DetectionModel::noProfile where no
    // free sub-cell lies.
    [[nodiscard]] int profileAt(std::size_t index) const { return profile_[index]; }
    [[nodiscard]] const DetectionModel& model() const { return model_; }

  private:
    const DetectionLattice& lattice_;
    const DetectionModel& model_;
    LatticeWindow window_;
    std::vector<double> probability_;
    std::vector<int> profile_;
};

} // namespace mcpp
