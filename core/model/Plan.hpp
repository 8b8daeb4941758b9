#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/PixelRuns.hpp"
#include "core/model/PlanIssue.hpp"
#include "core/model/PlanLayer.hpp"
#include "core/model/PlanMetrics.hpp"
#include "core/model/RegionAllocation.hpp"
#include "core/parameters/ParameterValues.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcpp {

// What any planner produced, in terms every reader understands: the cells, who covers which, the paths,
// the figures and what the user should know. Exporters, the renderer and the invariant checks read only this.
struct Plan {
    std::string planner;
    ParameterValues parameters; // every parameter the plan was made with, defaults filled in
    CellGraph cells;
    RegionAllocation regions;
    std::vector<CoveragePath> paths; // by robot
    // By robot, its own speed over every passable class in m/s; missing or 0: the class table's speeds
    // (PlanningProblem::robotSpeeds). Its path's waypoints carry it, and the lower bound counts it.
    std::vector<double> robotSpeeds;
    // By robot, the field seconds a second of its path takes that the planner's division already counted
    // (an aircraft's trips out to its work); empty or 0: none. Rounds balancing time in the field measure
    // their paces against it.
    std::vector<double> countedFieldPaces;
    PlanMetrics metrics;
    // Passable land left out of the task area beyond every flight's reach (LandBeyondReach): it has no cells,
    // yet exports and pictures show it with the land no robot covers.
    PixelRuns landBeyondReach;
    std::vector<PlanIssue> issues;
    std::vector<std::shared_ptr<const PlanLayer>> layers;

    [[nodiscard]] std::vector<std::string> warnings() const {
        std::vector<std::string> messages;
        for (const PlanIssue& issue : issues)
            if (issue.severity == IssueSeverity::Warning)
                messages.push_back(issue.message);
        return messages;
    }
};

} // namespace mcpp
