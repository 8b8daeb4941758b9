#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// Wavefront coverage on a battery (seed 002): the grid of 2 x Fd_min cells divided by the azimuth trend
// method, then per robot a wavefront walk from far to near in sorties that start and end at its charger
// (its start point), each within the battery's endurance, with a recharge between them.
class WavefrontBatteryPlanner : public Planner {
  public:
    static constexpr const char* plannerName = "wavefront-battery";

  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
