#include "core/planners/UncoveredLand.hpp"

#include "core/allocation/StartComponents.hpp"

#include <vector>

namespace mcpp {
namespace {

bool heldByNoRegion(const Plan& plan, std::size_t id) {
    return id >= plan.regions.robotOfCell.size() || plan.regions.robotOfCell[id] < 0;
}

// Marks every cell a way through neighbouring cells joins to `first` (those marked already excepted) with
// `mark`; returns the cells marked. For the pieces no start reaches (componentsWithStarts finds the rest).
std::vector<int> markJoined(const CellGraph& graph, int first, std::vector<int>& marks, int mark) {
    std::vector<int> joined{first};
    marks[static_cast<std::size_t>(first)] = mark;
    for (std::size_t next = 0; next < joined.size(); ++next)
        for (const int neighbour : graph.neighbours(joined[next]))
            if (marks[static_cast<std::size_t>(neighbour)] == 0) {
                marks[static_cast<std::size_t>(neighbour)] = mark;
                joined.push_back(neighbour);
            }
    return joined;
}

} // namespace

UncoveredLand uncoveredLand(const Plan& plan) {
    const CellGraph& graph = plan.cells;
    constexpr int joinedToAStart = 1;
    constexpr int cutOff = 2;
    std::vector<int> starts;
    for (const int start : plan.regions.startCell)
        if (graph.contains(start))
            starts.push_back(start);
    std::vector<int> marks(graph.size(), 0);
    for (const StartComponent& part : componentsWithStarts(graph, starts))
        for (const int cell : part.cells)
            marks[static_cast<std::size_t>(cell)] = joinedToAStart;
    UncoveredLand land;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        if (!heldByNoRegion(plan, id))
            continue;
        if (marks[id] == joinedToAStart) {
            land.leftOutSquareMetres += graph.cell(static_cast<int>(id)).passableAreaSquareMetres;
            continue;
        }
        if (marks[id] != 0)
            continue; // counted with its piece
        double area = 0.0;
        int largestCell = static_cast<int>(id);
        for (const int cell : markJoined(graph, static_cast<int>(id), marks, cutOff)) {
            if (!heldByNoRegion(plan, static_cast<std::size_t>(cell)))
                continue;
            area += graph.cell(cell).passableAreaSquareMetres;
            if (graph.cell(cell).passableAreaSquareMetres > graph.cell(largestCell).passableAreaSquareMetres)
                largestCell = cell;
        }
        land.cutOffSquareMetres += area;
        ++land.cutOffPieces;
        if (area > land.largestPieceSquareMetres) {
            land.largestPieceSquareMetres = area;
            const Cell cell = graph.cell(largestCell);
            land.largestPieceCentre = {cell.centreX(), cell.centreY()};
        }
    }
    return land;
}

} // namespace mcpp
