#include "core/decomposition/QuadTreeDecomposition.hpp"

#include "core/decomposition/NeighbourTopologyBuilder.hpp"

#include <utility>

namespace mcpp {

CellGraph cellGraphOfQuadTree(QuadTree tree, NeighbourTopology topology) {
    GridFrame frame;
    frame.originX = tree.originX;
    frame.originY = tree.originY;
    frame.bottomCellSize = 2.0 * tree.fovMin;
    frame.levels = tree.levels;
    frame.columns = tree.levels > 0 ? tree.columnsAt(tree.levels) : 0;
    frame.rows = tree.levels > 0 ? tree.rowsAt(tree.levels) : 0;
    std::vector<CellRecord> cells;
    cells.reserve(tree.activeCount());
    // What storing areas as floats changed, added to the total so that the cells never add up to more.
    double rounding = 0.0;
    for (std::size_t active = 0; active < tree.activeCount(); ++active) {
        const QuadCell& quadCell = tree.active(static_cast<int>(active));
        CellRecord cell;
        cell.span = 1 << (tree.levels - quadCell.level);
        cell.column = quadCell.column * cell.span;
        cell.row = quadCell.row * cell.span;
        cell.level = quadCell.level;
        cell.classValue = quadCell.classValue;
        cell.speedMetresPerSecond = quadCell.speedMetresPerSecond;
        cell.passableAreaSquareMetres = static_cast<float>(quadCell.passableAreaSquareMetres);
        rounding += double{cell.passableAreaSquareMetres} - quadCell.passableAreaSquareMetres;
        cells.push_back(cell);
    }
    const double passableArea = tree.passableAreaSquareMetres + rounding;
    std::vector<RoundedFieldOfView> fieldsOfView = std::move(tree.roundedFieldsOfView);
    tree = QuadTree{}; // freed before the graph's locator is built: the decomposition stage's peak
    CellGraph graph(frame, std::move(cells), std::move(topology));
    graph.fieldsOfView = std::move(fieldsOfView);
    graph.passableAreaSquareMetres = passableArea;
    return graph;
}

CellGraph cellGraphOfQuadTree(OneLevelQuadTree grid, bool withLists) {
    CellGraph graph;
    if (withLists) {
        NeighbourTopology topology = NeighbourTopologyBuilder{}.build(grid);
        graph = CellGraph(grid.frame, std::move(grid.cells), std::move(topology));
    } else {
        graph = CellGraph::ofGrid(grid.frame, std::move(grid.cells));
    }
    graph.fieldsOfView = std::move(grid.roundedFieldsOfView);
    graph.passableAreaSquareMetres = grid.passableAreaSquareMetres + grid.areaRounding;
    return graph;
}

CellGraph cellGraphOfLeaves(QuadTreeLeaves leaves, std::size_t fewestCellsWithoutLists) {
    if (auto* grid = std::get_if<OneLevelQuadTree>(&leaves)) {
        const bool withLists = grid->cells.size() < fewestCellsWithoutLists;
        return cellGraphOfQuadTree(std::move(*grid), withLists);
    }
    auto& tree = std::get<QuadTree>(leaves);
    NeighbourTopology topology = NeighbourTopologyBuilder{}.build(tree);
    return cellGraphOfQuadTree(std::move(tree), std::move(topology));
}

} // namespace mcpp
