#include "core/outlines/RegionLabels.hpp"

#include "core/model/ParallelFor.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/outlines/OutlineTracer.hpp"
#include "core/outlines/RegionOutlines.hpp"

#include <algorithm>
#include <cmath>
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

namespace {

// A box on the bottom grid, in its columns and rows (east and south one past the last).
struct BottomBox {
    int west = 0;
    int north = 0;
    int east = 0;
    int south = 0;
    bool empty = true;

    void hold(int column, int row, int endColumn, int endRow) {
        west = empty ? column : std::min(west, column);
        north = empty ? row : std::min(north, row);
        east = empty ? endColumn : std::max(east, endColumn);
        south = empty ? endRow : std::max(south, endRow);
        empty = false;
    }
};

// The frame (and any cell beyond it), or the labelled cells only.
BottomBox boxOf(const CellGraph& graph, const std::vector<std::int32_t>& labelOfCell, bool cropped) {
    BottomBox box;
    if (!cropped)
        box.hold(0, 0, graph.frame().columns, graph.frame().rows);
    for (std::size_t id = 0; id < labelOfCell.size() && id < graph.size(); ++id) {
        const CellRecord& cell = graph.record(static_cast<int>(id));
        if (cropped && labelOfCell[id] == LabelGrid::noLabel)
            continue;
        box.hold(cell.column, cell.row, cell.column + cell.span, cell.row + cell.span);
    }
    return box;
}

// Bottom-grid indices of coordinates, kept within reach of an int however far the point lies: the first
// whose cell holds the coordinate, and one past the last that reaches it.
constexpr double farthestIndex = 1 << 29;
int bottomIndex(double metres, double size) {
    return static_cast<int>(std::clamp(std::floor(metres / size), -farthestIndex, farthestIndex));
}
int bottomEnd(double metres, double size) {
    return static_cast<int>(std::clamp(std::ceil(metres / size), -farthestIndex, farthestIndex));
}

// Sub-cells a box holds.
double subCellsOf(const BottomBox& box) {
    return box.empty ? 0.0 : 4.0 * (box.east - box.west) * static_cast<double>(box.south - box.north);
}

// The box of the runs' pixels on the bottom grid; in doubles, as a damaged plan file's rows may be any.
BottomBox boxOfRuns(const PixelRuns& land, const GridFrame& frame) {
    double firstRow = land.runs.front().row;
    double endRow = firstRow + 1.0;
    double firstColumn = land.runs.front().firstColumn;
    double endColumn = land.runs.front().endColumn;
    for (const PixelRuns::Run& run : land.runs) {
        firstRow = std::min(firstRow, static_cast<double>(run.row));
        endRow = std::max(endRow, run.row + 1.0);
        firstColumn = std::min(firstColumn, static_cast<double>(run.firstColumn));
        endColumn = std::max(endColumn, static_cast<double>(run.endColumn));
    }
    const double size = frame.bottomCellSize;
    const double north = frame.originY - land.originY; // the runs' row 0, metres south of the frame's
    const double west = land.originX - frame.originX;
    BottomBox box;
    box.hold(bottomIndex(west + firstColumn * land.pixelWidth, size),
             bottomIndex(north + firstRow * land.pixelHeight, size),
             bottomEnd(west + endColumn * land.pixelWidth, size),
             bottomEnd(north + endRow * land.pixelHeight, size));
    return box;
}

// The box widened towards the runs' pixels by as much as 16 million sub-cells more allow (32 MB of labels):
// a few drones on a continent's raster leave nearly all of it beyond their reach, and the land round the
// plan is what a reader looks for.
void holdRuns(BottomBox& box, const PixelRuns& land, const GridFrame& frame) {
    if (land.empty())
        return;
    const BottomBox runs = boxOfRuns(land, frame);
    BottomBox widened = box;
    widened.hold(runs.west, runs.north, runs.east, runs.south);
    constexpr double allowance = 16.0e6;
    if (subCellsOf(widened) <= subCellsOf(box) + allowance) {
        box = widened;
        return;
    }
    if (box.empty)
        return; // no cells to draw it round
    // Grown by m bottom cells a side: 4 (w + 2m) (h + 2m) <= 4 w h + allowance.
    const double width = box.east - box.west;
    const double height = box.south - box.north;
    const double margin =
        std::floor((-(width + height) + std::sqrt((width + height) * (width + height) + allowance)) / 4.0);
    const auto grown = static_cast<int>(std::max(margin, 0.0));
    box = BottomBox{std::max(box.west - grown, widened.west), std::max(box.north - grown, widened.north),
                    std::min(box.east + grown, widened.east), std::min(box.south + grown, widened.south),
                    false};
}

// The first index i whose centre, origin + (i + 0.5) size, is at least `from` metres past the origin.
int firstCentreFrom(double from, double size) {
    constexpr double farthest = 1 << 30;
    return static_cast<int>(std::clamp(std::ceil(from / size - 0.5), -farthest, farthest));
}

// Marks unreachableLabel on the grid's empty pixels whose centres lie in the runs' pixels.
void markRuns(LabelGrid& grid, const PixelRuns& land) {
    const double size = grid.pixelSize;
    // Metres south and east of the grid's corner: a pixel's edges are worked out alike for its neighbours,
    // so no sub-cell centre on an edge falls between them.
    const double north = grid.originY - land.originY;
    const double west = land.originX - grid.originX;
    for (const PixelRuns::Run& run : land.runs) {
        const int firstRow = std::max(firstCentreFrom(north + run.row * land.pixelHeight, size), 0);
        const int endRow =
            std::min(firstCentreFrom(north + (run.row + 1.0) * land.pixelHeight, size), grid.rows);
        const int firstColumn = std::max(firstCentreFrom(west + run.firstColumn * land.pixelWidth, size), 0);
        const int endColumn =
            std::min(firstCentreFrom(west + run.endColumn * land.pixelWidth, size), grid.columns);
        for (int row = firstRow; row < endRow; ++row)
            for (int column = firstColumn; column < endColumn; ++column) {
                LabelGrid::Label& label = grid.labels[grid.index(column, row)];
                if (label == LabelGrid::noLabel)
                    label = static_cast<LabelGrid::Label>(unreachableLabel);
            }
    }
}

// The labels of the cells on the sub-cell grid over the box.
LabelGrid cellLabelsOn(const CellGraph& graph, const std::vector<std::int32_t>& labelOfCell,
                       const BottomBox& box) {
    const GridFrame& frame = graph.frame();
    LabelGrid grid;
    grid.columns = 2 * (box.east - box.west);
    grid.rows = 2 * (box.south - box.north);
    grid.originX = frame.x(box.west);
    grid.originY = frame.y(box.north);
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
                    fillSubCell(grid, cell, subCell, static_cast<LabelGrid::Label>(labelOfCell[id]), box.west,
                                box.north);
        }
    });
    return grid;
}

} // namespace

LabelGrid cellLabels(const CellGraph& graph, const std::vector<std::int32_t>& labelOfCell, bool cropped) {
    return cellLabelsOn(graph, labelOfCell, boxOf(graph, labelOfCell, cropped));
}

LabelGrid regionLabels(const Plan& plan) {
    std::vector<std::int32_t> labels(plan.cells.size(), LabelGrid::noLabel);
    const auto& owner = plan.regions.robotOfCell;
    for (std::size_t id = 0; id < owner.size() && id < labels.size(); ++id)
        labels[id] = owner[id] >= 0 ? owner[id] : unreachableLabel;
    // Cropped to the plan's cells: a small area on a large raster gives a small grid (and regions.tif). The
    // land left out beyond every flight's reach is no robot's either: the box holds it too.
    BottomBox box = boxOf(plan.cells, labels, true);
    holdRuns(box, plan.landBeyondReach, plan.cells.frame());
    LabelGrid grid = cellLabelsOn(plan.cells, labels, box);
    markRuns(grid, plan.landBeyondReach);
    return grid;
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
