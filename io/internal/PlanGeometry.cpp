#include "io/internal/PlanGeometry.hpp"

#include "io/internal/GdalSupport.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::io::internal {

namespace {

std::unique_ptr<OGRPolygon> square(double minX, double minY, double maxX, double maxY) {
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

// The part of a cell a robot covers: the whole square, or the squares of its free sub-cells.
void addCoveredPart(const CellGraph& graph, const Cell& cell, double metresPerUnit, OGRMultiPolygon& parts) {
    if (cell.freeSubCells == allSubCells) {
        parts.addGeometryDirectly(cellSquare(graph, cell, metresPerUnit).release());
        return;
    }
    const GridFrame& frame = graph.frame();
    const double half = cell.span * frame.bottomCellSize / 2.0;
    const double west = frame.x(cell.column);
    const double north = frame.y(cell.row);
    for (SubCell subCell : subCellsCounterClockwise) {
        if (!cell.isFree(subCell))
            continue;
        const bool east = subCell == SubCell::NorthEast || subCell == SubCell::SouthEast;
        const bool south = subCell == SubCell::SouthWest || subCell == SubCell::SouthEast;
        const double minX = west + (east ? half : 0.0);
        const double maxY = north - (south ? half : 0.0);
        parts.addGeometryDirectly(square(minX / metresPerUnit, (maxY - half) / metresPerUnit,
                                         (minX + half) / metresPerUnit, maxY / metresPerUnit)
                                      .release());
    }
}

// Union of the covered parts of the given cells: valid polygons, shared edges dissolved.
Result<std::unique_ptr<OGRGeometry>> dissolve(const CellGraph& graph, const std::vector<int>& cellIds,
                                              double metresPerUnit) {
    using Dissolved = Result<std::unique_ptr<OGRGeometry>>;
    if (cellIds.empty())
        return std::unique_ptr<OGRGeometry>(std::make_unique<OGRMultiPolygon>());
    OGRMultiPolygon squares;
    for (const int id : cellIds)
        addCoveredPart(graph, graph.cell(id), metresPerUnit, squares);
    QuietGdalErrors quiet;
    std::unique_ptr<OGRGeometry> merged(squares.UnionCascaded());
    if (!merged)
        return Dissolved::failure("could not dissolve " + std::to_string(cellIds.size()) + " cells" +
                                  quiet.detail());
    if (!merged->IsValid()) {
        std::unique_ptr<OGRGeometry> repaired(merged->MakeValid());
        if (!repaired || !repaired->IsValid())
            return Dissolved::failure("dissolved cells do not form a valid polygon" + quiet.detail());
        merged = std::move(repaired);
    }
    return merged;
}

} // namespace

int robotCount(const Plan& plan) {
    std::size_t count = std::max({plan.paths.size(), plan.regions.startCell.size(),
                                  plan.regions.costSeconds.size(), plan.metrics.robots.size()});
    for (const int robot : plan.regions.robotOfCell)
        count = std::max(count, static_cast<std::size_t>(robot + 1));
    return static_cast<int>(count);
}

std::unique_ptr<OGRPolygon> cellSquare(const CellGraph& graph, const Cell& cell, double metresPerUnit) {
    const GridFrame& frame = graph.frame();
    return square(frame.x(cell.column) / metresPerUnit, frame.y(cell.row + cell.span) / metresPerUnit,
                  frame.x(cell.column + cell.span) / metresPerUnit, frame.y(cell.row) / metresPerUnit);
}

Result<PlanFeatures> buildPlanFeatures(const Plan& plan, double metresPerUnit) {
    const CellGraph& graph = plan.cells;
    const int robots = robotCount(plan);
    const auto& owner = plan.regions.robotOfCell;
    if (!owner.empty() && owner.size() != graph.size()) {
        return Result<PlanFeatures>::failure("the regions name " + std::to_string(owner.size()) +
                                             " cells but the plan has " + std::to_string(graph.size()) +
                                             " cells");
    }
    std::vector<std::vector<int>> cellsOfRobot(static_cast<std::size_t>(robots));
    std::vector<int> unreachableCells;
    std::vector<double> areaOfRobot(static_cast<std::size_t>(robots), 0.0);
    for (std::size_t index = 0; index < owner.size(); ++index) {
        const Cell& cell = graph.cell(static_cast<int>(index));
        const int robot = owner[index];
        if (robot < 0) {
            unreachableCells.push_back(static_cast<int>(index));
        } else {
            cellsOfRobot[static_cast<std::size_t>(robot)].push_back(static_cast<int>(index));
            areaOfRobot[static_cast<std::size_t>(robot)] +=
                cell.size * cell.size * cell.freeSubCellCount() / 4.0;
        }
    }

    PlanFeatures features;
    for (int robot = 0; robot < robots; ++robot) {
        const auto r = static_cast<std::size_t>(robot);
        auto region = dissolve(graph, cellsOfRobot[r], metresPerUnit);
        if (!region)
            return Result<PlanFeatures>::failure("robot " + std::to_string(robot) +
                                                 " region: " + region.error());
        RegionFeature feature;
        feature.robot = robot;
        feature.geometry = std::move(region.value());
        feature.cells = static_cast<int>(cellsOfRobot[r].size());
        feature.areaSquareMetres = areaOfRobot[r];
        if (r < plan.regions.costSeconds.size())
            feature.costSeconds = plan.regions.costSeconds[r];
        else if (r < plan.metrics.robots.size())
            feature.costSeconds = plan.metrics.robots[r].costSeconds;
        features.regions.push_back(std::move(feature));
    }
    for (const CoveragePath& path : plan.paths) {
        if (path.waypoints.empty())
            continue;
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
        start.geometry = std::make_unique<OGRPoint>(path.waypoints.front().x / metresPerUnit,
                                                    path.waypoints.front().y / metresPerUnit);
        features.starts.push_back(std::move(start));
    }
    // Robots without a path still get their start: the centre of their start cell.
    for (std::size_t robot = 0; robot < plan.regions.startCell.size(); ++robot) {
        const bool hasStart =
            std::any_of(features.starts.begin(), features.starts.end(),
                        [&](const StartFeature& start) { return start.robot == static_cast<int>(robot); });
        const int cell = plan.regions.startCell[robot];
        if (hasStart || cell < 0 || static_cast<std::size_t>(cell) >= graph.size())
            continue;
        StartFeature start;
        start.robot = static_cast<int>(robot);
        start.geometry = std::make_unique<OGRPoint>(graph.cell(cell).centreX() / metresPerUnit,
                                                    graph.cell(cell).centreY() / metresPerUnit);
        features.starts.push_back(std::move(start));
    }
    std::sort(features.starts.begin(), features.starts.end(),
              [](const StartFeature& a, const StartFeature& b) { return a.robot < b.robot; });

    if (!unreachableCells.empty()) {
        auto dissolved = dissolve(graph, unreachableCells, metresPerUnit);
        if (!dissolved)
            return Result<PlanFeatures>::failure("unreachable cells: " + dissolved.error());
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
            for (const OGRPolygon* part : *geometry.toMultiPolygon())
                addPart(*part);
        } else if (type == wkbGeometryCollection) {
            for (const OGRGeometry* part : *geometry.toGeometryCollection()) {
                if (wkbFlatten(part->getGeometryType()) == wkbPolygon)
                    addPart(*part->toPolygon());
            }
        }
    }
    return features;
}

} // namespace mcpp::io::internal
