#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/planners/PlannerDescription.hpp"

#include <optional>
#include <vector>

namespace mcpp {

class PlanningRun;
struct LandBeyondReach;

// A complete coverage planner: problem in, plan out. The base class does what every planner needs the same
// way: it checks the starts, times each stage, measures the paths, computes the figures and reports cells no
// robot can reach; a planner adds its own steps in run(). Throws PlanningError on bad input.
class Planner {
  public:
    virtual ~Planner() = default;
    // The planner's own description, with the parameters every planner has added to its own.
    [[nodiscard]] PlannerDescription description() const;
    [[nodiscard]] std::string name() const { return describe().name; }
    [[nodiscard]] Plan plan(const PlanningProblem& problem, const ProgressReporter& progress) const;
    // The same with parameters given here instead of the problem's (a planner that runs another beside it).
    [[nodiscard]] Plan plan(const PlanningProblem& problem, const ParameterValues& given,
                            const ProgressReporter& progress) const;

    // Parameters the base class reads for every planner.
    [[nodiscard]] static ParameterSpec snapStartsParameter();

  protected:
    [[nodiscard]] virtual PlannerDescription describe() const = 0;
    // Fills the run's plan: its cells, regions and paths (waypoints; measuring is done afterwards).
    virtual void run(PlanningRun& run) const = 0;

  private:
    // What a round of evening out time in the field hands to its plan: each robot's field pace
    // (PlanningRun::fieldPaces), the paces the plan before took in the field (to be said), where the
    // rounds keep the cells the first built, and whether cells are weighed by trips
    // (PlanningRun::tripsWeighed).
    struct FieldRound {
        std::vector<double> paces;
        std::vector<double> measuredPaces;
        std::optional<CellGraph>* cells = nullptr;
        bool tripsWeighed = true;
    };
    // Plans the problem as given: in rounds where the planner evens out time in the field.
    [[nodiscard]] Plan planWithin(const PlannerDescription& planner, const PlanningProblem& problem,
                                  const ParameterValues& given, const ProgressReporter& progress) const;
    // The same within the reach of the fleet's flights (problem: with the land beyond flagged), saying the
    // reach where nothing is left to plan.
    [[nodiscard]] Plan planWithinReach(const PlannerDescription& planner, const PlanningProblem& problem,
                                       const ParameterValues& given, const ProgressReporter& progress,
                                       const LandBeyondReach& beyond) const;
    // One plan of the problem, as a round of evening out time in the field where `round` says so.
    [[nodiscard]] Plan planOnce(const PlannerDescription& planner, const PlanningProblem& problem,
                                const ParameterValues& given, const ProgressReporter& progress,
                                FieldRound round) const;
    // Plans again while evening out the robots' time in the field (PlanningProblem::fieldSeconds) brings
    // the last robot home sooner.
    [[nodiscard]] Plan planInFieldTime(const PlannerDescription& planner, const PlanningProblem& problem,
                                       const ParameterValues& given, const ProgressReporter& progress) const;
};

} // namespace mcpp
