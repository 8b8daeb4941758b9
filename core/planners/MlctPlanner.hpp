#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// MCPP-MLCT (Huang et al., IEEE Access 2020): hierarchical quadtree -> neighbour topology -> azimuth-trend
// allocation -> improved STC.
class MlctPlanner final : public Planner {
  public:
    static constexpr const char* plannerName = "mcpp-mlct";

  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
