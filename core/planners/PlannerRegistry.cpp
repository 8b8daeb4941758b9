#include "core/planners/PlannerRegistry.hpp"

#include "core/model/NameSuggestion.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/CppiedPlanner.hpp"
#include "core/planners/DarpPlanner.hpp"
#include "core/planners/DarpTurnsPlanner.hpp"
#include "core/planners/FullSpiralStcPlanner.hpp"
#include "core/planners/MdstcPlanner.hpp"
#include "core/planners/MlctPlanner.hpp"
#include "core/planners/MstcPlanner.hpp"
#include "core/planners/SpiralStcPlanner.hpp"
#include "core/planners/WavefrontBatteryPlanner.hpp"

#include <algorithm>
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
        factory<SpiralStcPlanner>(),
        factory<FullSpiralStcPlanner>(),
        factory<DarpPlanner>(),
        factory<DarpTurnsPlanner>(),
        factory<MstcPlanner>(),
        factory<WavefrontBatteryPlanner>(),
        factory<CppiedPlanner>(),
        factory<MdstcPlanner>(),
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

std::optional<PlannerDescription> findPlannerDescription(const std::string& name) {
    for (const PlannerDescription& description : plannerDescriptions())
        if (description.name == name)
            return description;
    return std::nullopt;
}

std::int64_t leastBytesPerBottomCell() {
    std::int64_t least = unmeasuredBytesPerBottomCell;
    for (const PlannerDescription& description : plannerDescriptions())
        least = std::min(least, description.bytesPerBottomCell);
    return least;
}

std::string unknownPlannerMessage(const std::string& name) {
    std::string known;
    for (const std::string& planner : availablePlanners())
        known += (known.empty() ? "" : ", ") + planner;
    const auto meant = closestName(name, availablePlanners());
    return "unknown planner \"" + name + "\"" +
           (meant ? ": did you mean \"" + *meant + "\"?" : std::string()) + " (available: " + known + ")";
}

const std::string& defaultPlannerName() {
    static const std::string name = MlctPlanner::plannerName;
    return name;
}

PlannerChoice defaultPlannerChoice(const std::string& name) {
    PlannerChoice choice;
    choice.planner = name.empty() ? defaultPlannerName() : name;
    if (const auto description = findPlannerDescription(choice.planner))
        choice.parameters = resolveParameters(description->parameters, {});
    return choice;
}

PlannerChoice switchPlanner(const PlannerChoice& current, const std::string& name) {
    PlannerChoice choice = defaultPlannerChoice(name);
    for (const auto& [key, value] : current.parameters.all())
        if (choice.parameters.has(key))
            choice.parameters.set(key, value);
    return choice;
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
