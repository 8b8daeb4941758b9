#pragma once

#include "core/coverage/ImpassableCrossings.hpp"
#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/Plan.hpp"
#include "core/outlines/RegionOutlines.hpp"
#include "render/MapLayers.hpp"

#include <QImage>
#include <QPolygonF>
#include <QRectF>
#include <QSizeF>
#include <QTransform>
#include <optional>
#include <utility>
#include <vector>

class QPainter;

namespace mcpp::render {

// Paints a land-cover map and a plan over it with any QPainter (widget, image, SVG) through a
// world-to-device transform, so the GUI canvas and headless batch mode draw the same picture.
// The grid, class table and plan are borrowed: they must outlive the renderer or be replaced first.
class PlanRenderer {
  public:
    // Rebuilds the cached land-cover image; call again when the class colours change.
    void setMap(const ClassGrid* grid, const ClassTable* classes);
    // outlines: the plan's, when the caller has them already (exports share one tracing); else traced here.
    // crossings: the plan's cells over impassable land, when the caller has found them; else found here.
    void setPlan(const Plan* plan, const RegionOutlines* outlines = nullptr,
                 const std::vector<ImpassableCrossing>* crossings = nullptr);
    // Start points to draw; when empty the first waypoint of each path is used.
    void setStarts(std::vector<MapPoint> starts);
    // Each robot's charger away from its start, as placed (none: at its start); without them, those of
    // the plan's sorties.
    void setChargers(std::vector<std::optional<MapPoint>> chargers) { chargers_ = std::move(chargers); }
    // By robot, how far its aircraft flies out and back in one flight (io::flightReachMetres), drawn as a
    // dashed ring round its start: ground outside cannot be covered from there. 0: no ring.
    void setFlightReach(std::vector<double> metres) { flightReach_ = std::move(metres); }
    // The area of interest's and the no-go zones' edges, drawn over the plan (a dashed line; no-go zones
    // hatched red), with or without a plan.
    void setArea(const AreaOutline& area);
    void setLayers(const MapLayers& layers) { layers_ = layers; }
    // A plan simulated over time shown at one moment: each path as driven so far, each robot where it is.
    // Empty: the whole paths.
    void setTimelineSeconds(std::optional<double> seconds) { timelineSeconds_ = seconds; }
    [[nodiscard]] std::optional<double> timelineSeconds() const { return timelineSeconds_; }
    // A plan that no longer matches the inputs is drawn faded.
    void setPlanStale(bool stale) { planStale_ = stale; }
    // The start drawn with a selection ring, -1 for none.
    void setSelectedStart(int robot) { selectedStart_ = robot; }

    [[nodiscard]] const MapLayers& layers() const { return layers_; }
    [[nodiscard]] const QImage& landCoverImage() const { return landCoverImage_; }
    [[nodiscard]] const ClassGrid* grid() const { return grid_; }
    [[nodiscard]] const Plan* plan() const { return plan_; }

    // Draws everything visible inside deviceArea (device pixels). worldToDevice must be an axis-aligned
    // scale with y flipped (map north up) plus a translation.
    void paint(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    // The two parts of paint: the map (land cover and plan layers), which a view may keep as an image
    // while the starts above it move, and the start markers.
    void paintMap(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintStartMarkers(QPainter& painter, const QTransform& worldToDevice) const;

    // The transform that fits the grid into a device area of `size`, centred, keeping aspect.
    [[nodiscard]] static QTransform fitTransform(const ClassGrid& grid, const QSizeF& size,
                                                 double margin = 0.0);
    // The colour a raster value is drawn in.
    [[nodiscard]] static QRgb classColour(const ClassTable& classes, std::int32_t value);

  private:
    // What setPlan prepares once so that a repaint only draws: the regions as an image on the sub-cell grid,
    // their borders and the unreachable parts as outlines, the paths as turning points.
    struct Outline {
        QPolygonF ring; // world coordinates, closed
        QRectF bounds;
    };
    struct PathLine {
        int robot = 0;
        bool alternate = false; // every second sortie of a robot on a battery, drawn darker
        QPolygonF points;       // world coordinates, turning points only
        QRectF bounds;
    };
    // An image covering a rectangle of the map, drawn like the land cover.
    struct GridImage {
        QImage image;
        QRectF world; // x = west..east, y = south..north
    };
    void prepareRegions(const RegionOutlines* given);
    void prepareDetection();
    void prepareTakenOver();
    void preparePaths();
    void addPathLine(const CoveragePath& path, bool alternate);
    void drawGridImage(QPainter& painter, const GridImage& grid, const QTransform& worldToDevice,
                       const QRectF& deviceArea) const;
    void drawPyramid(QPainter& painter, const std::vector<GridImage>& pyramid,
                     const QTransform& worldToDevice, const QRectF& deviceArea) const;
    [[nodiscard]] static std::vector<GridImage> pyramidOf(QImage image, const QRectF& world);
    // An outline's rings (exterior, then holes) as closed polygons in planning metres.
    [[nodiscard]] static std::vector<Outline> outlineRings(const OutlinePolygon& outline,
                                                           const LabelGrid& grid);
    void paintLandCover(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintRegions(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintRegionBorders(QPainter& painter, const QTransform& worldToDevice,
                            const QRectF& deviceArea) const;
    void paintUnreachable(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintTakenOver(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintQuadTree(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintPaths(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintPathsAt(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea,
                      double seconds) const;
    void drawPathLine(QPainter& painter, const QPolygonF& points, const QColor& colour,
                      const QTransform& worldToDevice, const QRectF& visibleDevice, bool dense) const;
    void paintCrossings(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintArea(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const;
    void paintStarts(QPainter& painter, const QTransform& worldToDevice) const;
    void paintChargers(QPainter& painter, const QTransform& worldToDevice) const;
    void paintTakeOffLegs(QPainter& painter, const QTransform& worldToDevice) const;
    void paintFlightReach(QPainter& painter, const QTransform& worldToDevice,
                          std::vector<MapPoint> starts) const;
    static void drawCharger(QPainter& painter, QPointF centre, const QColor& colour);

    std::vector<GridImage> landCoverPyramid_; // halved again and again, for zoomed-out views
    std::vector<GridImage> regionPyramid_;
    std::vector<GridImage> detectionPyramid_; // empty when the plan has no detection layer
    std::vector<Outline> regionBorders_;
    std::vector<Outline> unreachableOutlines_;
    // A polygon of the area: its rings (outer, then holes) and their bounds.
    struct AreaPolygon {
        std::vector<QPolygonF> rings; // world coordinates, closed
        QRectF bounds;
    };
    std::vector<AreaPolygon> areaEdges_;                     // the area of interest's polygons
    std::vector<AreaPolygon> noGoEdges_;                     // the no-go zones' polygons
    std::vector<std::pair<int, Outline>> takenOverOutlines_; // (robot, outline): the cells it took over
    std::vector<std::optional<MapPoint>> chargers_;          // by robot: a charger away from its start
    std::vector<double> flightReach_;                        // by robot, metres; 0: none
    std::vector<QRectF> crossingCells_; // world rectangles of cells whose path crosses impassable land
    std::vector<PathLine> pathLines_;
    double meanStepMetres_ = 0.0; // mean distance between consecutive waypoints
    const ClassGrid* grid_ = nullptr;
    const ClassTable* classes_ = nullptr;
    const Plan* plan_ = nullptr;
    std::vector<MapPoint> starts_;
    MapLayers layers_;
    QImage landCoverImage_;
    bool planStale_ = false;
    int selectedStart_ = -1;
    std::optional<double> timelineSeconds_;
};

} // namespace mcpp::render
