#pragma once

#include "core/planners/DarpPlanner.hpp"

namespace mcpp {

// DARP with turn reduction (seed 004): DARP's regions and paths, then end shapes change hands between
// regions where that lowers the number of turns (see TurnReduction).
class DarpTurnsPlanner final : public DarpPlanner {
  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
