#pragma once

#include "core/model/Plan.hpp"
#include "io/GeoReference.hpp"
#include "io/PlanExport.hpp"
#include "io/Result.hpp"

#include <memory>
#include <ogr_geometry.h>
#include <vector>

namespace mcpp::io::internal {

struct RegionFeature {
    int robot = 0;
    // Built as a multipolygon in CRS units, empty for a robot without cells; in WGS84 it may be cut at the
    // antimeridian, as may the other features' geometries.
    std::unique_ptr<OGRGeometry> geometry;
    double timeSeconds = 0.0; // the robot's path at its own speed: what covering the region takes
    double costSeconds = 0.0; // what the region cost the division, at the class table's speeds
    double areaSquareMetres = 0.0;
    int cells = 0;
};

struct PathFeature {
    int robot = 0;
    std::unique_ptr<OGRGeometry> geometry; // a line string
    double lengthMetres = 0.0;
    double timeSeconds = 0.0;
    int turns = 0;
};

struct StartFeature {
    int robot = 0;
    std::unique_ptr<OGRPoint> geometry;
};

struct UnreachableFeature {
    std::unique_ptr<OGRGeometry> geometry; // a polygon
    double areaSquareMetres = 0.0;
};

// The cells a robot covered that were first given to another (a plan simulated with re-allocation).
struct TakenOverFeature {
    int robot = 0;
    std::unique_ptr<OGRGeometry> geometry; // a multipolygon
    double areaSquareMetres = 0.0;         // of its free sub-cells, as the regions count it
    int cells = 0;
};

// One polygon of the task area the user gave: of the area of interest, or a no-go zone.
struct AreaFeature {
    bool noGoZone = false;
    std::unique_ptr<OGRGeometry> geometry; // a polygon with its holes
    double areaSquareMetres = 0.0;
};

// The plan's vector content in the raster CRS's units (planning metres / metresPerUnit). Region and
// unreachable polygons are the outlines of the sub-cell grid of core/outlines/RegionLabels, traced, not
// unions of cells; paths are their turning points unless densePaths asks for every waypoint.
struct PlanFeatures {
    std::vector<RegionFeature> regions; // one per robot, also for robots without cells (empty geometry)
    std::vector<PathFeature> paths;
    std::vector<StartFeature> starts;
    std::vector<StartFeature> chargers; // of robots flying sorties from a charger away from their start
    std::vector<UnreachableFeature> unreachable; // one per connected part
    // One per robot that took cells over, for plans simulated over time (GeoPackage then writes the layer
    // even when empty; KML only when it has features).
    std::vector<TakenOverFeature> takenOver;
    bool simulatedOverTime = false;
    // The area of interest's polygons, then the no-go zones', as the context's area gives them (none without
    // one): a plan can then be checked against the area it was asked for in any GIS.
    std::vector<AreaFeature> area;
};

// From the context's plan, its (shared) region outlines, its CRS's units and its dense-paths setting.
[[nodiscard]] Result<PlanFeatures> buildPlanFeatures(const ExportContext& context);
// The square of one cell in CRS units, its corners computed from its placement on the bottom grid so that
// neighbouring cells share exactly the same edge coordinates.
[[nodiscard]] std::unique_ptr<OGRPolygon> cellSquare(const CellGraph& graph, const Cell& cell,
                                                     double metresPerUnit);
// Number of robots the plan describes.
[[nodiscard]] int robotCount(const Plan& plan);

} // namespace mcpp::io::internal
