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

// Each waypoint of the path carries `speed` (its turns then cost what they cost at it); nothing at 0. The
// caller measures or times the path.
void setOwnSpeed(CoveragePath& path, double speed);
// The path driven at `speed` over every cell: setOwnSpeed, and the path timed again (timePath; measured again
// by the metrics stage). A path whose straight runs are merged keeps no steps between cells of different
// sizes to time: its connector time is scaled by its travel's, exact where the land covers share a speed.
void driveAtOwnSpeed(CoveragePath& path, const CellGraph& graph, double speed);
// driveAtOwnSpeed for each path with its robot's speed.
void driveAtOwnSpeeds(std::vector<CoveragePath>& paths, const CellGraph& graph,
                      const std::vector<double>& speeds);

// By robot, the seconds it takes for a second of the cells' cover time (Cell::coverSeconds) over the graph:
// 1 at the class speeds; for a robot of its own speed, its travel over them (about 0.1 for a robot ten times
// as fast).
// A division balances robots' own times by costs times these: a first guess, which drivenPaces corrects.
[[nodiscard]] std::vector<double> robotPaces(const CellGraph& graph, const std::vector<double>& speeds,
                                             std::size_t robots);
// By robot, its path's time over its region's cover time: its pace as driven, its own speed and the turns
// its path made included; `guessed` (robotPaces) for a robot with no cells.
[[nodiscard]] std::vector<double> drivenPaces(const CellGraph& graph, const RegionAllocation& regions,
                                              const std::vector<CoveragePath>& paths,
                                              const std::vector<double>& guessed);
// A robot's pace, 1 where none is given.
[[nodiscard]] inline double paceOf(const std::vector<double>& paces, std::size_t robot) {
    return robot < paces.size() ? paces[robot] : 1.0;
}
// Whether some robot spends more (or less) time in the field than on its path (PlanningRun::fieldPaces).
[[nodiscard]] bool someFieldPace(const std::vector<double>& fieldPaces);
// The robot's field pace; 1 where none is given.
[[nodiscard]] double fieldPaceOf(const std::vector<double>& fieldPaces, std::size_t robot);
// `paces` (empty: 1 each) times each robot's field pace, for `robots` robots.
[[nodiscard]] std::vector<double> withFieldPaces(const std::vector<double>& paces,
                                                 const std::vector<double>& fieldPaces, std::size_t robots);
// The path's time in the field: its time times its robot's field pace.
[[nodiscard]] double fieldSeconds(const CoveragePath& path, const std::vector<double>& fieldPaces);

} // namespace mcpp
