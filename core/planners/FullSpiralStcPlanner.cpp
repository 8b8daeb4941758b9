#include "core/planners/FullSpiralStcPlanner.hpp"

#include "core/allocation/ComponentRegion.hpp"
#include "core/coverage/BlockedSubCellDetours.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"
#include "core/coverage/SubCellLattice.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/decomposition/GridNeighbours.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace mcpp {
namespace {

// The free sub-cell of the start cell nearest the start point: where the robot enters the lattice.
SubCellLattice::Position entrySubCell(const SubCellLattice& lattice, const Cell& cell, MapPoint start) {
    SubCellLattice::Position best{};
    double bestDistance = std::numeric_limits<double>::infinity();
    for (SubCell subCell : subCellsCounterClockwise) {
        if (!cell.isFree(subCell))
            continue;
        const MapPoint centre = cell.subCellCentre(subCell);
        const double distance = std::hypot(centre.x - start.x, centre.y - start.y);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = *lattice.at(centre);
        }
    }
    return best;
}

struct Reachability {
    CellGraph graph;           // the cells with only their reachable sub-cells free
    int enclosedSubCells = 0;  // free sub-cells of reachable cells that no way leads to
    double enclosedArea = 0.0; // their passable area, m2
};

// Keeps, in every cell the robot can reach, only the free sub-cells it can reach by side steps from where it
// enters: a free sub-cell walled in by blocked ones (diagonal neighbours only) cannot be covered.
Reachability reachableSubCells(const CellGraph& graph, const SubCellLattice& lattice,
                               SubCellLattice::Position entry) {
    std::vector<std::uint8_t> reached(graph.size(), 0);
    for (const auto& position : lattice.reachableFrom(entry)) {
        const Waypoint centre = lattice.waypointAt(position);
        const Cell& cell = graph.cell(centre.cell);
        reached[static_cast<std::size_t>(centre.cell)] |=
            static_cast<std::uint8_t>(1U << static_cast<unsigned>(cell.subCellAt({centre.x, centre.y})));
    }
    Reachability result;
    std::vector<Cell> cells = graph.cells().toVector();
    for (std::size_t id = 0; id < cells.size(); ++id) {
        if (reached[id] == 0 || reached[id] == cells[id].freeSubCells)
            continue;
        const int before = cells[id].freeSubCellCount();
        const int after = subCellsIn(reached[id]);
        const double lost = cells[id].passableAreaSquareMetres * (before - after) / before;
        result.enclosedSubCells += before - after;
        result.enclosedArea += lost;
        cells[id].passableAreaSquareMetres -= lost;
        cells[id].freeSubCells = reached[id];
    }
    NeighbourTopology adjacency = gridNeighbours(graph.frame(), cells);
    result.graph = CellGraph(graph.frame(), cells, std::move(adjacency));
    result.graph.fieldsOfView = graph.fieldsOfView;
    result.graph.passableAreaSquareMetres = graph.passableAreaSquareMetres;
    return result;
}

std::string enclosedMessage(const Reachability& reachability) {
    std::ostringstream text;
    text.precision(6);
    text << reachability.enclosedSubCells << " free sub-cells (" << formatArea(reachability.enclosedArea)
         << ") are walled in by blocked sub-cells and cannot be covered";
    return text.str();
}

} // namespace

PlannerDescription FullSpiralStcPlanner::describe() const {
    PlannerDescription description;
    description.name = "full-spiral-stc";
    description.label = "Full Spiral-STC";
    description.summary = "Spiral-STC that keeps partly blocked mega-cells, covering more near obstacles";
    description.singleRobot = true;
    description.parameters = {DecompositionOptions::blockedThresholdParameter(),
                              SpanningTreeCoverage::closedTourParameter()};
    return description;
}

void FullSpiralStcPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::AnySubCellFree);
    const int startCell = run.locateStarts().front();
    const MapPoint start = run.starts().front();
    plan.regions = run.stage("allocation", [&] {
        std::vector<int> everyCell(plan.cells.size());
        for (std::size_t id = 0; id < everyCell.size(); ++id)
            everyCell[id] = static_cast<int>(id);
        const SubCellLattice lattice(plan.cells, everyCell);
        Reachability reachability =
            reachableSubCells(plan.cells, lattice, entrySubCell(lattice, plan.cells.cell(startCell), start));
        if (reachability.enclosedSubCells > 0)
            run.addIssue(IssueSeverity::Information, "enclosed-sub-cells", enclosedMessage(reachability));
        plan.cells = std::move(reachability.graph);
        return componentRegion(plan.cells, startCell);
    });
    plan.paths = run.stage("paths", [&] {
        const std::vector<int> region = cellsByRobot(plan.regions).front();
        std::vector<int> scratchIndex(plan.cells.size(), -1);
        const SpanningTree tree = SpanningTreeBuilder(plan.cells, scratchIndex).spiral(region, startCell);
        TreeCircumnavigation walker(plan.cells);
        const bool closed = parameters.boolean("closed_tour");
        const SubCellLattice lattice(plan.cells, region);
        std::vector<Waypoint> walk = avoidBlockedSubCells(lattice, walker.walk(tree, start, closed));
        if (closed &&
            walk.size() > 1) { // the walk began in a blocked sub-cell: come back to where it entered
            const auto first = lattice.at({walk.front().x, walk.front().y});
            for (const auto& step : lattice.shortestWay(*lattice.at({walk.back().x, walk.back().y}), *first))
                walk.push_back(lattice.waypointAt(step));
        }
        return std::vector<CoveragePath>{pathFromWalk(0, start, std::move(walk), closed)};
    });
}

} // namespace mcpp
