#include "core/model/StartPointCheck.hpp"

#include "core/model/HumanUnits.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mcpp {
namespace {

using Kind = PlanningError::Kind;

std::string fixed(double value) {
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(2);
    text << value;
    return text.str();
}

// To the centimetre, trailing zeros dropped: "314617.96", "0".
std::string centimetres(double metres) {
    std::string text = fixed(metres);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.')
        text.pop_back();
    return text == "-0" ? "0" : text;
}

// "north-east": the compass point nearest the direction of the grid's (dx, dy), turned to true north.
std::string compassPoint(const ClassGrid& grid, double dx, double dy) {
    static const char* const names[] = {"east", "north-east", "north", "north-west",
                                        "west", "south-west", "south", "south-east"};
    const double turn = grid.trueNorthRadians;
    const double east = dx * std::cos(turn) + dy * std::sin(turn);
    const double north = -dx * std::sin(turn) + dy * std::cos(turn);
    const double turns = std::atan2(north, east) / (2.0 * std::acos(-1.0)); // -0.5 to 0.5, 0 east
    const int sector = static_cast<int>(std::lround(turns * 8.0 + 8.0)) % 8;
    return names[sector];
}

// "9.42 km north-east of it": how far outside the raster's extent a point lies, and which way from the
// nearest point of the extent.
std::string beyondTheRaster(const ClassGrid& grid, MapPoint point) {
    const double dx = point.x - std::clamp(point.x, grid.originX, grid.maxX());
    const double dy = point.y - std::clamp(point.y, grid.minY(), grid.originY);
    if (dx == 0.0 && dy == 0.0) // on the far edges, which belong to no pixel
        return "on its far edge";
    return formatDistance(std::hypot(dx, dy)) + " " + compassPoint(grid, dx, dy) + " of it";
}

std::string whyOutside(std::uint8_t reason) {
    switch (reason) {
    case ClassGrid::outsideNodata:
        return "the raster has no land cover there (nodata)";
    case ClassGrid::outsideArea:
        return "it lies outside the area of interest";
    case ClassGrid::inNoGoZone:
        return "it lies in a no-go zone";
    case ClassGrid::outsideUnlisted:
        return "its class has no row in the class table and is left out";
    case ClassGrid::beyondFlightReach:
        return "it lies beyond one flight's reach of every start";
    default:
        return "it is left out of the task area";
    }
}

// Whether a robot could start on the pixel: in the task area, of a class robots cross.
bool startable(const ClassGrid& grid, const ClassTable& classes, int column, int row) {
    if (grid.isOutside(column, row))
        return false;
    const LandCoverClass* landCover = classes.find(grid.valueAt(column, row));
    return landCover != nullptr && landCover->isTraversable();
}

// "; the nearest land of the task area a robot can cross is 35 m east, at (500105, 3999955)", searched up to
// a few hundred pixels away (a start on the nodata rim of a warped raster, or just outside a drawn area);
// empty when none is that near.
std::string nearestStartableLand(const ClassGrid& grid, const ClassTable& classes, MapPoint point,
                                 PixelIndex from) {
    constexpr int farthestRing = 400;
    const double smallerSide = std::min(grid.pixelWidth, grid.pixelHeight);
    const auto centreOf = [&](int column, int row) {
        return MapPoint{grid.originX + (column + 0.5) * grid.pixelWidth,
                        grid.originY - (row + 0.5) * grid.pixelHeight};
    };
    std::optional<MapPoint> nearest;
    double nearestDistance = 0.0;
    int lastRing = farthestRing;
    for (int ring = 1; ring <= lastRing; ++ring) {
        for (int row = std::max(from.row - ring, 0); row <= std::min(from.row + ring, grid.rows - 1); ++row) {
            const bool edgeRow = row == from.row - ring || row == from.row + ring;
            for (int column = from.column - ring; column <= from.column + ring;
                 column += edgeRow ? 1 : 2 * ring) {
                if (column < 0 || column >= grid.columns || !startable(grid, classes, column, row))
                    continue;
                const MapPoint centre = centreOf(column, row);
                const double distance = std::hypot(centre.x - point.x, centre.y - point.y);
                if (nearest && distance >= nearestDistance)
                    continue;
                nearest = centre;
                nearestDistance = distance;
                // A pixel on ring k lies at least k - 1/2 pixels away, the point anywhere in its own pixel:
                // rings beyond this one's distance cannot hold a nearer one.
                lastRing = std::min(lastRing, static_cast<int>(std::ceil(distance / smallerSide + 0.5)));
            }
        }
    }
    if (!nearest)
        return {};
    return "; the nearest land of the task area a robot can cross is " + formatDistance(nearestDistance) +
           " " + compassPoint(grid, nearest->x - point.x, nearest->y - point.y) + ", at " +
           describePoint(*nearest);
}

} // namespace

bool takesOffThere(const ClassGrid& grid, MapPoint point, const StartPointProblem& problem) {
    if (problem.kind == Kind::InvalidParameter || !std::isfinite(point.x) || !std::isfinite(point.y))
        return false;
    const auto pixel = grid.pixelAt(point);
    // Not from a no-go zone: its flights would cross it.
    return pixel && !(grid.isOutside(pixel->column, pixel->row) &&
                      grid.outside[grid.index(pixel->column, pixel->row)] == ClassGrid::inNoGoZone);
}

bool robotTakesOffThere(const std::vector<bool>& flyingRobots, std::size_t robot, const ClassGrid& grid,
                        MapPoint point, const StartPointProblem& problem) {
    return robot < flyingRobots.size() && flyingRobots[robot] && takesOffThere(grid, point, problem);
}

std::string describePoint(MapPoint point) {
    return "(" + centimetres(point.x) + ", " + centimetres(point.y) + ")";
}

std::optional<StartPointProblem> startPointProblem(const ClassGrid& grid, const ClassTable& classes,
                                                   MapPoint point, const std::string& pointName) {
    const std::string named = pointName.empty() ? describePoint(point) : pointName;
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
        return StartPointProblem{Kind::InvalidParameter, named + " is not a number"};
    const auto pixel = grid.pixelAt(point);
    if (!pixel)
        return StartPointProblem{Kind::StartOutsideArea,
                                 named + " is outside the raster, " + beyondTheRaster(grid, point) + " (x " +
                                     fixed(grid.originX) + " to " + fixed(grid.maxX()) + ", y " +
                                     fixed(grid.minY()) + " to " + fixed(grid.originY) + ")"};
    if (grid.isOutside(pixel->column, pixel->row))
        return StartPointProblem{Kind::StartOutsideArea,
                                 named + " is not in the task area: " +
                                     whyOutside(grid.outside[grid.index(pixel->column, pixel->row)])};
    const std::int32_t value = grid.valueAt(pixel->column, pixel->row);
    const LandCoverClass* landCover = classes.find(value);
    if (landCover == nullptr)
        return StartPointProblem{Kind::InvalidClassTable, named + " is on class " + std::to_string(value) +
                                                              ", which has no row in the class table"};
    if (!landCover->isTraversable()) {
        const std::string name = landCover->name.empty() ? std::string() : " (" + landCover->name + ")";
        return StartPointProblem{Kind::StartOnObstacle, named + " is on an obstacle: class " +
                                                            std::to_string(value) + name +
                                                            ", which robots cannot cross"};
    }
    return std::nullopt;
}

std::string startRefusal(const ClassGrid& grid, const ClassTable& classes, MapPoint point,
                         const StartPointProblem& problem) {
    if (problem.kind != PlanningError::Kind::StartOutsideArea)
        return problem.detail;
    const auto pixel = grid.pixelAt(point);
    if (!pixel || !grid.isOutside(pixel->column, pixel->row))
        return problem.detail;
    return problem.detail + nearestStartableLand(grid, classes, point, *pixel);
}

} // namespace mcpp
