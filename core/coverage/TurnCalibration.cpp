#include "core/coverage/TurnCalibration.hpp"

#include <algorithm>

namespace mcpp {

bool calibrateTurnRates(CellGraph& graph, const RegionAllocation& regions,
                        const std::vector<double>& turningSecondsByRobot) {
    const std::size_t robots = std::min(regions.startCell.size(), turningSecondsByRobot.size());
    const auto robotOf = [&](std::size_t id) {
        const int robot = id < regions.robotOfCell.size() ? regions.robotOfCell[id] : -1;
        return robot >= 0 && static_cast<std::size_t>(robot) < robots ? static_cast<std::size_t>(robot)
                                                                      : robots;
    };
    // Per robot: what one quarter turn per sub-cell would cost over its region, then its path's rate.
    std::vector<double> rates(robots + 1, 0.0);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        rates[robotOf(id)] += cell.freeSubCellCount() * double(cell.turnSecondsPer90Degrees);
    }
    for (std::size_t robot = 0; robot < robots; ++robot)
        rates[robot] = rates[robot] > 0.0 ? turningSecondsByRobot[robot] / rates[robot] : -1.0;
    rates[robots] = -1.0; // cells of no region keep their rate
    std::vector<float> cellRates;
    cellRates.reserve(graph.size());
    bool changed = false;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const float own = graph.cell(static_cast<int>(id)).expectedTurnsPerSubCell;
        const double measured = rates[robotOf(id)];
        cellRates.push_back(measured >= 0.0 ? static_cast<float>(measured) : own);
        changed = changed || cellRates.back() != own;
    }
    graph.setExpectedTurns(cellRates);
    return changed;
}

} // namespace mcpp
