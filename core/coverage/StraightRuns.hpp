#pragma once

#include "core/coverage/RegionAdjacency.hpp"
#include "core/model/ProgressReporter.hpp"

#include <vector>

namespace mcpp {

// The fewest straight runs ("bricks", as in TMSTC*) a region's cells split into: each cell lies in one
// east-west or one north-south run of equal cells. Two straight adjacencies conflict when they meet at a
// cell from perpendicular sides; the largest conflict-free set of them is the complement of a minimum
// vertex cover of that bipartite graph (Konig), found by Hopcroft-Karp matching. The matching stops after
// 16 phases, so on maps of a million cells the set may fall a few runs short of the largest; it is always
// conflict-free.
// Returns, per adjacency of `adjacency`, whether it joins two cells of one run. A cancel request to
// `progress` (where given) stops it after the greedy matching and between the matching's phases: on a
// region of millions of cells they take seconds.
[[nodiscard]] std::vector<char> straightRuns(const RegionAdjacency& adjacency,
                                             const ProgressReporter* progress = nullptr);

} // namespace mcpp
