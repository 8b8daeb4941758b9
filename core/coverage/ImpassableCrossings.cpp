#include "core/coverage/ImpassableCrossings.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp {

namespace {

// Whether each raster value is traversable, looked up without a search per pixel.
class TraversableValues {
  public:
    explicit TraversableValues(const ClassTable& classes) {
        for (const LandCoverClass& entry : classes.classes())
            if (entry.isTraversable())
                traversable_.push_back(entry.value);
        std::sort(traversable_.begin(), traversable_.end());
    }
    [[nodiscard]] bool contains(std::int32_t value) const {
        return std::binary_search(traversable_.begin(), traversable_.end(), value);
    }

  private:
    std::vector<std::int32_t> traversable_;
};

// Calls visit(column, row) for each pixel whose centre lies in one of the cell's free sub-cells.
template <typename Visit>
void forPixelsInFreeSubCells(const Cell& cell, const ClassGrid& grid, Visit&& visit) {
    const auto firstIndex = [](double low, double origin, double step, int count) {
        return std::clamp(static_cast<int>(std::ceil((low - origin) / step - 0.5)), 0, count);
    };
    const int firstColumn = firstIndex(cell.minX, grid.originX, grid.pixelWidth, grid.columns);
    const int lastColumn = firstIndex(cell.maxX(), grid.originX, grid.pixelWidth, grid.columns);
    const int firstRow = firstIndex(grid.originY - cell.maxY(), 0.0, grid.pixelHeight, grid.rows);
    const int lastRow = firstIndex(grid.originY - cell.minY, 0.0, grid.pixelHeight, grid.rows);
    for (int row = firstRow; row < lastRow; ++row) {
        const double y = grid.originY - (row + 0.5) * grid.pixelHeight;
        for (int column = firstColumn; column < lastColumn; ++column) {
            const double x = grid.originX + (column + 0.5) * grid.pixelWidth;
            if (cell.isFree(cell.subCellAt({x, y})))
                visit(column, row);
        }
    }
}

} // namespace

std::vector<ImpassableCrossing> impassableCrossings(const CellGraph& cells, const RegionAllocation& regions,
                                                    const ClassGrid& grid, const ClassTable& classes,
                                                    std::size_t most) {
    const TraversableValues traversable(classes);
    std::vector<ImpassableCrossing> crossings;
    for (std::size_t id = 0; id < cells.size() && crossings.size() < most; ++id) {
        if (id >= regions.robotOfCell.size() || regions.robotOfCell[id] < 0)
            continue;
        std::int64_t pixels = 0;
        std::int64_t impassable = 0;
        forPixelsInFreeSubCells(cells.cells()[id], grid, [&](int column, int row) {
            ++pixels;
            if (grid.isOutside(column, row) || !traversable.contains(grid.valueAt(column, row)))
                ++impassable;
        });
        if (impassable > 0)
            crossings.push_back(
                {static_cast<int>(id), static_cast<double>(impassable) / static_cast<double>(pixels)});
    }
    return crossings;
}

std::map<std::int32_t, std::int64_t> impassableClassesIn(const Cell& cell, const ClassGrid& grid,
                                                         const ClassTable& classes, std::int64_t& pixels) {
    const TraversableValues traversable(classes);
    std::map<std::int32_t, std::int64_t> counts;
    pixels = 0;
    forPixelsInFreeSubCells(cell, grid, [&](int column, int row) {
        ++pixels;
        if (grid.isOutside(column, row))
            ++counts[outsideTaskArea];
        else if (!traversable.contains(grid.valueAt(column, row)))
            ++counts[grid.valueAt(column, row)];
    });
    return counts;
}

} // namespace mcpp
