#include "core/coverage/BlockedSubCellDetours.hpp"

#include <cstdlib>

namespace mcpp {

std::vector<Waypoint> avoidBlockedSubCells(const SubCellLattice& lattice, const std::vector<Waypoint>& walk) {
    std::vector<Waypoint> result;
    result.reserve(walk.size());
    std::optional<SubCellLattice::Position> previous;
    for (const Waypoint& waypoint : walk) {
        const auto position = lattice.at({waypoint.x, waypoint.y});
        if (!position || !lattice.isFree(*position) || (previous && *previous == *position))
            continue;
        const bool sideBySide =
            previous && std::abs(previous->x - position->x) + std::abs(previous->y - position->y) <= 1;
        if (previous && !sideBySide) {
            std::vector<SubCellLattice::Position> way = lattice.shortestWay(*previous, *position);
            if (!way.empty())
                way.pop_back(); // the target itself follows
            for (const auto& step : way)
                result.push_back(lattice.waypointAt(step));
        }
        result.push_back(lattice.waypointAt(*position));
        previous = position;
    }
    return result;
}

} // namespace mcpp
