#pragma once

#include "core/coverage/DetectionAccumulator.hpp"
#include "core/coverage/DetectionSegment.hpp"
#include "core/model/ProgressReporter.hpp"

#include <vector>

namespace mcpp {

// The greedy part of CPPIED (seed 001): round after round, the set of rows (or of columns, whichever
// gains more) at least a strip apart whose passes gain most towards the required probability, found by
// dynamic programming over the lines; each line gives every stretch where a pass gains. It stops when
// every target has reached the required probability.
class DetectionSegmentSelection {
  public:
    DetectionSegmentSelection(const DetectionModel& model, double requiredProbability)
        : model_(model), required_(requiredProbability) {}

    // own: by the accumulator's window index, 1 where the robot may drive and must see (classes of p0 0
    // are never targets). The passes chosen are added to `seen`.
    [[nodiscard]] std::vector<DetectionSegment>
    select(const std::vector<char>& own, DetectionAccumulator& seen, const ProgressReporter& progress) const;
    // Targets of `own` still below the required probability.
    [[nodiscard]] std::size_t unmetTargets(const std::vector<char>& own,
                                           const DetectionAccumulator& seen) const;

  private:
    struct Stretch {
        int first = 0;
        int last = 0;
    };
    struct LineGains {
        double total = 0.0;
        std::vector<Stretch> stretches;
    };
    // The targets still short, and the lines within reach of one (window rows and columns).
    struct UnmetLines {
        std::size_t targets = 0;
        std::vector<char> rows;
        std::vector<char> columns;
    };
    struct Round {
        double total = 0.0;
        bool horizontal = true;
        std::vector<int> lines;
        std::vector<LineGains> gains; // by line
    };

    [[nodiscard]] bool isTarget(const std::vector<char>& own, const DetectionAccumulator& seen,
                                LatticePosition position) const;
    [[nodiscard]] double passGain(const std::vector<char>& own, const DetectionAccumulator& seen,
                                  LatticePosition position, bool horizontal, double overlapPenalty) const;
    [[nodiscard]] LineGains lineGains(const std::vector<char>& own, const DetectionAccumulator& seen,
                                      int line, bool horizontal, double overlapPenalty) const;
    [[nodiscard]] Round bestRound(const std::vector<char>& own, const DetectionAccumulator& seen,
                                  const std::vector<char>& nearUnmet, bool horizontal,
                                  double overlapPenalty) const;
    [[nodiscard]] UnmetLines unmetLines(const std::vector<char>& own, const DetectionAccumulator& seen) const;
    [[nodiscard]] static bool isOwn(const std::vector<char>& own, const LatticeWindow& window, int line,
                                    int step, bool horizontal);
    [[nodiscard]] static LatticePosition along(const LatticeWindow& window, int line, int step,
                                               bool horizontal);

    const DetectionModel& model_;
    double required_;
};

} // namespace mcpp
