#include "core/planners/UnevenField.hpp"

#include "core/model/HumanUnits.hpp"
#include "core/planners/PlannerRegistry.hpp"

#include <sstream>

namespace mcpp {
namespace {

// Planners that even out time in the field, for the advice: "MCPP-MLCT (mcpp-mlct)".
std::string fieldBalancingPlanners() {
    std::string names;
    for (const PlannerDescription& other : plannerDescriptions())
        if (other.balancesFieldTime)
            names += (names.empty() ? "" : " or ") + other.label + " (" + other.name + ")";
    return names;
}

} // namespace

std::string unevenFieldMessage(const Plan& plan, const PlannerDescription& planner) {
    const PlanMetrics& metrics = plan.metrics;
    constexpr double noticeableSpread = 1.25;
    if (!(metrics.fieldSpread() >= noticeableSpread) || !metrics.confinedRobots.empty())
        return {};
    const auto [first, last] = metrics.firstAndLastHome();
    std::ostringstream spread;
    spread.precision(3);
    spread << metrics.fieldSpread();
    const std::string fact = "robot " + std::to_string(last->robot + 1) + " comes home after " +
                             formatDuration(last->fieldSeconds) + " in the field, " + spread.str() +
                             " times as long as robot " + std::to_string(first->robot + 1) + " (" +
                             formatDuration(first->fieldSeconds) + ")";
    const std::string nearer = "start robots nearer the land farthest from every start, or add robots";
    if (planner.balancesFieldTime)
        return fact + ": the division could not even out what they spend beside their paths (an aircraft's " +
               "trips out to its work and back, the turnarounds between parts); " + nearer;
    const std::string others = fieldBalancingPlanners();
    return fact + ": " + planner.label +
           " evens out the paths, not what the robots spend beside them (an aircraft's trips out to its "
           "work " +
           "and back, the turnarounds between parts); " +
           (others.empty() ? "" : "plan with " + others + ", which evens out time in the field, ") + nearer;
}

} // namespace mcpp
