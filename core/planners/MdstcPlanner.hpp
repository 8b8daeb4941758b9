#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// MDSTC (seed 003) on the grid of 2 x Fd_min cells: regions grown from the starts, each robot planning its
// spanning-tree coverage as it drives (DSTC), and cells nobody has entered yet passed from the robots that
// will finish last to those that will finish first, while the mission's events slow robots down or stop
// them. Beside it, MCPP-MLCT's static plan run through the same events shows what re-allocation saved.
class MdstcPlanner final : public Planner {
  public:
    static constexpr const char* plannerName = "mdstc";

  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
