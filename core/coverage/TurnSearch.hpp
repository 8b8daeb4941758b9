#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"
#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

#include <vector>

namespace mcpp {

// The last step for fewer turns: each region's turn-minimising tree built again with its search across
// plateaus of equal turns (TurnMinimisingTree::Options::plateauRounds), and the region's path replaced where
// the new walk is quicker, or as quick and turns less. It comes after the balancing steps, whose many
// replans stay cheap; no path gets slower (beyond rounding), so neither does the makespan. Regions whose
// cells differ in size are left as they are: there the tree weighs time, not turns.
class TurnSearch {
  public:
    TurnSearch(bool closedTour, int rounds) : closedTour_(closedTour), rounds_(rounds) {}

    [[nodiscard]] static ParameterSpec roundsParameter();
    // The rounds to run on this map of those turn_search_rounds asks for: at most 160 000 / cells, at
    // least one, and none above 2 million cells.
    [[nodiscard]] static int roundsFor(const CellGraph& graph, const ParameterValues& parameters);
    // The search a planner with the closed_tour and turn_search_rounds parameters runs on this map.
    [[nodiscard]] static TurnSearch forPlan(const CellGraph& graph, const ParameterValues& parameters);

    // Returns the paths made quicker. Each is timed (timePath), as the waypoints stage leaves them.
    int improve(const CellGraph& graph, const RegionAllocation& regions, std::vector<CoveragePath>& paths,
                const std::vector<MapPoint>& starts, const ProgressReporter& progress) const;

    // By robot, its own speed (PlanningProblem::robotSpeeds): a new path is timed at it, as the one it may
    // replace was. Empty (the default): the class table's speeds.
    void setRobotSpeeds(std::vector<double> speeds) { robotSpeeds_ = std::move(speeds); }

  private:
    bool closedTour_;
    int rounds_;
    std::vector<double> robotSpeeds_;
};

} // namespace mcpp
