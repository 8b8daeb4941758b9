#pragma once

#include "core/decomposition/LandCoverSamples.hpp"
#include "core/model/ClassTable.hpp"
#include "core/parameters/PlannerChoice.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::io {

// How much work a mission is, counted from the land cover before any planning: what a user should hear
// before waiting minutes for a plan of tens of millions of cells.
struct MissionScale {
    double passableSquareMetres = 0.0;
    // Squares of each class's field of view over its land (the smallest FOV's over all of it for planners on
    // a uniform grid): the places a path passes, which planning time and output size follow.
    double coveragePoints = 0.0;
    double smallestFieldOfViewMetres = 0.0;
    std::string smallestFieldOfViewClass;
    // Each class's land swept in strips as wide as its FOV at its speed, shared by the robots: no plan at the
    // class table's speeds is done sooner. 0 without robots.
    double sweepSeconds = 0.0;
    int planners = 1; // that plan it, one after the other

    // The factor on every FOV that brings the points down to `points` (two significant digits, rounded up);
    // 1 where they are no more already.
    [[nodiscard]] double fieldOfViewFactorFor(double points) const;
};

// From the raster's class counts (the area of interest applied) and the table's passable classes, for the
// planners given (counted on a uniform grid where one of them plans on it; a planner's bad parameters are
// left to planningProblem to say).
[[nodiscard]] MissionScale missionScale(const LoadedRaster& raster, const ClassTable& classes,
                                        std::size_t robots, const std::vector<PlannerChoice>& planners);

// What planning with `choice` needs against the memory allowed, counted as the planner's guard counts it:
// the smallest rounded FOV of the passable classes present, the quadtree's levels (1 on a uniform grid) and
// the planner's bytes per smallest cell. Nothing where no passable class is present.
struct PlanningMemory {
    CellBudgetEstimate estimate;
    double smallestFieldOfViewMetres = 0.0;
    int levels = 1;
};
[[nodiscard]] std::optional<PlanningMemory>
planningMemory(const LoadedRaster& raster, const ClassTable& classes, const PlannerChoice& choice);

// Past this many points MCPP-MLCT plans for a minute or more (tens of millions of places on a uniform map
// take it about that; mixed land cover, longer), and the planners on uniform grids take several times its
// time: a comparison is said to be large at a quarter of it.
inline constexpr double largeMissionPoints = 20e6;
[[nodiscard]] double largeMissionPointsFor(int planners);

// A warning where the mission is large (more points than largeMissionPointsFor): the points, the area, the
// smallest FOV, the planners it is planned by and, where the robots move at the table's speeds, the least
// time any plan takes; ends with what `remedy` names for the factor on every FOV that brings the points to
// that count (a flag, or the window's command).
[[nodiscard]] std::optional<std::string>
largeMissionWarning(const MissionScale& scale, bool atTableSpeeds,
                    const std::function<std::string(double factor)>& remedy);

// The same for a mission's robots, timed at the table's speeds where none has a cruise speed of its own; not
// said where some planner cannot plan it in the memory allowed (its guard says so, and that is all).
[[nodiscard]] std::optional<std::string>
largeMissionWarning(const Mission& mission, const LoadedRaster& raster, const ClassTable& classes,
                    const std::vector<PlannerChoice>& planners,
                    const std::function<std::string(double factor)>& remedy);

} // namespace mcpp::io
