#include "core/planners/LandBeyondReach.hpp"

#include "core/model/HumanUnits.hpp"
#include "core/model/StartPointCheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace mcpp {
namespace {

struct Reach {
    MapPoint start;
    double metres = 0.0; // how far from its start one of its flights works
};

// Each robot's reach, or nothing where one of them reaches everywhere.
std::optional<std::vector<Reach>> reachesOf(const PlanningProblem& problem) {
    if (problem.starts.empty() || problem.robotFlights.size() < problem.starts.size())
        return std::nullopt;
    // A malformed grid or start is the planner's to refuse, with its own words.
    const ClassGrid& grid = problem.grid;
    const auto pixels = static_cast<std::size_t>(std::max(grid.columns, 0)) *
                        static_cast<std::size_t>(std::max(grid.rows, 0));
    if (grid.values.size() != pixels || (!grid.outside.empty() && grid.outside.size() != pixels) ||
        !(grid.pixelWidth > 0.0) || !(grid.pixelHeight > 0.0))
        return std::nullopt;
    for (const MapPoint& start : problem.starts)
        if (!std::isfinite(start.x) || !std::isfinite(start.y))
            return std::nullopt;
    std::vector<Reach> reaches;
    for (std::size_t robot = 0; robot < problem.starts.size(); ++robot) {
        const double reach = problem.robotFlights[robot].workingReachMetres();
        if (!std::isfinite(reach))
            return std::nullopt;
        reaches.push_back({problem.starts[robot], reach});
    }
    return reaches;
}

// How far inside a reach a pixel's centre must lie, by its class. A cell partly within reach is kept whole
// and its path's waypoints lie anywhere in it: a cell of at most two of its classes' fields of view a side.
// So the margin is that cell's diagonal and half the pixel's, at most half the reach; impassable pixels and
// classes the table lacks take half the pixel's alone. Few distinct margins: each row is marked once for
// each.
class ReachMargins {
  public:
    explicit ReachMargins(const PlanningProblem& problem) {
        const double halfPixel = std::hypot(problem.grid.pixelWidth, problem.grid.pixelHeight) / 2.0;
        metres_.push_back(halfPixel);
        for (const LandCoverClass& landCover : problem.classes.classes()) {
            const double margin = landCover.isTraversable()
                                      ? halfPixel + 2.0 * std::sqrt(2.0) * landCover.fieldOfViewMetres
                                      : halfPixel;
            const auto found = std::find(metres_.begin(), metres_.end(), margin);
            indexOfValue_[landCover.value] = static_cast<std::size_t>(found - metres_.begin());
            if (found == metres_.end())
                metres_.push_back(margin);
        }
    }
    [[nodiscard]] const std::vector<double>& metres() const { return metres_; }
    [[nodiscard]] std::size_t indexOf(std::int32_t value) const {
        const auto found = indexOfValue_.find(value);
        return found == indexOfValue_.end() ? 0 : found->second;
    }

  private:
    std::vector<double> metres_;
    std::unordered_map<std::int32_t, std::size_t> indexOfValue_;
};

// Marks the columns of a row whose pixel centres lie `margin` or more inside some robot's reach: one
// interval per robot.
void markReachedColumns(const ClassGrid& grid, const std::vector<Reach>& reaches, double margin, double y,
                        std::vector<char>& reached) {
    std::fill(reached.begin(), reached.end(), 0);
    for (const Reach& reach : reaches) {
        // Cells as large as the reach cannot fit a flight anyway: the land nearest the start is kept, and
        // the flights too long for them are warned of.
        const double radius = reach.metres - std::min(margin, reach.metres / 2.0);
        const double dy = std::abs(y - reach.start.y);
        if (!(radius >= dy))
            continue;
        const double half = std::sqrt(radius * radius - dy * dy);
        const double first = std::ceil((reach.start.x - half - grid.originX) / grid.pixelWidth - 0.5);
        const double last = std::floor((reach.start.x + half - grid.originX) / grid.pixelWidth - 0.5);
        const auto from = static_cast<std::ptrdiff_t>(std::max(first, 0.0));
        const auto to = static_cast<std::ptrdiff_t>(std::min(last, static_cast<double>(grid.columns - 1)));
        if (from <= to)
            std::fill(reached.begin() + from, reached.begin() + to + 1, 1);
    }
}

double nearestStartMetres(const std::vector<Reach>& reaches, MapPoint point) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Reach& reach : reaches)
        nearest = std::min(nearest, std::hypot(point.x - reach.start.x, point.y - reach.start.y));
    return nearest;
}

// Adds the pixel to the run it continues, or starts one.
void extendRuns(std::vector<PixelRuns::Run>& runs, int row, int column) {
    if (!runs.empty() && runs.back().row == row && runs.back().endColumn == column)
        ++runs.back().endColumn;
    else
        runs.push_back({row, column, column + 1});
}

bool passable(const ClassTable& classes, std::int32_t value) {
    const LandCoverClass* found = classes.find(value);
    return found != nullptr && found->isTraversable();
}

} // namespace

std::optional<LandBeyondReach> landBeyondEveryReach(const PlanningProblem& problem) {
    const std::optional<std::vector<Reach>> reaches = reachesOf(problem);
    if (!reaches)
        return std::nullopt;
    const ClassGrid& grid = problem.grid;
    const ReachMargins margins(problem);
    LandBeyondReach land;
    land.passable = PixelRuns{grid.originX, grid.originY, grid.pixelWidth, grid.pixelHeight, {}};
    land.outside = grid.outside;
    land.outside.resize(grid.values.size(), 0);
    const double pixelArea = grid.pixelWidth * grid.pixelHeight;
    std::vector<std::vector<char>> reached(
        margins.metres().size(), std::vector<char>(static_cast<std::size_t>(std::max(grid.columns, 0))));
    for (int row = 0; row < grid.rows; ++row) {
        const double y = grid.originY - (row + 0.5) * grid.pixelHeight;
        for (std::size_t margin = 0; margin < reached.size(); ++margin)
            markReachedColumns(grid, *reaches, margins.metres()[margin], y, reached[margin]);
        for (int column = 0; column < grid.columns; ++column) {
            const std::size_t index = grid.index(column, row);
            if (land.outside[index] != 0)
                continue;
            const bool isPassable = passable(problem.classes, grid.values[index]);
            if (reached[margins.indexOf(grid.values[index])][static_cast<std::size_t>(column)] != 0) {
                land.reachedPassable = land.reachedPassable || isPassable;
                continue;
            }
            land.outside[index] = ClassGrid::beyondFlightReach;
            if (!isPassable)
                continue;
            extendRuns(land.passable.runs, row, column);
            land.passableSquareMetres += pixelArea;
            const MapPoint centre{grid.originX + (column + 0.5) * grid.pixelWidth, y};
            const double metres = nearestStartMetres(*reaches, centre);
            if (metres > land.farthestMetres) {
                land.farthestMetres = metres;
                land.farthest = centre;
            }
        }
    }
    if (!(land.passableSquareMetres > 0.0))
        return std::nullopt;
    land.leastReachMetres = std::numeric_limits<double>::infinity();
    for (const Reach& reach : *reaches) {
        land.leastReachMetres = std::min(land.leastReachMetres, reach.metres);
        land.mostReachMetres = std::max(land.mostReachMetres, reach.metres);
    }
    return land;
}

namespace {

// Whether a pixel of the cell's square or the ring of pixels round it is flagged beyond reach.
bool cellTouchesLandBeyondReach(const ClassGrid& grid, const Cell& cell) {
    const auto column = [&grid](double x) {
        return static_cast<int>(std::floor((x - grid.originX) / grid.pixelWidth));
    };
    const auto row = [&grid](double y) {
        return static_cast<int>(std::floor((grid.originY - y) / grid.pixelHeight));
    };
    // The square's pixels are those whose centres it holds; one more on each side is the ring.
    const int firstColumn = std::max(column(cell.minX + grid.pixelWidth / 2.0) - 1, 0);
    const int lastColumn = std::min(column(cell.maxX() - grid.pixelWidth / 2.0) + 1, grid.columns - 1);
    const int firstRow = std::max(row(cell.maxY() - grid.pixelHeight / 2.0) - 1, 0);
    const int lastRow = std::min(row(cell.minY + grid.pixelHeight / 2.0) + 1, grid.rows - 1);
    for (int r = firstRow; r <= lastRow; ++r)
        for (int c = firstColumn; c <= lastColumn; ++c)
            if (grid.outside[grid.index(c, r)] == ClassGrid::beyondFlightReach)
                return true;
    return false;
}

} // namespace

bool coversNextToLandBeyondReach(const ClassGrid& grid, const CellGraph& cells,
                                 const std::vector<int>& robotOfCell, int robot) {
    if (grid.outside.size() != grid.values.size())
        return false;
    for (std::size_t id = 0; id < cells.size() && id < robotOfCell.size(); ++id)
        if (robotOfCell[id] == robot && cellTouchesLandBeyondReach(grid, cells.cell(static_cast<int>(id))))
            return true;
    return false;
}

std::string landBeyondReachMessage(const LandBeyondReach& land) {
    const bool oneReach = formatDistance(land.leastReachMetres) == formatDistance(land.mostReachMetres);
    const std::string reach =
        oneReach ? formatDistance(land.mostReachMetres)
                 : formatDistance(land.leastReachMetres) + " to " + formatDistance(land.mostReachMetres);
    return formatArea(land.passableSquareMetres) +
           " of passable land lies too far from every start for one flight to work there and come back, and "
           "is left out of the plan: a flight works at most " +
           reach +
           " from its start, its trips and a twentieth of its time at work included, and the cells at that "
           "edge (two fields of view a side) must lie wholly within it; the farthest of that land lies "
           "round " +
           describePoint(land.farthest) + ", " + formatDistance(land.farthestMetres) +
           " from the nearest start. Start a robot nearer it, or give the aircraft a longer flight time or a "
           "faster cruise speed, to cover it";
}

std::string nothingWithinReachMessage(const LandBeyondReach& land) {
    return "no passable land lies within what one flight can cover from any start: the flights work at "
           "most " +
           formatDistance(land.mostReachMetres) +
           " from their starts (their climb, descent and trips and a twentieth of a flight at work), less "
           "the "
           "size of the cells there (two fields of view a side). Give the aircraft a longer flight time, a "
           "faster cruise speed or a smaller field of view, or start them nearer the land";
}

} // namespace mcpp
