#pragma once

#include "core/allocation/RegionAllocator.hpp"
#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// DARP, Divide Areas based on Robots' initial Positions (Kapoutsis et al., seed 004). Each robot has an
// evaluation matrix E_r over the cells (here: travel time from its start, stepping eight ways through the
// cell graph, so land cover counts); every cell goes to the robot with the smallest E_r. Each round
// multiplies the E_r by correction factors that shrink regions above their fair share and grow those below
// (chosen together, as one Newton step on DARP's dual), and, for a region in pieces, by a connectivity term
// that pulls it towards the piece holding its start. Shares are cover times, not cell counts, so regions
// balance time. It stops when every region is connected and within the tolerance of its share, at the
// iteration cap, or when rounds stop improving; a border exchange (BorderExchange) then settles the cells
// the factors cannot place.
class DarpAllocator final : public RegionAllocator {
  public:
    struct Options {
        int maxIterations = 4000;
        double tolerance = 0.005;         // of the fair share; never finer than one cell
        double connectivityWeight = 0.01; // strength of the connectivity term (DARP's CCvariation)
        double randomLevel = 0.0001;      // noise that breaks ties between equal evaluations
        std::uint32_t seed = 1;

        [[nodiscard]] static std::vector<ParameterSpec> parameters();
        [[nodiscard]] static Options from(const ParameterValues& values);
    };

    // What the last allocation did, for the plan's issues.
    struct Outcome {
        int iterations = 0;
        bool converged = true;
        double largestShareError = 0.0; // largest |region cost - fair share| / fair share
    };

    explicit DarpAllocator(Options options) : options_(options) {}

    [[nodiscard]] RegionAllocation allocate(const CellGraph& graph, const std::vector<int>& startCells,
                                            const ProgressReporter& progress) const override;
    [[nodiscard]] const Outcome& outcome() const { return outcome_; }

  private:
    Options options_;
    mutable Outcome outcome_;
};

} // namespace mcpp
