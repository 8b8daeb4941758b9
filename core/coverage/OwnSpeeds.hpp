#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/RegionAllocation.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// Robots that drive at their own speed over every passable class (PlanningProblem::robotSpeeds): an
// aircraft's cruise speed beside ground robots that take the class table's.

// Whether some robot has a speed of its own.
[[nodiscard]] bool someOwnSpeed(const std::vector<double>& speeds);
// The robot's own speed; 0 when it takes the class table's.
[[nodiscard]] double ownSpeedOf(const std::vector<double>& speeds, std::size_t robot);

// The path driven at `speed` over every cell: each waypoint carries it, turns cost what they cost at it,
// and the path is timed again (timePath; measured again by the metrics stage). Nothing changes at 0.
void driveAtOwnSpeed(CoveragePath& path, const CellGraph& graph, double speed);
// driveAtOwnSpeed for each path with its robot's speed.
void driveAtOwnSpeeds(std::vector<CoveragePath>& paths, const CellGraph& graph,
                      const std::vector<double>& speeds);

// By robot, the seconds it takes for a second of the cells' cover time (Cell::coverSeconds) over the graph:
// 1 at the class speeds; for a robot of its own speed, its travel over them (about 0.1 ten times as fast).
// A division balances robots' own times by costs times these: a first guess, which drivenPaces corrects.
[[nodiscard]] std::vector<double> robotPaces(const CellGraph& graph, const std::vector<double>& speeds,
                                             std::size_t robots);
// By robot, its path's time over its region's cover time: its pace as driven, its own speed and the turns
// its path made included.
[[nodiscard]] std::vector<double> drivenPaces(const CellGraph& graph, const RegionAllocation& regions,
                                              const std::vector<CoveragePath>& paths);

} // namespace mcpp
