#include "ui/ComparedWarnings.hpp"

#include <map>
#include <set>

namespace mcpp::ui {

std::vector<ComparedWarning> comparedWarnings(const std::vector<PlannerWarnings>& plans) {
    std::map<std::string, std::vector<std::string>> carriers;
    for (const PlannerWarnings& plan : plans)
        for (const std::string& warning : std::set<std::string>(plan.warnings.begin(), plan.warnings.end()))
            carriers[warning].push_back(plan.planner);
    std::vector<ComparedWarning> said;
    std::set<std::string> seen;
    for (const PlannerWarnings& plan : plans)
        for (const std::string& warning : plan.warnings) {
            if (!seen.insert(warning).second)
                continue;
            const std::vector<std::string>& by = carriers[warning];
            std::string names;
            if (plans.size() == 1 || by.size() < plans.size())
                for (const std::string& planner : by)
                    names += (names.empty() ? "" : ", ") + planner;
            said.push_back({names, warning});
        }
    return said;
}

} // namespace mcpp::ui
