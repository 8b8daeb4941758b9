#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// Leaves out the waypoints inside a path's straight runs as the path is fed one waypoint at a time (the
// rule mergeStraightRuns states): a walk of millions of cells is merged as it is made, and only what is
// kept is ever held.
class StraightRunMerger {
  public:
    explicit StraightRunMerger(const CellGraph& graph) : graph_(graph) {}

    void add(const Waypoint& waypoint);
    // Puts the kept waypoints into `path`, with walkedWaypoints and runFollows when a run was merged; a
    // path of no straight run gets every waypoint and stays unmerged. The merger then starts afresh.
    void finishInto(CoveragePath& path);
    // Waypoints kept so far (one more is kept when the walk finishes).
    [[nodiscard]] std::size_t keptCount() const { return kept_.size(); }

  private:
    void keep(const Waypoint& waypoint, std::size_t index);

    const CellGraph& graph_;
    std::vector<Waypoint> kept_;
    std::vector<bool> runFollows_;
    std::size_t walked_ = 0;
    std::size_t lastKept_ = 0; // the walk's index of the last waypoint kept
    Waypoint beforePrevious_;
    Waypoint previous_;
};

} // namespace mcpp
