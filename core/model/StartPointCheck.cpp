#include "core/model/StartPointCheck.hpp"

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

} // namespace

std::string describePoint(MapPoint point) {
    std::ostringstream text;
    text.precision(12);
    text << "(" << point.x << ", " << point.y << ")";
    return text.str();
}

std::optional<StartPointProblem> startPointProblem(const ClassGrid& grid, const ClassTable& classes,
                                                   MapPoint point) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
        return StartPointProblem{Kind::InvalidParameter, describePoint(point) + " is not a number"};
    const auto pixel = grid.pixelAt(point);
    if (!pixel)
        return StartPointProblem{Kind::StartOutsideArea,
                                 describePoint(point) + " is outside the raster (x " + fixed(grid.originX) +
                                     " to " + fixed(grid.maxX()) + ", y " + fixed(grid.minY()) + " to " +
                                     fixed(grid.originY) + ")"};
    if (grid.isOutside(pixel->column, pixel->row))
        return StartPointProblem{
            Kind::StartOutsideArea,
            describePoint(point) +
                " is outside the task area (a nodata pixel, or outside the area of interest)"};
    const std::int32_t value = grid.valueAt(pixel->column, pixel->row);
    const LandCoverClass* landCover = classes.find(value);
    if (landCover == nullptr)
        return StartPointProblem{Kind::InvalidClassTable, describePoint(point) + " is on class " +
                                                              std::to_string(value) +
                                                              ", which has no row in the class table"};
    if (!landCover->isTraversable()) {
        const std::string name = landCover->name.empty() ? std::string() : " (" + landCover->name + ")";
        return StartPointProblem{Kind::StartOnObstacle, describePoint(point) + " is on an obstacle: class " +
                                                            std::to_string(value) + name +
                                                            ", which robots cannot cross"};
    }
    return std::nullopt;
}

} // namespace mcpp
