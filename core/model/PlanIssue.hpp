#pragma once

#include <string>

namespace mcpp {

enum class IssueSeverity { Information, Warning };

// Something a user should know about a plan, with a stable code for scripts and a sentence for people.
struct PlanIssue {
    IssueSeverity severity = IssueSeverity::Warning;
    std::string code;    // e.g. "start-moved", "unreachable-area"
    std::string message; // one sentence naming the robot, place or figure concerned

    friend bool operator==(const PlanIssue&, const PlanIssue&) = default;
};

} // namespace mcpp
