#include "core/planners/PlannerRegistry.hpp"

#include "core/planners/MlctPlanner.hpp"

#include <functional>

namespace mcpp {
namespace {

using Factory = std::function<std::unique_ptr<Planner>()>;

template <typename PlannerType> Factory factory() {
    return [] { return std::make_unique<PlannerType>(); };
}

// One line per planner: adding a planner means its files, its tests and a line here.
const std::vector<Factory>& factories() {
    static const std::vector<Factory> all{
        factory<MlctPlanner>(),
    };
    return all;
}

} // namespace

std::vector<PlannerDescription> plannerDescriptions() {
    std::vector<PlannerDescription> descriptions;
    for (const Factory& make : factories())
        descriptions.push_back(make()->description());
    return descriptions;
}

std::vector<std::string> availablePlanners() {
    std::vector<std::string> names;
    for (const PlannerDescription& description : plannerDescriptions())
        names.push_back(description.name);
    return names;
}

const std::string& defaultPlannerName() {
    static const std::string name = MlctPlanner::plannerName;
    return name;
}

std::unique_ptr<Planner> makePlanner(const std::string& name) {
    const std::string& wanted = name.empty() ? defaultPlannerName() : name;
    for (const Factory& make : factories()) {
        auto planner = make();
        if (planner->description().name == wanted)
            return planner;
    }
    return nullptr;
}

} // namespace mcpp
