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

std::vector<CoveragePath> SpanningTreeCoverage::plan(const CellGraph& graph, const RegionAllocation& regions,
                                                     const std::vector<MapPoint>& starts,
                                                     const ProgressReporter& progress) const {
    const std::size_t robots = regions.startCell.size();
    const auto regionCells = cellsByRobot(regions);
    std::vector<int> scratchIndex(graph.size(), -1);
    const SpanningTreeBuilder trees(graph, scratchIndex);
    TreeCircumnavigation walker(graph);
    std::vector<CoveragePath> paths;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        progress.throwIfCancelled();
        progress.report("paths", static_cast<double>(robot) / static_cast<double>(robots));
        CoveragePath best;
        for (auto preference : {EdgeDirection::EastWest, EdgeDirection::NorthSouth}) {
            const SpanningTree tree =
                trees.preferring(regionCells[robot], regions.startCell[robot], preference);
            CoveragePath candidate = pathFromWalk(static_cast<int>(robot), starts[robot],
                                                  walker.walk(tree, starts[robot], closedTour_), closedTour_);
            measurePath(candidate, graph);
            if (best.waypoints.empty() || candidate.turns < best.turns ||
                (candidate.turns == best.turns && candidate.lengthMetres < best.lengthMetres - 1e-9))
                best = std::move(candidate);
        }
        paths.push_back(std::move(best));
    }
    progress.report("paths", 1.0);
    return paths;
}

} // namespace mcpp
