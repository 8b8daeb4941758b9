#include "core/planners/Planner.hpp"

#include "core/planners/MlctPlanner.hpp"

namespace mcpp {

std::vector<std::string> availablePlanners() { return {MlctPlanner::plannerName}; }

std::unique_ptr<Planner> makePlanner(const std::string& name) {
    if (name == MlctPlanner::plannerName || name.empty()) return std::make_unique<MlctPlanner>();
    return nullptr;
}

} // namespace mcpp
