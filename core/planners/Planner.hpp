#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/ProgressReporter.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcpp {

// A complete coverage planner: problem in, plan out. Throws PlanningError on bad input.
class Planner {
public:
    virtual ~Planner() = default;
    [[nodiscard]] virtual std::string name() const = 0;
    [[nodiscard]] virtual Plan plan(const PlanningProblem& problem, const ProgressReporter& progress) const = 0;
};

// The planners this build offers, by the names used on the command line and in mission files.
[[nodiscard]] std::vector<std::string> availablePlanners();
// Nullptr when the name is unknown.
[[nodiscard]] std::unique_ptr<Planner> makePlanner(const std::string& name);

} // namespace mcpp
