#pragma once

#include "core/model/Plan.hpp"

namespace mcpp {

// Fills plan.metrics and the regions' costs from the cell graph, the regions and the measured paths
// (spec section 6). Stage timings are left as they are.
class PlanMetricsCalculator {
  public:
    void compute(Plan& plan) const;

  private:
    // Raises the lower bound to what the robots of each connected part need (robots of one speed only) and
    // lists confined robots;
    // `regionsLinked`: the regions link every robot (regionsLinkEveryRobot), so the map is one part.
    static void boundByConnectedParts(Plan& plan, bool regionsLinked);
    // The bound where some robots drive at their own speeds (Plan::robotSpeeds): no plan beats the weighted
    // mean, by each robot's share of what the fleet does in a second, of what each robot must do.
    static void boundWithOwnSpeeds(Plan& plan);
    // Raises the lower bound by the charges a robot on a battery must make to fly it.
    static void boundByCharges(Plan& plan);
};

} // namespace mcpp
