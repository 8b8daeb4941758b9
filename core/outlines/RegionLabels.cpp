#include "core/outlines/RegionLabels.hpp"

#include "core/model/ParallelFor.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/outlines/OutlineTracer.hpp"
#include "core/outlines/RegionOutlines.hpp"

#include <algorithm>
#include <limits>

namespace mcpp {

// Robot numbers and unreachableLabel fit a label.
static_assert(mostRobots <= LabelGrid::largestLabel &&
              unreachableLabel >= std::numeric_limits<LabelGrid::Label>::min());

namespace {

constexpr std::size_t cellsPerTask = std::size_t{1} << 16;

// Fills the pixels of one free sub-cell: a square of span x span pixels of the sub-cell grid, whose
// north-west corner is bottom-grid column `west`, row `north`.
void fillSubCell(LabelGrid& grid, const CellRecord& cell, SubCell subCell, LabelGrid::Label label, int west,
                 int north) {
    const bool east = subCell == SubCell::NorthEast || subCell == SubCell::SouthEast;
    const bool south = subCell == SubCell::SouthWest || subCell == SubCell::SouthEast;
    const int firstColumn = 2 * (cell.column - west) + (east ? cell.span : 0);
    const int firstRow = 2 * (cell.row - north) + (south ? cell.span : 0);
    for (int row = firstRow; row < firstRow + cell.span; ++row) {
        const auto begin = grid.labels.begin() + static_cast<std::ptrdiff_t>(grid.index(firstColumn, row));
        std::fill(begin, begin + cell.span, label);
    }
}

} // namespace

LabelGrid cellLabels(const CellGraph& graph, const std::vector<std::int32_t>& labelOfCell, bool cropped) {
    const GridFrame& frame = graph.frame();
    // The box on the bottom grid: the frame (and any cell beyond it), or the labelled cells only.
    int west = 0;
    int north = 0;
    int east = cropped ? 0 : frame.columns;
    int south = cropped ? 0 : frame.rows;
    bool first = true;
    for (std::size_t id = 0; id < labelOfCell.size() && id < graph.size(); ++id) {
        const CellRecord& cell = graph.record(static_cast<int>(id));
        if (cropped && labelOfCell[id] == LabelGrid::noLabel)
            continue;
        if (cropped && first) {
            west = cell.column;
            north = cell.row;
            first = false;
        }
        west = std::min(west, cell.column);
        north = std::min(north, cell.row);
        east = std::max(east, cell.column + cell.span);
        south = std::max(south, cell.row + cell.span);
    }
    LabelGrid grid;
    grid.columns = 2 * (east - west);
    grid.rows = 2 * (south - north);
    grid.originX = frame.x(west);
    grid.originY = frame.y(north);
    grid.pixelSize = frame.bottomCellSize / 2.0;
    grid.labels.assign(static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows),
                       LabelGrid::noLabel);
    // Cells fill pixels of their own, so blocks of cells are filled side by side.
    const std::size_t cells = std::min(labelOfCell.size(), graph.size());
    parallelForRanges(cells, cellsPerTask, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t id = begin; id < end; ++id) {
            if (labelOfCell[id] == LabelGrid::noLabel)
                continue;
            const CellRecord& cell = graph.record(static_cast<int>(id));
            for (const SubCell subCell : subCellsCounterClockwise)
                if (holdsSubCell(cell.freeSubCells, subCell))
                    fillSubCell(grid, cell, subCell, static_cast<LabelGrid::Label>(labelOfCell[id]), west,
                                north);
        }
    });
    return grid;
}

LabelGrid regionLabels(const Plan& plan) {
    std::vector<std::int32_t> labels(plan.cells.size(), LabelGrid::noLabel);
    const auto& owner = plan.regions.robotOfCell;
    for (std::size_t id = 0; id < owner.size() && id < labels.size(); ++id)
        labels[id] = owner[id] >= 0 ? owner[id] : unreachableLabel;
    // Cropped to the plan's cells: a small area on a large raster gives a small grid (and regions.tif).
    return cellLabels(plan.cells, labels, true);
}

LabelGrid takenOverLabels(const Plan& plan) {
    const TimelineLayer* timeline = timelineLayerOf(plan);
    if (timeline == nullptr)
        return {};
    std::vector<std::int32_t> labels(plan.cells.size(), LabelGrid::noLabel);
    bool any = false;
    for (const RobotTimeline& robot : timeline->robots())
        for (const int cell : robot.cellsTakenOver)
            if (robot.robot >= 0 && cell >= 0 && static_cast<std::size_t>(cell) < labels.size()) {
                labels[static_cast<std::size_t>(cell)] = robot.robot;
                any = true;
            }
    return any ? cellLabels(plan.cells, labels, true) : LabelGrid{};
}

RegionOutlines regionOutlines(const Plan& plan) {
    RegionOutlines outlines;
    outlines.labels = regionLabels(plan);
    outlines.polygons = traceOutlines(outlines.labels);
    return outlines;
}

} // namespace mcpp
