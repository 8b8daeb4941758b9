#include "core/planners/ClosedInStart.hpp"

#include <set>
#include <unordered_map>
#include <unordered_set>

namespace mcpp {

std::optional<ClosedInStart> closedInStart(const Plan& plan, int robot, double enoughSeconds) {
    const std::vector<int>& startCells = plan.regions.startCell;
    if (static_cast<std::size_t>(robot) >= startCells.size() || startCells.size() != plan.paths.size())
        return std::nullopt;
    std::unordered_map<int, int> robotStartingAt;
    for (std::size_t other = 0; other < startCells.size(); ++other)
        robotStartingAt.emplace(startCells[other], static_cast<int>(other));
    const int start = startCells[static_cast<std::size_t>(robot)];
    std::vector<int> queue{start};
    std::unordered_set<int> seen{start};
    std::set<int> closedBy;
    ClosedInStart closed;
    closed.robot = robot;
    double seconds = 0.0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Cell& cell = plan.cells.cell(queue[head]);
        seconds += cell.coverSeconds();
        closed.areaSquareMetres += cell.passableAreaSquareMetres;
        if (seconds >= enoughSeconds)
            return std::nullopt;
        for (const int next : plan.cells.neighbours(queue[head])) {
            if (!seen.insert(next).second)
                continue;
            if (const auto other = robotStartingAt.find(next); other != robotStartingAt.end())
                closedBy.insert(other->second);
            else
                queue.push_back(next);
        }
    }
    if (closedBy.empty()) // a pocket of its own, which confined-robot names
        return std::nullopt;
    closed.closedBy.assign(closedBy.begin(), closedBy.end());
    return closed;
}

} // namespace mcpp
