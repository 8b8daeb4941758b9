#include "io/internal/PlanGeometry.hpp"

#include "core/coverage/StraightRunMerging.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/outlines/OutlineTracer.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "io/PlanExport.hpp"
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

OGRLinearRing* linearRing(const OutlineRing& outline, const LabelGrid& grid, double metresPerUnit) {
    auto* ring = new OGRLinearRing;
    const int count = static_cast<int>(outline.size());
    ring->setNumPoints(count + 1, FALSE);
    for (int i = 0; i <= count; ++i) {
        const GridVertex& vertex = outline[static_cast<std::size_t>(i % count)];
        ring->setPoint(i, grid.x(vertex.column) / metresPerUnit, grid.y(vertex.row) / metresPerUnit);
    }
    return ring;
}

std::unique_ptr<OGRPolygon> polygonOf(const OutlinePolygon& outline, const LabelGrid& grid,
                                      double metresPerUnit) {
    auto polygon = std::make_unique<OGRPolygon>();
    polygon->addRingDirectly(linearRing(outline.exterior, grid, metresPerUnit));
    for (const OutlineRing& hole : outline.holes)
        polygon->addRingDirectly(linearRing(hole, grid, metresPerUnit));
    return polygon;
}

PathFeature pathFeature(const CoveragePath& path, const CellGraph& cells, double metresPerUnit,
                        bool densePaths) {
    PathFeature feature;
    feature.robot = path.robot;
    auto line = std::make_unique<OGRLineString>();
    const std::vector<Waypoint> points = densePaths ? walkedWaypoints(path, cells) : turningPoints(path);
    line->setNumPoints(static_cast<int>(points.size()), FALSE);
    for (std::size_t i = 0; i < points.size(); ++i)
        line->setPoint(static_cast<int>(i), points[i].x / metresPerUnit, points[i].y / metresPerUnit);
    feature.geometry = std::move(line);
    feature.lengthMetres = path.lengthMetres;
    feature.timeSeconds = path.timeSeconds;
    feature.turns = path.turns;
    return feature;
}

void addStarts(const Plan& plan, double metresPerUnit, PlanFeatures& features) {
    for (const CoveragePath& path : plan.paths) {
        if (path.waypoints.empty())
            continue;
        // Where it starts: its take-off point where an aircraft takes off outside its path.
        const MapPoint start =
            path.takeOff ? *path.takeOff : MapPoint{path.waypoints.front().x, path.waypoints.front().y};
        features.starts.push_back(StartFeature{
            path.robot, std::make_unique<OGRPoint>(start.x / metresPerUnit, start.y / metresPerUnit)});
    }
    // Robots without a path still get their start: the centre of their start cell.
    const CellGraph& graph = plan.cells;
    for (std::size_t robot = 0; robot < plan.regions.startCell.size(); ++robot) {
        const bool hasStart =
            std::any_of(features.starts.begin(), features.starts.end(),
                        [&](const StartFeature& start) { return start.robot == static_cast<int>(robot); });
        const int cell = plan.regions.startCell[robot];
        if (hasStart || cell < 0 || static_cast<std::size_t>(cell) >= graph.size())
            continue;
        features.starts.push_back(StartFeature{
            static_cast<int>(robot), std::make_unique<OGRPoint>(graph.cell(cell).centreX() / metresPerUnit,
                                                                graph.cell(cell).centreY() / metresPerUnit)});
    }
    std::sort(features.starts.begin(), features.starts.end(),
              [](const StartFeature& a, const StartFeature& b) { return a.robot < b.robot; });
}

// The chargers of robots whose sorties fly from one away from their start (at the start, the start says it).
void addChargers(const Plan& plan, double metresPerUnit, PlanFeatures& features) {
    const SortieLayer* sorties = sortieLayerOf(plan);
    if (sorties == nullptr)
        return;
    for (const RobotSorties& robot : sorties->robots()) {
        const auto start =
            std::find_if(features.starts.begin(), features.starts.end(),
                         [&](const StartFeature& feature) { return feature.robot == robot.robot; });
        if (start != features.starts.end() &&
            !robot.chargerAwayFrom(
                {start->geometry->getX() * metresPerUnit, start->geometry->getY() * metresPerUnit}))
            continue;
        features.chargers.push_back(
            StartFeature{robot.robot, std::make_unique<OGRPoint>(robot.charger.x / metresPerUnit,
                                                                 robot.charger.y / metresPerUnit)});
    }
}

// One feature per robot with its figures; geometry filled from the outlines afterwards.
std::vector<RegionFeature> emptyRegions(const Plan& plan) {
    const int robots = robotCount(plan);
    std::vector<RegionFeature> regions(static_cast<std::size_t>(robots));
    for (int robot = 0; robot < robots; ++robot) {
        const auto r = static_cast<std::size_t>(robot);
        regions[r].robot = robot;
        regions[r].geometry = std::make_unique<OGRMultiPolygon>();
        if (r < plan.paths.size())
            regions[r].timeSeconds = plan.paths[r].timeSeconds;
        if (r < plan.regions.costSeconds.size())
            regions[r].costSeconds = plan.regions.costSeconds[r];
        else if (r < plan.metrics.robots.size())
            regions[r].costSeconds = plan.metrics.robots[r].costSeconds;
    }
    const auto& owner = plan.regions.robotOfCell;
    for (std::size_t id = 0; id < owner.size(); ++id) {
        if (owner[id] < 0)
            continue;
        const Cell& cell = plan.cells.cell(static_cast<int>(id));
        RegionFeature& region = regions[static_cast<std::size_t>(owner[id])];
        ++region.cells;
        region.areaSquareMetres += cell.freeAreaSquareMetres();
    }
    return regions;
}

// What each robot of a plan simulated over time took over from others, traced on a grid cropped to those
// cells.
void addTakenOver(const Plan& plan, double metresPerUnit, PlanFeatures& features) {
    const TimelineLayer* timeline = timelineLayerOf(plan);
    if (timeline == nullptr)
        return;
    features.simulatedOverTime = true;
    std::vector<int> featureOfRobot(static_cast<std::size_t>(robotCount(plan)), -1);
    for (const RobotTimeline& robot : timeline->robots()) {
        if (robot.cellsTakenOver.empty() || robot.robot < 0 ||
            static_cast<std::size_t>(robot.robot) >= featureOfRobot.size())
            continue;
        TakenOverFeature feature{robot.robot, std::make_unique<OGRMultiPolygon>(), 0.0,
                                 static_cast<int>(robot.cellsTakenOver.size())};
        for (const int id : robot.cellsTakenOver)
            if (id >= 0 && static_cast<std::size_t>(id) < plan.cells.size())
                feature.areaSquareMetres += plan.cells.cell(id).freeAreaSquareMetres();
        featureOfRobot[static_cast<std::size_t>(robot.robot)] = static_cast<int>(features.takenOver.size());
        features.takenOver.push_back(std::move(feature));
    }
    const LabelGrid grid = takenOverLabels(plan);
    for (const OutlinePolygon& outline : traceOutlines(grid)) {
        const auto robot = static_cast<std::size_t>(outline.label);
        const int feature = robot < featureOfRobot.size() ? featureOfRobot[robot] : -1;
        if (feature >= 0)
            features.takenOver[static_cast<std::size_t>(feature)]
                .geometry->toMultiPolygon()
                ->addGeometryDirectly(polygonOf(outline, grid, metresPerUnit).release());
    }
}

// Whether a ring has three corners at least, the first one given again at its end or not: GeoJSON and
// GeoPackage readers refuse a ring of fewer.
bool enclosesArea(const AreaOutline::Ring& corners) {
    const bool closed =
        corners.size() > 1 && corners.front().x == corners.back().x && corners.front().y == corners.back().y;
    return corners.size() >= (closed ? 4U : 3U);
}

// The area's polygons in CRS units, each with its area on the ground.
void addArea(const AreaOutline* area, double metresPerUnit, PlanFeatures& features) {
    if (area == nullptr)
        return;
    const auto add = [&](const std::vector<AreaOutline::Polygon>& polygons, bool noGoZone) {
        for (const AreaOutline::Polygon& rings : polygons) {
            if (rings.empty() || !enclosesArea(rings.front()))
                continue; // no outer ring to speak of
            auto polygon = std::make_unique<OGRPolygon>();
            for (const AreaOutline::Ring& corners : rings)
                if (enclosesArea(corners))
                    polygon->addRingDirectly(crsRing(corners, metresPerUnit).release());
            const double squareMetres = polygon->get_Area() * metresPerUnit * metresPerUnit;
            features.area.push_back(AreaFeature{noGoZone, std::move(polygon), squareMetres});
        }
    };
    add(area->include, false);
    add(area->exclude, true);
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

Result<PlanFeatures> buildPlanFeatures(const ExportContext& context) {
    const Plan& plan = context.plan;
    const double metresPerUnit = context.georeference.metresPerUnit();
    const bool densePaths = context.settings.densePaths;
    const auto& owner = plan.regions.robotOfCell;
    if (!owner.empty() && owner.size() != plan.cells.size()) {
        return Result<PlanFeatures>::failure("the regions name " + std::to_string(owner.size()) +
                                             " cells but the plan has " + std::to_string(plan.cells.size()) +
                                             " cells");
    }
    PlanFeatures features;
    features.regions = emptyRegions(plan);
    const RegionOutlines& outlines = context.outlines();
    const LabelGrid& labels = outlines.labels;
    const double pixelArea = labels.pixelSize * labels.pixelSize;
    for (const OutlinePolygon& outline : outlines.polygons) {
        if (outline.label == unreachableLabel) {
            features.unreachable.push_back(UnreachableFeature{
                polygonOf(outline, labels, metresPerUnit), static_cast<double>(outline.pixels) * pixelArea});
        } else if (outline.label >= 0 && static_cast<std::size_t>(outline.label) < features.regions.size()) {
            features.regions[static_cast<std::size_t>(outline.label)]
                .geometry->toMultiPolygon()
                ->addGeometryDirectly(polygonOf(outline, labels, metresPerUnit).release());
        }
    }
    for (const CoveragePath& path : plan.paths) {
        if (!path.waypoints.empty())
            features.paths.push_back(pathFeature(path, plan.cells, metresPerUnit, densePaths));
    }
    addStarts(plan, metresPerUnit, features);
    addChargers(plan, metresPerUnit, features);
    addTakenOver(plan, metresPerUnit, features);
    addArea(context.area, metresPerUnit, features);
    return features;
}

} // namespace mcpp::io::internal
