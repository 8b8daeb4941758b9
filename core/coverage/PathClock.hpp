#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <vector>

namespace mcpp {

// A path as it grows, timed as pathSeconds will time it (same formulas, same order of sums):
// a planner that must keep within a time, a battery's, asks it what the next point would cost.
class PathClock {
  public:
    explicit PathClock(const CellGraph& graph) : graph_(graph) {}

    [[nodiscard]] const std::vector<Waypoint>& waypoints() const { return waypoints_; }
    [[nodiscard]] std::vector<Waypoint> take() { return std::move(waypoints_); }
    [[nodiscard]] double elapsed() const { return elapsed_; }
    [[nodiscard]] std::size_t lastIndex() const { return waypoints_.size() - 1; }
    // The turn at the last point and the travel to `next`.
    [[nodiscard]] double secondsToAppend(const Waypoint& next) const;
    void append(const Waypoint& next);

  private:
    struct Step {
        double turn = 0.0;
        double travel = 0.0;
    };
    [[nodiscard]] Step stepTo(const Waypoint& next) const;

    const CellGraph& graph_;
    std::vector<Waypoint> waypoints_;
    double elapsed_ = 0.0;
    bool haveDirection_ = false; // a step of positive length was made
    double directionX_ = 0.0;
    double directionY_ = 0.0;
};

} // namespace mcpp
