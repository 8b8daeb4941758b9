#pragma once

#include "core/model/Plan.hpp"

namespace mcpp {

// Fills plan.metrics from the quadtree, the allocation and the paths (spec section 6).
// Stage timings are left to the caller.
class PlanMetricsCalculator {
public:
    void compute(Plan& plan) const;
};

} // namespace mcpp
