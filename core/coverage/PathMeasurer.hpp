#pragma once

#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathShape.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <optional>

namespace mcpp {

// Measures a path fed one waypoint at a time: its length and turns (PathShape), its time as pathSeconds
// adds it up and its connector time as connectorSeconds does, in the same order of sums, so the figures
// are those of the whole path bit for bit. A walk of hundreds of millions of waypoints is measured this
// way without being held.
class PathMeasurer {
  public:
    // tracksShape false: the caller follows the same points' shape and gives it to fill (a walk measured
    // for its shape and its path at once adds each point to one shape, not two).
    explicit PathMeasurer(const CellGraph& graph, bool tracksShape = true)
        : graph_(graph), oneCellSize_(graph.hasOneCellSize()), tracksShape_(tracksShape) {}

    void add(const Waypoint& waypoint);
    // Length, turns, time (with the path's pauses, by the path's waypoint numbers, so a path being made
    // has none), turn and connector seconds: measurePath's figures but the repeated visits.
    void fill(CoveragePath& path) const { fill(path, shape_); }
    // fill, with the length and turns of `shape`: that of the points added, when not tracked here.
    void fill(CoveragePath& path, const PathShape& shape) const;
    [[nodiscard]] double connectorSeconds() const { return connectorSeconds_; }

  private:
    void addConnector(const Waypoint& from, const Waypoint& to, double length);

    const CellGraph& graph_;
    bool oneCellSize_;
    bool tracksShape_;
    PathShape shape_;
    PathSeconds seconds_;
    double connectorSeconds_ = 0.0;
    bool havePrevious_ = false;
    Waypoint previous_;
    std::optional<Direction> direction_;
};

} // namespace mcpp
