#pragma once

#include <algorithm>
#include <cstddef>

namespace mcpp {

// Figures over the targets: the lattice cells a robot covers whose land cover can be seen at all.
struct DetectionSummary {
    double requiredProbability = 0.0;
    double minimum = 0.0;
    double mean = 0.0;
    double shareMet = 0.0; // targets at or above the required probability
    std::size_t targets = 0;
    std::size_t unmetTargets = 0;
    double undetectableAreaSquareMetres = 0.0; // covered cells whose land cover has p0 = 0
    // Passes no plan seeing what this one sees makes fewer of: a target seen with C took passes whose
    // probabilities add up to at least C (C' - C <= p); counting min(C, D) per target, one pass sees at
    // most the strip's sum of the best class's probabilities.
    double passesNoPlanBeats = 0.0;
    double secondsPerStep = 0.0; // the quickest step between lattice centres: a cell at the top speed

    // Travel no plan beats, all robots together: a centre counts at most two passes, one unless the path
    // turns there (a quarter turn at least) or stays on it alone (once per robot at most), and each
    // robot's path has one step fewer than centres.
    [[nodiscard]] double travelSecondsNoPlanBeats(int turns, std::size_t robots) const {
        const auto robotCount = static_cast<double>(robots);
        const double centres = std::max(passesNoPlanBeats / 2.0, passesNoPlanBeats - turns - robotCount);
        const double steps = centres - robotCount;
        return steps > 0.0 ? steps * secondsPerStep : 0.0;
    }
};

} // namespace mcpp
