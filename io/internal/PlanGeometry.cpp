#include "io/internal/PlanGeometry.hpp"

#include "io/internal/GdalSupport.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::io::internal {

namespace {

double snapped(double coordinate, double origin, double unit) {
    if (!(unit > 0.0)) return coordinate;
    return origin + std::round((coordinate - origin) / unit) * unit;
}

// Union of the given active cells: valid polygons, shared edges dissolved.
Result<std::unique_ptr<OGRGeometry>> dissolve(const QuadTree& tree, const std::vector<int>& activeIndices,
                                              double metresPerUnit) {
    using Dissolved = Result<std::unique_ptr<OGRGeometry>>;
    if (activeIndices.empty()) return std::unique_ptr<OGRGeometry>(std::make_unique<OGRMultiPolygon>());
    OGRMultiPolygon squares;
    for (const int index : activeIndices) squares.addGeometryDirectly(cellSquare(tree, tree.active(index), metresPerUnit).release());
    QuietGdalErrors quiet;
    std::unique_ptr<OGRGeometry> merged(squares.UnionCascaded());
    if (!merged) return Dissolved::failure("could not dissolve " + std::to_string(activeIndices.size()) + " cells" + quiet.detail());
    if (!merged->IsValid()) {
        std::unique_ptr<OGRGeometry> repaired(merged->MakeValid());
        if (!repaired || !repaired->IsValid()) return Dissolved::failure("dissolved cells do not form a valid polygon" + quiet.detail());
        merged = std::move(repaired);
    }
    return merged;
}

} // namespace

int robotCount(const Plan& plan) {
    std::size_t count = std::max({plan.paths.size(), plan.allocation.startCell.size(), plan.allocation.costSeconds.size(),
                                  plan.metrics.robots.size()});
    for (const int robot : plan.allocation.robotOfCell) count = std::max(count, static_cast<std::size_t>(robot + 1));
    return static_cast<int>(count);
}

std::unique_ptr<OGRPolygon> cellSquare(const QuadTree& tree, const QuadCell& cell, double metresPerUnit) {
    const double unit = tree.fovMin;
    const double minX = snapped(cell.minX, tree.originX, unit) / metresPerUnit;
    const double maxX = snapped(cell.maxX(), tree.originX, unit) / metresPerUnit;
    const double minY = snapped(cell.minY, tree.originY, unit) / metresPerUnit;
    const double maxY = snapped(cell.maxY(), tree.originY, unit) / metresPerUnit;
    auto ring = std::make_unique<OGRLinearRing>();
    // Counter-clockwise exterior (right-hand rule).
    ring->addPoint(minX, minY);
    ring->addPoint(maxX, minY);
    ring->addPoint(maxX, maxY);
    ring->addPoint(minX, maxY);
    ring->addPoint(minX, minY);
    auto polygon = std::make_unique<OGRPolygon>();
    polygon->addRingDirectly(ring.release());
    return polygon;
}

Result<PlanFeatures> buildPlanFeatures(const Plan& plan, double metresPerUnit) {
    const QuadTree& tree = plan.quadTree;
    const int robots = robotCount(plan);
    const auto& owner = plan.allocation.robotOfCell;
    if (!owner.empty() && owner.size() != tree.activeCount()) {
        return Result<PlanFeatures>::failure("the allocation has " + std::to_string(owner.size()) + " cells but the quadtree has "
                                             + std::to_string(tree.activeCount()) + " active cells");
    }
    std::vector<std::vector<int>> cellsOfRobot(static_cast<std::size_t>(robots));
    std::vector<int> unreachableCells;
    std::vector<double> areaOfRobot(static_cast<std::size_t>(robots), 0.0);
    for (std::size_t index = 0; index < owner.size(); ++index) {
        const QuadCell& cell = tree.active(static_cast<int>(index));
        const int robot = owner[index];
        if (robot < 0) {
            unreachableCells.push_back(static_cast<int>(index));
        } else {
            cellsOfRobot[static_cast<std::size_t>(robot)].push_back(static_cast<int>(index));
            areaOfRobot[static_cast<std::size_t>(robot)] += cell.size * cell.size;
        }
    }

    PlanFeatures features;
    for (int robot = 0; robot < robots; ++robot) {
        const auto r = static_cast<std::size_t>(robot);
        auto region = dissolve(tree, cellsOfRobot[r], metresPerUnit);
        if (!region) return Result<PlanFeatures>::failure("robot " + std::to_string(robot) + " region: " + region.error());
        RegionFeature feature;
        feature.robot = robot;
        feature.geometry = std::move(region.value());
        feature.cells = static_cast<int>(cellsOfRobot[r].size());
        feature.areaSquareMetres = areaOfRobot[r];
        if (r < plan.allocation.costSeconds.size()) feature.costSeconds = plan.allocation.costSeconds[r];
        else if (r < plan.metrics.robots.size()) feature.costSeconds = plan.metrics.robots[r].costSeconds;
        features.regions.push_back(std::move(feature));
    }
    for (const CoveragePath& path : plan.paths) {
        if (path.waypoints.empty()) continue;
        PathFeature feature;
        feature.robot = path.robot;
        feature.geometry = std::make_unique<OGRLineString>();
        for (const Waypoint& waypoint : path.waypoints) {
            feature.geometry->addPoint(waypoint.x / metresPerUnit, waypoint.y / metresPerUnit);
        }
        feature.lengthMetres = path.lengthMetres;
        feature.timeSeconds = path.timeSeconds;
        feature.turns = path.turns;
        features.paths.push_back(std::move(feature));

        StartFeature start;
        start.robot = path.robot;
        start.geometry = std::make_unique<OGRPoint>(path.waypoints.front().x / metresPerUnit, path.waypoints.front().y / metresPerUnit);
        features.starts.push_back(std::move(start));
    }
    // Robots without a path still get their start: the centre of their start cell.
    for (std::size_t robot = 0; robot < plan.allocation.startCell.size(); ++robot) {
        const bool hasStart = std::any_of(features.starts.begin(), features.starts.end(),
                                          [&](const StartFeature& start) { return start.robot == static_cast<int>(robot); });
        const int cell = plan.allocation.startCell[robot];
        if (hasStart || cell < 0 || static_cast<std::size_t>(cell) >= tree.activeCount()) continue;
        StartFeature start;
        start.robot = static_cast<int>(robot);
        start.geometry = std::make_unique<OGRPoint>(tree.active(cell).centreX() / metresPerUnit, tree.active(cell).centreY() / metresPerUnit);
        features.starts.push_back(std::move(start));
    }
    std::sort(features.starts.begin(), features.starts.end(),
              [](const StartFeature& a, const StartFeature& b) { return a.robot < b.robot; });

    if (!unreachableCells.empty()) {
        auto dissolved = dissolve(tree, unreachableCells, metresPerUnit);
        if (!dissolved) return Result<PlanFeatures>::failure("unreachable cells: " + dissolved.error());
        const double squareMetresPerUnit = metresPerUnit * metresPerUnit;
        const auto addPart = [&](const OGRPolygon& polygon) {
            UnreachableFeature feature;
            feature.geometry.reset(polygon.clone());
            feature.areaSquareMetres = polygon.get_Area() * squareMetresPerUnit;
            features.unreachable.push_back(std::move(feature));
        };
        const OGRGeometry& geometry = *dissolved.value();
        const auto type = wkbFlatten(geometry.getGeometryType());
        if (type == wkbPolygon) {
            addPart(*geometry.toPolygon());
        } else if (type == wkbMultiPolygon) {
            for (const OGRPolygon* part : *geometry.toMultiPolygon()) addPart(*part);
        } else if (type == wkbGeometryCollection) {
            for (const OGRGeometry* part : *geometry.toGeometryCollection()) {
                if (wkbFlatten(part->getGeometryType()) == wkbPolygon) addPart(*part->toPolygon());
            }
        }
    }
    return features;
}

} // namespace mcpp::io::internal
