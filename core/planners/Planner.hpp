#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/planners/PlannerDescription.hpp"

namespace mcpp {

class PlanningRun;

// A complete coverage planner: problem in, plan out. The base class does what every planner needs the same
// way: it checks the starts, times each stage, measures the paths, computes the figures and reports cells no
// robot can reach; a planner adds its own steps in run(). Throws PlanningError on bad input.
class Planner {
  public:
    virtual ~Planner() = default;
    [[nodiscard]] virtual PlannerDescription description() const = 0;
    [[nodiscard]] std::string name() const { return description().name; }
    [[nodiscard]] Plan plan(const PlanningProblem& problem, const ProgressReporter& progress) const;

  protected:
    // Fills the run's plan: its cells, regions and paths (waypoints; measuring is done afterwards).
    virtual void run(PlanningRun& run) const = 0;
};

} // namespace mcpp
