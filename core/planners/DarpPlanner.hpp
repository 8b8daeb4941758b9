#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// DARP (Kapoutsis et al.) on the grid of 2 x Fd_min cells: regions divided by DARP so each robot's cover time
// is about equal, then spanning-tree coverage per region, keeping for each robot the tree (east-west or
// north-south spines) whose path turns least.
class DarpPlanner : public Planner {
  public:
    static constexpr const char* plannerName = "darp";

  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
    // DARP's regions and their paths, timed only: run() without the last search for fewer turns.
    void planRegionsAndPaths(PlanningRun& run) const;
    // The last stage, "turn search" (TurnSearch), with the rounds of turn_search_rounds.
    void searchTurns(PlanningRun& run) const;
};

} // namespace mcpp
