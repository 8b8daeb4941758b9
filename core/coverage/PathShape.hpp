#pragma once

#include <cstddef>

namespace mcpp {

// The length and turns of a polyline fed one point at a time: the one rule for turns (zero-length steps
// skipped, a U-turn counted once), used by countTurns and to compare two candidate walks without storing
// either.
class PathShape {
  public:
    void add(double x, double y);
    [[nodiscard]] int turns() const { return turns_; }
    [[nodiscard]] double lengthMetres() const { return length_; }
    [[nodiscard]] std::size_t points() const { return points_; }

  private:
    bool havePoint_ = false;
    double lastX_ = 0.0;
    double lastY_ = 0.0;
    bool haveDirection_ = false;
    double directionX_ = 0.0;
    double directionY_ = 0.0;
    int turns_ = 0;
    double length_ = 0.0;
    std::size_t points_ = 0;
};

} // namespace mcpp
