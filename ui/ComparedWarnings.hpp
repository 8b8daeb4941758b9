#pragma once

#include <string>
#include <vector>

namespace mcpp::ui {

// One compared plan's warnings.
struct PlannerWarnings {
    std::string planner;
    std::vector<std::string> warnings;
};

// A warning as the messages panel keeps it after a comparison: once, under the names of the planners whose
// plans carry it ("darp, mstc"), or under none where every plan of several carries it (the mission's own).
struct ComparedWarning {
    std::string planners; // empty: every plan carries it
    std::string text;
};

// Every warning of the compared plans once, in the order the plans and their warnings come.
[[nodiscard]] std::vector<ComparedWarning> comparedWarnings(const std::vector<PlannerWarnings>& plans);

} // namespace mcpp::ui
