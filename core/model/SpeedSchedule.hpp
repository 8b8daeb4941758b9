#pragma once

#include "core/model/SpeedEvent.hpp"

#include <utility>
#include <vector>

namespace mcpp {

// One robot's speed factor over time, from its events: 1 until the first, then each event's factor from
// its time on (of events at the same time, the last given holds).
class SpeedSchedule {
  public:
    SpeedSchedule() = default;
    SpeedSchedule(const std::vector<SpeedEvent>& events, int robot);

    [[nodiscard]] double factorAt(double seconds) const;
    // When a robot at `startSeconds` has done `nominalSeconds` of driving timed at full speed; infinity when
    // it stops for good before.
    [[nodiscard]] double finishTime(double startSeconds, double nominalSeconds) const;
    // Whether the factor is 0 from `seconds` on, for good.
    [[nodiscard]] bool stoppedFrom(double seconds) const;
    // The time of the first change after `seconds`, or infinity.
    [[nodiscard]] double nextChangeAfter(double seconds) const;

  private:
    std::vector<std::pair<double, double>> changes_; // (time, factor), ascending in time
};

} // namespace mcpp
