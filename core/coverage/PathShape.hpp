#pragma once

#include <cstddef>

namespace mcpp {

// The length and turns of a polyline fed one point at a time: the one rule for turns (zero-length steps
// skipped, a U-turn counted once), used by countTurns and to compare two candidate walks without storing
// either. Points given with their speed and turn price also add up the time, as measurePath times a path.
class PathShape {
  public:
    void add(double x, double y) { add(x, y, 0.0, 0.0); }
    // speed: of the point's cell (0: untimed); turnSecondsPer90Degrees: what turning at this point costs.
    void add(double x, double y, double speedMetresPerSecond, double turnSecondsPer90Degrees);
    [[nodiscard]] int turns() const { return turns_; }
    [[nodiscard]] double lengthMetres() const { return length_; }
    // Travel and turning, when every point came with a speed.
    [[nodiscard]] double seconds() const { return seconds_; }
    // The part of seconds() spent turning.
    [[nodiscard]] double turningSeconds() const { return turningSeconds_; }
    [[nodiscard]] std::size_t points() const { return points_; }

  private:
    bool havePoint_ = false;
    double lastX_ = 0.0;
    double lastY_ = 0.0;
    bool haveDirection_ = false;
    double directionX_ = 0.0;
    double directionY_ = 0.0;
    double lastSpeed_ = 0.0;
    double lastTurnPrice_ = 0.0;
    double seconds_ = 0.0;
    double turningSeconds_ = 0.0;
    int turns_ = 0;
    double length_ = 0.0;
    std::size_t points_ = 0;
};

// Walks compared by time (travel and turns at their cells' price), then turns, then length: where turns are
// free (turn_s 0), the one that turns less. Times within a billionth of each other are the same time
// summed in another order, not a quicker walk.
[[nodiscard]] bool isQuicker(const PathShape& walk, const PathShape& than);

} // namespace mcpp
