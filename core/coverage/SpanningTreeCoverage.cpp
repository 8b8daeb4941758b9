#include "core/coverage/SpanningTreeCoverage.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"

namespace mcpp {

std::vector<std::vector<int>> cellsByRobot(const RegionAllocation& regions) {
    std::vector<std::vector<int>> cells(regions.startCell.size());
    for (std::size_t cell = 0; cell < regions.robotOfCell.size(); ++cell) {
        const int robot = regions.robotOfCell[cell];
        if (robot >= 0 && static_cast<std::size_t>(robot) < cells.size())
            cells[static_cast<std::size_t>(robot)].push_back(static_cast<int>(cell));
    }
    return cells;
}

ParameterSpec SpanningTreeCoverage::closedTourParameter() {
    return booleanParameter("closed_tour", "Return to start", true,
                            "Closed tours end where they start; open paths stop at the last cell");
}

CoveragePath SpanningTreeCoverage::regionPath(const CellGraph& graph, const std::vector<int>& cells,
                                              int startCell, int robot, MapPoint start,
                                              std::vector<int>& scratchIndex) const {
    const SpanningTreeBuilder trees(graph, scratchIndex);
    TreeCircumnavigation walker(graph);
    CoveragePath best;
    for (auto preference : {EdgeDirection::EastWest, EdgeDirection::NorthSouth}) {
        const SpanningTree tree = trees.preferring(cells, startCell, preference);
        CoveragePath candidate =
            pathFromWalk(robot, start, walker.walk(tree, start, closedTour_), closedTour_);
        measurePath(candidate, graph);
        if (best.waypoints.empty() || candidate.turns < best.turns ||
            (candidate.turns == best.turns && candidate.lengthMetres < best.lengthMetres - 1e-9))
            best = std::move(candidate);
    }
    return best;
}

std::vector<CoveragePath> SpanningTreeCoverage::plan(const CellGraph& graph, const RegionAllocation& regions,
                                                     const std::vector<MapPoint>& starts,
                                                     const ProgressReporter& progress) const {
    const std::size_t robots = regions.startCell.size();
    const auto regionCells = cellsByRobot(regions);
    std::vector<int> scratchIndex(graph.size(), -1);
    std::vector<CoveragePath> paths;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        progress.throwIfCancelled();
        progress.report("paths", static_cast<double>(robot) / static_cast<double>(robots));
        paths.push_back(regionPath(graph, regionCells[robot], regions.startCell[robot],
                                   static_cast<int>(robot), starts[robot], scratchIndex));
    }
    progress.report("paths", 1.0);
    return paths;
}

} // namespace mcpp
