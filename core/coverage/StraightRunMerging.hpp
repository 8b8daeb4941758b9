#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <vector>

namespace mcpp {

// How many waypoints a walk may pass per cell of the map at most: a walk passes each of a cell's four
// sub-cell centres about once; a count beyond this is no walk of the map (a damaged plan file).
inline constexpr std::size_t mostWalkedWaypointsPerCell = 8;

// A measured path with the waypoints inside its straight runs left out: a waypoint stays where the path
// turns, begins or ends, where the speed, the cell size or the land cover changes on either side of it, and
// off sub-cell steps (a point outside the graph, a step of no length). What is left times, measures and
// exports as the whole path does (its turning points, speed changes and steps between sizes are all kept), in
// a small part of the memory: on a one-class map a waypoint in a few hundred. A path with pauses is left
// whole, as they are numbered by waypoint. Sets path.walkedWaypoints and path.runFollows.
void mergeStraightRuns(CoveragePath& path, const CellGraph& graph);

// Every sub-cell centre a path passes: its waypoints, with those mergeStraightRuns left out put back,
// evenly spaced along each merged run (path.runFollows) at half its cells' side, each in its cell.
[[nodiscard]] std::vector<Waypoint> walkedWaypoints(const CoveragePath& path, const CellGraph& graph);

// The path with every sub-cell centre it passes (walkedWaypoints), its measures as they are: for an export
// asked for every waypoint.
[[nodiscard]] CoveragePath withEveryWaypoint(const CoveragePath& path, const CellGraph& graph);

} // namespace mcpp
