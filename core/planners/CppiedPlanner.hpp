#pragma once

#include "core/planners/Planner.hpp"

namespace mcpp {

// Coverage with imperfect, extended detection (CPPIED, seed 001): the grid of 2 x Fd_min cells divided by
// the azimuth trend method, then per robot straight passes on the lattice of half cells chosen greedily
// until every target of its region is seen with the required probability, flown in the order of a tour
// over their ends. The plan carries a detection layer: the probability reached per lattice cell.
class CppiedPlanner : public Planner {
  public:
    static constexpr const char* plannerName = "cppied";

  protected:
    [[nodiscard]] PlannerDescription describe() const override;
    void run(PlanningRun& run) const override;
};

} // namespace mcpp
