#include "core/coverage/TurnCalibration.hpp"

namespace mcpp {

bool calibrateTurnRates(CellGraph& graph, const RegionAllocation& regions,
                        const std::vector<CoveragePath>& paths) {
    const std::size_t robots = regions.startCell.size();
    // Per robot: turn seconds the path spent, and what one turn per sub-cell would cost over its region.
    std::vector<double> pricedSubCells(robots, 0.0);
    for (std::size_t id = 0; id < graph.size() && id < regions.robotOfCell.size(); ++id) {
        const int robot = regions.robotOfCell[id];
        if (robot < 0 || static_cast<std::size_t>(robot) >= robots)
            continue;
        const Cell& cell = graph.cell(static_cast<int>(id));
        pricedSubCells[static_cast<std::size_t>(robot)] +=
            cell.freeSubCellCount() * double(cell.turnSecondsPer90Degrees);
    }
    std::vector<float> rates;
    rates.reserve(graph.size());
    bool changed = false;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        float rate = cell.expectedTurnsPerSubCell;
        const int robot = id < regions.robotOfCell.size() ? regions.robotOfCell[id] : -1;
        if (robot >= 0 && static_cast<std::size_t>(robot) < robots &&
            static_cast<std::size_t>(robot) < paths.size() &&
            pricedSubCells[static_cast<std::size_t>(robot)] > 0.0)
            rate = static_cast<float>(paths[static_cast<std::size_t>(robot)].turnSeconds /
                                      pricedSubCells[static_cast<std::size_t>(robot)]);
        changed = changed || rate != cell.expectedTurnsPerSubCell;
        rates.push_back(rate);
    }
    graph.setExpectedTurns(rates);
    return changed;
}

} // namespace mcpp
