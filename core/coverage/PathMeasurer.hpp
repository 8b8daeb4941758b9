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
    // sharedShape: a shape the caller adds the same points to, read for length and turns instead of one of
    // the measurer's own (a walk measured for its shape and its path at once adds each point once).
    explicit PathMeasurer(const CellGraph& graph, const PathShape* sharedShape = nullptr)
        : graph_(graph), oneCellSize_(graph.hasOneCellSize()), sharedShape_(sharedShape) {}

    void add(const Waypoint& waypoint);
    // Length, turns, time (with the path's pauses, by the path's waypoint numbers, so a path being made
    // has none), turn and connector seconds: measurePath's figures but the repeated visits.
    void fill(CoveragePath& path) const;
    [[nodiscard]] double connectorSeconds() const { return connectorSeconds_; }

  private:
    void addConnector(const Waypoint& from, const Waypoint& to, double length);

    const CellGraph& graph_;
    bool oneCellSize_;
    const PathShape* sharedShape_;
    PathShape shape_; // when no shape is shared
    PathSeconds seconds_;
    double connectorSeconds_ = 0.0;
    bool havePrevious_ = false;
    Waypoint previous_;
    std::optional<Direction> direction_;
};

} // namespace mcpp
