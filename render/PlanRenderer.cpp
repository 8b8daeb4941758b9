#include "render/PlanRenderer.hpp"

#include "core/coverage/ImpassableCrossings.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/outlines/OutlineTracer.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "core/outlines/RegionOutlines.hpp"
#include "io/PlanExport.hpp"
#include "render/DetectionPalette.hpp"
#include "render/RobotPalette.hpp"

#include <QFont>
#include <QGuiApplication>
#include <QLineF>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <utility>

namespace mcpp::render {

namespace {

constexpr double kArrowSpacingPixels = 90.0;
constexpr double kArrowLengthPixels = 10.0;
constexpr double kStartRadiusPixels = 10.0;
// Below this on-screen side a cell outline only adds noise, so it is skipped.
constexpr double kSmallestOutlinedCellPixels = 8.0;

QRectF deviceRectOf(const QTransform& worldToDevice, double minX, double minY, double maxX, double maxY) {
    return worldToDevice.mapRect(QRectF(QPointF(minX, minY), QPointF(maxX, maxY))).normalized();
}

QRectF deviceRectOf(const QTransform& worldToDevice, const Cell& cell) {
    return deviceRectOf(worldToDevice, cell.minX, cell.minY, cell.maxX(), cell.maxY());
}

void drawArrow(QPainter& painter, QPointF tip, QPointF direction, const QColor& colour) {
    const double length = std::hypot(direction.x(), direction.y());
    if (length <= 0.0)
        return;
    const QPointF unit(direction.x() / length, direction.y() / length);
    const QPointF normal(-unit.y(), unit.x());
    const QPointF base = tip - unit * kArrowLengthPixels;
    const QPolygonF head(
        {tip, base + normal * (kArrowLengthPixels * 0.5), base - normal * (kArrowLengthPixels * 0.5)});
    painter.setPen(QPen(QColor(255, 255, 255, 220), 1.0));
    painter.setBrush(colour);
    painter.drawPolygon(head);
}

// The whole pixels, as first and count, that a line `pixels` wide covers along one axis from `from` to
// `to` (from <= to) with square caps, or across it (from == to). Every end rounds the same way, so
// segments that meet at a point meet on the same pixels. Widths round to whole pixels (1.5 draws 2).
std::pair<int, int> pixelSpan(double from, double to, int pixels) {
    // Halves round up on both sides of 0 (std::lround would round them away from it): a casing and the
    // line inside it then share their middle whatever the position.
    const auto rounded = [](double value) { return static_cast<int>(std::floor(value + 0.5)); };
    const double half = pixels / 2.0;
    const int start = rounded(from - half);
    return {start, rounded(to - half) + pixels - start};
}

// A wide opaque line with square caps and mitred corners. Qt strokes a wide polyline as one polygon whose
// filling slows down sharply as the line crosses itself (coverage paths pass close by themselves all the
// time). The axis-aligned segments, nearly all of a coverage path or a region's outline, are filled as
// rectangles of whole pixels reaching half the width past their ends, which meet as mitred corners do.
// Whole pixels without antialiasing take the raster engine's plain fill, crisp, where fractional
// rectangles went through its antialiasing rasterizer (a 49 x 49 plan with 20 robots: its sheet painted
// in 15 ms instead of 20 ms). Other segments are stroked. Opaque: a translucent colour would show where the
// rectangles overlap.
void drawWideLine(QPainter& painter, const QPolygonF& line, const QColor& colour, double width) {
    const int pixels = std::max(1, static_cast<int>(std::lround(width)));
    painter.setPen(QPen(colour, width, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
    const bool antialiased = painter.testRenderHint(QPainter::Antialiasing);
    for (qsizetype i = 1; i < line.size(); ++i) {
        const QPointF from = line[i - 1];
        const QPointF to = line[i];
        if (from.x() != to.x() && from.y() != to.y()) {
            painter.setRenderHint(QPainter::Antialiasing, antialiased);
            painter.drawLine(from, to);
            continue;
        }
        const auto [left, columns] =
            pixelSpan(std::min(from.x(), to.x()), std::max(from.x(), to.x()), pixels);
        const auto [top, rows] = pixelSpan(std::min(from.y(), to.y()), std::max(from.y(), to.y()), pixels);
        painter.setRenderHint(QPainter::Antialiasing, false);
        painter.fillRect(QRect(left, top, columns, rows), colour);
    }
    painter.setRenderHint(QPainter::Antialiasing, antialiased);
}

// Whether two rectangles share a point; unlike QRectF::intersects, true for a straight line's flat bounds.
bool touches(const QRectF& a, const QRectF& b) {
    return a.left() <= b.right() && b.left() <= a.right() && a.top() <= b.bottom() && b.top() <= a.bottom();
}

// An image and its halvings down to about a thousand pixels a side: a zoomed-out view draws a small image
// instead of shrinking millions of pixels at every repaint.
template <typename GridImage> std::vector<GridImage> halvings(QImage image, const QRectF& world) {
    std::vector<GridImage> pyramid;
    if (image.isNull())
        return pyramid;
    pyramid.push_back({std::move(image), world});
    while (std::max(pyramid.back().image.width(), pyramid.back().image.height()) > 1024) {
        const QImage& previous = pyramid.back().image;
        QImage half = previous.scaled(std::max(1, previous.width() / 2), std::max(1, previous.height() / 2),
                                      Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
        pyramid.push_back({std::move(half), world});
    }
    return pyramid;
}

// The parts of a line (world coordinates) that cross the visible area, in device coordinates, with points
// closer than a pixel to the previous one dropped: a zoomed-out view of millions of waypoints draws
// thousands, and a zoomed-in view only what is on screen.
std::vector<QPolygonF> visibleRuns(const QPolygonF& line, const QTransform& worldToDevice,
                                   const QRectF& visible) {
    // The transform is a scale and a shift (north up): mapped by hand, as this runs over every point.
    const double scaleX = worldToDevice.m11(), scaleY = worldToDevice.m22();
    const double shiftX = worldToDevice.dx(), shiftY = worldToDevice.dy();
    const double left = visible.left(), right = visible.right(), top = visible.top(),
                 bottom = visible.bottom();
    std::vector<QPolygonF> runs;
    QPolygonF run;
    double previousX = line.front().x() * scaleX + shiftX;
    double previousY = line.front().y() * scaleY + shiftY;
    for (qsizetype i = 1; i < line.size(); ++i) {
        const double x = line[i].x() * scaleX + shiftX;
        const double y = line[i].y() * scaleY + shiftY;
        const bool outside = std::max(x, previousX) < left || std::min(x, previousX) > right ||
                             std::max(y, previousY) < top || std::min(y, previousY) > bottom;
        if (outside) {
            if (run.size() > 1)
                runs.push_back(std::move(run));
            run = QPolygonF();
        } else {
            if (run.isEmpty())
                run << QPointF(previousX, previousY);
            const QPointF last = run.back();
            if (i + 1 == line.size() || std::abs(x - last.x()) + std::abs(y - last.y()) >= 1.0)
                run << QPointF(x, y);
        }
        previousX = x;
        previousY = y;
    }
    if (run.size() > 1)
        runs.push_back(std::move(run));
    return runs;
}

// Arrows at even on-screen spacing show the direction of travel.
void drawArrows(QPainter& painter, const QPolygonF& line, const QColor& colour) {
    double untilNextArrow = kArrowSpacingPixels / 2.0;
    for (qsizetype i = 1; i < line.size(); ++i) {
        const QPointF from = line[i - 1];
        const QPointF to = line[i];
        const double segment = QLineF(from, to).length();
        double along = 0.0;
        while (segment - along >= untilNextArrow) {
            along += untilNextArrow;
            const QPointF tip = from + (to - from) * (along / segment);
            drawArrow(painter, tip, to - from, colour);
            untilNextArrow = kArrowSpacingPixels;
        }
        untilNextArrow -= segment - along;
    }
}

} // namespace

std::vector<PlanRenderer::GridImage> PlanRenderer::pyramidOf(QImage image, const QRectF& world) {
    return halvings<GridImage>(std::move(image), world);
}

void PlanRenderer::setMap(const ClassGrid* grid, const ClassTable* classes) {
    grid_ = grid;
    classes_ = classes;
    landCoverImage_ = QImage();
    landCoverPyramid_.clear();
    if (grid_ == nullptr || classes_ == nullptr || grid_->columns <= 0 || grid_->rows <= 0)
        return;
    if (grid_->values.size() <
        static_cast<std::size_t>(grid_->columns) * static_cast<std::size_t>(grid_->rows))
        return;

    std::unordered_map<std::int32_t, QRgb> colours;
    for (const auto& landCoverClass : classes_->classes())
        colours[landCoverClass.value] = classColour(*classes_, landCoverClass.value);
    const QRgb unknown = qRgb(200, 200, 200);

    landCoverImage_ = QImage(grid_->columns, grid_->rows, QImage::Format_ARGB32);
    for (int row = 0; row < grid_->rows; ++row) {
        auto* line = reinterpret_cast<QRgb*>(landCoverImage_.scanLine(row));
        for (int column = 0; column < grid_->columns; ++column) {
            if (grid_->isOutside(column, row)) {
                line[column] = qRgba(0, 0, 0, 0);
                continue;
            }
            const auto found = colours.find(grid_->valueAt(column, row));
            line[column] = found == colours.end() ? unknown : found->second;
        }
    }
    landCoverPyramid_ =
        pyramidOf(landCoverImage_, QRectF(grid_->originX, grid_->minY(), grid_->maxX() - grid_->originX,
                                          grid_->originY - grid_->minY()));
}

void PlanRenderer::setPlan(const Plan* plan, const RegionOutlines* outlines,
                           const std::vector<ImpassableCrossing>* crossings) {
    plan_ = plan;
    prepareRegions(outlines);
    prepareDetection();
    prepareTakenOver();
    preparePaths();
    crossingCells_.clear();
    if (plan_ == nullptr || grid_ == nullptr || classes_ == nullptr)
        return;
    std::vector<ImpassableCrossing> found;
    if (crossings == nullptr) {
        found = impassableCrossings(plan_->cells, plan_->regions, *grid_, *classes_);
        crossings = &found;
    }
    for (const ImpassableCrossing& crossing : *crossings) {
        const Cell& cell = plan_->cells.cell(crossing.cell);
        crossingCells_.emplace_back(cell.minX, cell.minY, cell.size, cell.size);
    }
}

std::vector<PlanRenderer::Outline> PlanRenderer::outlineRings(const OutlinePolygon& outline,
                                                              const LabelGrid& grid) {
    std::vector<PlanRenderer::Outline> rings;
    const auto add = [&](const OutlineRing& ring) {
        QPolygonF polygon;
        polygon.reserve(static_cast<qsizetype>(ring.size()) + 1);
        for (const GridVertex& vertex : ring)
            polygon << QPointF(grid.x(vertex.column), grid.y(vertex.row));
        polygon << polygon.front();
        rings.push_back({polygon, polygon.boundingRect()});
    };
    add(outline.exterior);
    for (const OutlineRing& hole : outline.holes)
        add(hole);
    return rings;
}

namespace {

// Pixels of a grid per image pixel side: 1, or more on grids beyond 16 million cells.
int imageStep(int columns, int rows) {
    constexpr std::int64_t largestImage = 16'000'000;
    int step = 1;
    while (static_cast<std::int64_t>(columns / step) * (rows / step) > largestImage)
        ++step;
    return step;
}

} // namespace

void PlanRenderer::prepareRegions(const RegionOutlines* given) {
    regionPyramid_.clear();
    regionBorders_.clear();
    unreachableOutlines_.clear();
    if (plan_ == nullptr || plan_->regions.robotOfCell.empty() || plan_->cells.empty())
        return;
    RegionOutlines traced;
    if (given == nullptr)
        traced = regionOutlines(*plan_);
    const RegionOutlines& outlines = given != nullptr ? *given : traced;
    const LabelGrid& labels = outlines.labels;
    // One image pixel per sub-cell, or per block of them on maps beyond 16 million sub-cells.
    const int step = imageStep(labels.columns, labels.rows);
    const int width = (labels.columns + step - 1) / step;
    const int height = (labels.rows + step - 1) / step;
    QImage image(width, height, QImage::Format_ARGB32);
    const QRgb unreachable = qRgba(120, 0, 0, 50);
    for (int row = 0; row < height; ++row) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(row));
        for (int column = 0; column < width; ++column) {
            const std::int32_t label = labels.at(std::min(column * step + step / 2, labels.columns - 1),
                                                 std::min(row * step + step / 2, labels.rows - 1));
            if (label >= 0) {
                const QColor colour = RobotPalette::colour(label);
                line[column] = qRgba(colour.red(), colour.green(), colour.blue(), 80);
            } else {
                line[column] = label == unreachableLabel ? unreachable : qRgba(0, 0, 0, 0);
            }
        }
    }
    const double size = labels.pixelSize * step;
    regionPyramid_ =
        pyramidOf(image, QRectF(labels.originX, labels.originY - height * size, width * size, height * size));

    for (const OutlinePolygon& outline : outlines.polygons) {
        auto& target = outline.label == unreachableLabel ? unreachableOutlines_ : regionBorders_;
        if (outline.label < 0 && outline.label != unreachableLabel)
            continue;
        const std::vector<Outline> rings = outlineRings(outline, labels);
        target.insert(target.end(), rings.begin(), rings.end());
    }
}

// The cells each robot of a plan simulated over time took over from others, traced on a grid cropped to
// them.
void PlanRenderer::prepareTakenOver() {
    takenOverOutlines_.clear();
    if (plan_ == nullptr)
        return;
    const LabelGrid grid = takenOverLabels(*plan_);
    for (const OutlinePolygon& outline : traceOutlines(grid))
        for (const Outline& ring : outlineRings(outline, grid))
            takenOverOutlines_.emplace_back(outline.label, ring);
}

void PlanRenderer::prepareDetection() {
    detectionPyramid_.clear();
    const DetectionLayer* layer = plan_ == nullptr ? nullptr : detectionLayerOf(*plan_);
    if (layer == nullptr || layer->grid().columns == 0 || layer->grid().rows == 0)
        return;
    const DetectionGrid& grid = layer->grid();
    // One image pixel per lattice cell, or per block of them on the largest maps.
    const int step = imageStep(grid.columns, grid.rows);
    const int width = (grid.columns + step - 1) / step;
    const int height = (grid.rows + step - 1) / step;
    // Of a block, the cell seen least for what it needs shows: a gap must not vanish when zoomed out.
    std::vector<std::size_t> shown(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                   grid.required.size());
    const auto share = [&grid](std::size_t index) {
        return grid.required[index] > 0.0F ? grid.probability[index] / grid.required[index] : 2.0F;
    };
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            const std::size_t index =
                static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.columns) + column;
            if (std::isnan(grid.required[index]))
                continue;
            std::size_t& block =
                shown[static_cast<std::size_t>(row / step) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(column / step)];
            if (block == grid.required.size() || share(index) < share(block))
                block = index;
        }
    QImage image(width, height, QImage::Format_ARGB32);
    for (int row = 0; row < height; ++row) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(row));
        for (int column = 0; column < width; ++column) {
            const std::size_t index = shown[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                                            static_cast<std::size_t>(column)];
            line[column] = index == grid.required.size()
                               ? qRgba(0, 0, 0, 0)
                               : DetectionPalette::colour(grid.probability[index], grid.required[index]);
        }
    }
    const double size = grid.cellSize * step;
    detectionPyramid_ =
        pyramidOf(image, QRectF(grid.originX, grid.originY - height * size, width * size, height * size));
}

namespace {

// A path's length as measured; summed here only for a path not measured (one made by hand): on a large map
// a pass over hundreds of millions of waypoints.
double lengthOf(const CoveragePath& path) {
    return path.lengthMetres > 0.0 ? path.lengthMetres : pathLengthMetres(path.waypoints);
}

} // namespace

void PlanRenderer::addPathLine(const CoveragePath& path, bool alternate) {
    PathLine line;
    line.robot = path.robot;
    line.alternate = alternate;
    const std::vector<Waypoint> corners = io::turningPoints(path);
    line.points.reserve(static_cast<qsizetype>(corners.size()) + 1);
    for (const Waypoint& waypoint : corners)
        line.points << QPointF(waypoint.x, waypoint.y);
    if (path.closed && line.points.front() != line.points.back())
        line.points << line.points.front();
    line.bounds = line.points.boundingRect();
    pathLines_.push_back(std::move(line));
}

void PlanRenderer::preparePaths() {
    pathLines_.clear();
    meanStepMetres_ = 0.0;
    if (plan_ == nullptr)
        return;
    double length = 0.0;
    std::size_t steps = 0;
    for (const CoveragePath& path : plan_->paths) {
        if (path.waypoints.size() < 2)
            continue;
        length += lengthOf(path);
        steps += std::max(path.waypoints.size(), path.walkedWaypoints) - 1; // the walk's, runs merged or not
        const RobotSorties* sorties = sortiesOfRobot(*plan_, path.robot);
        if (sorties == nullptr || sorties->sorties.size() < 2) {
            addPathLine(path, false);
            continue;
        }
        // Each sortie a line of its own, every second one darker, so the flights between charges show.
        for (std::size_t sortie = 0; sortie < sorties->sorties.size(); ++sortie)
            addPathLine(sortiePath(path, sorties->sorties[sortie]), sortie % 2 == 1);
    }
    meanStepMetres_ = steps == 0 ? 0.0 : length / static_cast<double>(steps);
}

void PlanRenderer::setStarts(std::vector<MapPoint> starts) {
    starts_ = std::move(starts);
}

QRgb PlanRenderer::classColour(const ClassTable& classes, std::int32_t value) {
    const LandCoverClass* found = classes.find(value);
    if (found == nullptr)
        return qRgb(200, 200, 200);
    const std::uint32_t rgb = found->colorRgb;
    return qRgb(static_cast<int>((rgb >> 16) & 0xffu), static_cast<int>((rgb >> 8) & 0xffu),
                static_cast<int>(rgb & 0xffu));
}

QTransform PlanRenderer::fitTransform(const ClassGrid& grid, const QSizeF& size, double margin) {
    const double width = std::max(grid.width(), 1e-9);
    const double height = std::max(grid.height(), 1e-9);
    const double availableWidth = std::max(size.width() - 2.0 * margin, 1.0);
    const double availableHeight = std::max(size.height() - 2.0 * margin, 1.0);
    const double scale = std::min(availableWidth / width, availableHeight / height);
    const double offsetX = (size.width() - width * scale) / 2.0;
    const double offsetY = (size.height() - height * scale) / 2.0;
    // device x = (x - originX) * scale + offsetX; device y = (originY - y) * scale + offsetY
    return QTransform(scale, 0.0, 0.0, -scale, offsetX - grid.originX * scale,
                      offsetY + grid.originY * scale);
}

void PlanRenderer::paint(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea) const {
    paintMap(painter, worldToDevice, deviceArea);
    paintStartMarkers(painter, worldToDevice);
}

void PlanRenderer::paintMap(QPainter& painter, const QTransform& worldToDevice,
                            const QRectF& deviceArea) const {
    painter.save();
    painter.setTransform(QTransform());
    if (layers_.landCover)
        paintLandCover(painter, worldToDevice, deviceArea);
    if (plan_ != nullptr) {
        // Cells along the raster's east and south edges may reach past it (a raster of an odd number of
        // pixels under cells of two): what lies there is no map, so the plan is drawn within the raster.
        if (grid_ != nullptr)
            painter.setClipRect(
                deviceRectOf(worldToDevice, grid_->originX, grid_->minY(), grid_->maxX(), grid_->originY),
                painter.hasClipping() ? Qt::IntersectClip : Qt::ReplaceClip);
        if (planStale_)
            painter.setOpacity(0.45);
        // A detection plan shows what its passes see where other plans tint their regions.
        const bool detection = layers_.detection && !detectionPyramid_.empty();
        if (detection)
            drawPyramid(painter, detectionPyramid_, worldToDevice, deviceArea);
        if (layers_.regions && !detection)
            paintRegions(painter, worldToDevice, deviceArea);
        if (layers_.regions && !detection)
            paintTakenOver(painter, worldToDevice, deviceArea);
        if (layers_.unreachable)
            paintUnreachable(painter, worldToDevice, deviceArea);
        if (layers_.quadTree)
            paintQuadTree(painter, worldToDevice, deviceArea);
        if (layers_.regions)
            paintRegionBorders(painter, worldToDevice, deviceArea);
        if (layers_.crossings)
            paintCrossings(painter, worldToDevice, deviceArea);
        if (layers_.paths && timelineSeconds_ && timelineLayerOf(*plan_) != nullptr)
            paintPathsAt(painter, worldToDevice, deviceArea, *timelineSeconds_);
        else if (layers_.paths)
            paintPaths(painter, worldToDevice, deviceArea);
        painter.setOpacity(1.0);
    }
    painter.restore();
    // Over the plan, and past the raster's edge within the caller's clip: what was asked for, against the
    // cells that cover it.
    if (layers_.area) {
        painter.save();
        painter.setTransform(QTransform());
        paintArea(painter, worldToDevice, deviceArea);
        painter.restore();
    }
}

void PlanRenderer::paintStartMarkers(QPainter& painter, const QTransform& worldToDevice) const {
    if (!layers_.starts)
        return;
    painter.save();
    painter.setTransform(QTransform());
    paintStarts(painter, worldToDevice);
    painter.restore();
}

void PlanRenderer::drawGridImage(QPainter& painter, const GridImage& grid, const QTransform& worldToDevice,
                                 const QRectF& deviceArea) const {
    if (grid.image.isNull())
        return;
    const QRectF full = deviceRectOf(worldToDevice, grid.world.left(), grid.world.top(), grid.world.right(),
                                     grid.world.bottom());
    const QRectF visible = full.intersected(deviceArea);
    if (visible.isEmpty())
        return;
    // Only the visible pixels are drawn, on whole-pixel boundaries, so deep zooms stay fast and crisp.
    const int columns = grid.image.width();
    const int rows = grid.image.height();
    const double pixelsPerColumn = full.width() / columns;
    const double pixelsPerRow = full.height() / rows;
    const int firstColumn = std::clamp(
        static_cast<int>(std::floor((visible.left() - full.left()) / pixelsPerColumn)), 0, columns - 1);
    const int lastColumn =
        std::clamp(static_cast<int>(std::ceil((visible.right() - full.left()) / pixelsPerColumn)),
                   firstColumn + 1, columns);
    const int firstRow =
        std::clamp(static_cast<int>(std::floor((visible.top() - full.top()) / pixelsPerRow)), 0, rows - 1);
    const int lastRow = std::clamp(
        static_cast<int>(std::ceil((visible.bottom() - full.top()) / pixelsPerRow)), firstRow + 1, rows);
    const QRect source(firstColumn, firstRow, lastColumn - firstColumn, lastRow - firstRow);
    const QRectF target(full.left() + firstColumn * pixelsPerColumn, full.top() + firstRow * pixelsPerRow,
                        source.width() * pixelsPerColumn, source.height() * pixelsPerRow);
    // Zoomed out, smoothing averages many pixels into one; zoomed in, the pixels stay square.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, pixelsPerColumn < 1.0);
    painter.drawImage(target, grid.image, source);
}

void PlanRenderer::drawPyramid(QPainter& painter, const std::vector<GridImage>& pyramid,
                               const QTransform& worldToDevice, const QRectF& deviceArea) const {
    if (pyramid.empty())
        return;
    // The smallest level whose pixels are still at least one device pixel wide.
    const double deviceWidth = pyramid.front().world.width() * std::abs(worldToDevice.m11());
    std::size_t level = 0;
    while (level + 1 < pyramid.size() && pyramid[level + 1].image.width() >= deviceWidth)
        ++level;
    drawGridImage(painter, pyramid[level], worldToDevice, deviceArea);
}

void PlanRenderer::paintLandCover(QPainter& painter, const QTransform& worldToDevice,
                                  const QRectF& deviceArea) const {
    if (grid_ != nullptr)
        drawPyramid(painter, landCoverPyramid_, worldToDevice, deviceArea);
}

void PlanRenderer::paintRegions(QPainter& painter, const QTransform& worldToDevice,
                                const QRectF& deviceArea) const {
    drawPyramid(painter, regionPyramid_, worldToDevice, deviceArea);
}

void PlanRenderer::paintRegionBorders(QPainter& painter, const QTransform& worldToDevice,
                                      const QRectF& deviceArea) const {
    // A dark line round every region, so regions read as areas (opaque: see drawWideLine).
    const QRectF visible = worldToDevice.inverted().mapRect(deviceArea);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setBrush(Qt::NoBrush);
    const QRectF visibleDevice = deviceArea.adjusted(-2.0, -2.0, 2.0, 2.0);
    for (const Outline& outline : regionBorders_) {
        if (!touches(outline.bounds, visible))
            continue;
        for (const QPolygonF& run : visibleRuns(outline.ring, worldToDevice, visibleDevice))
            drawWideLine(painter, run, QColor(45, 45, 45), 1.5);
    }
}

void PlanRenderer::paintUnreachable(QPainter& painter, const QTransform& worldToDevice,
                                    const QRectF& deviceArea) const {
    const QRectF visible = worldToDevice.inverted().mapRect(deviceArea);
    QPainterPath area;
    area.setFillRule(Qt::OddEvenFill);
    for (const Outline& outline : unreachableOutlines_) {
        if (touches(outline.bounds, visible))
            area.addPolygon(worldToDevice.map(outline.ring));
    }
    if (area.isEmpty())
        return;
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    painter.fillPath(area, QBrush(QColor(140, 0, 0, 220), Qt::BDiagPattern));
}

// Hatched in the colour of the robot that took them over, over the region tint of the robot that covered
// them (the same robot: the tint says who, the hatch says "not its own at first").
void PlanRenderer::paintTakenOver(QPainter& painter, const QTransform& worldToDevice,
                                  const QRectF& deviceArea) const {
    const QRectF visible = worldToDevice.inverted().mapRect(deviceArea);
    std::map<int, QPainterPath> areas;
    for (const auto& [robot, outline] : takenOverOutlines_)
        if (touches(outline.bounds, visible)) {
            QPainterPath& area = areas[robot];
            area.setFillRule(Qt::OddEvenFill);
            area.addPolygon(worldToDevice.map(outline.ring));
        }
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    for (const auto& [robot, area] : areas)
        painter.fillPath(area, QBrush(RobotPalette::colour(robot).darker(140), Qt::FDiagPattern));
}

void PlanRenderer::paintQuadTree(QPainter& painter, const QTransform& worldToDevice,
                                 const QRectF& deviceArea) const {
    const CellGraph& graph = plan_->cells;
    const int levels = std::max(graph.frame().levels, 1);
    // The top grid overhangs the raster's east and south edges; cells there hold nothing to show.
    QRectF visible = deviceArea;
    if (grid_ != nullptr)
        visible = visible.intersected(
            deviceRectOf(worldToDevice, grid_->originX, grid_->minY(), grid_->maxX(), grid_->originY));
    std::vector<std::vector<QRectF>> rectanglesByLevel(static_cast<std::size_t>(levels) + 1);
    std::vector<double> levelPixels(static_cast<std::size_t>(levels) + 1, 0.0);
    const double scale = std::abs(worldToDevice.m11());
    for (const Cell& cell : graph.cells()) {
        if (cell.size * scale < kSmallestOutlinedCellPixels)
            continue; // decided before mapping: zoomed out, most cells are too small to outline
        const QRectF rectangle = deviceRectOf(worldToDevice, cell);
        if (rectangle.width() < kSmallestOutlinedCellPixels || !rectangle.intersects(visible))
            continue;
        const auto level = static_cast<std::size_t>(std::clamp(int{cell.level}, 1, levels));
        rectanglesByLevel[level].push_back(rectangle);
        levelPixels[level] = rectangle.width();
    }
    painter.save();
    painter.setClipRect(visible, Qt::IntersectClip); // within any clip the caller set
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setBrush(Qt::NoBrush);
    for (std::size_t level = 1; level < rectanglesByLevel.size(); ++level) {
        const auto& rectangles = rectanglesByLevel[level];
        if (rectangles.empty())
            continue;
        QColor outline = RobotPalette::levelColour(static_cast<int>(level), levels);
        // Outlines a few pixels apart would hide the land cover under a mesh: they fade in as cells grow.
        outline.setAlpha(static_cast<int>(std::clamp(10.0 * (levelPixels[level] - 4.0), 25.0, 110.0)));
        QPen pen(outline, 0.0); // cosmetic: one device pixel at any zoom
        painter.setPen(pen);
        painter.drawRects(rectangles.data(), static_cast<int>(rectangles.size()));
    }
    painter.restore();
}

void PlanRenderer::drawPathLine(QPainter& painter, const QPolygonF& points, const QColor& colour,
                                const QTransform& worldToDevice, const QRectF& visibleDevice,
                                bool dense) const {
    QColor faded = colour;
    faded.setAlpha(150);
    for (const QPolygonF& run : visibleRuns(points, worldToDevice, visibleDevice)) {
        painter.setBrush(Qt::NoBrush);
        if (dense) {
            // A one-pixel cosmetic pen is drawn line by line, with no outline to fill.
            painter.setPen(QPen(faded, 0.0));
            painter.drawPolyline(run);
            continue;
        }
        // A white casing under the line keeps it readable over any land-cover colour.
        drawWideLine(painter, run, Qt::white, 4.0);
        drawWideLine(painter, run, colour, 2.0);
        drawArrows(painter, run, colour);
    }
}

void PlanRenderer::paintPaths(QPainter& painter, const QTransform& worldToDevice,
                              const QRectF& deviceArea) const {
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Zoomed out, neighbouring passes sit a few pixels apart: full-width lines would hide the land cover,
    // so they thin out and fade until the user zooms in.
    const bool dense = meanStepMetres_ * std::abs(worldToDevice.m11()) < 12.0;
    const QRectF visibleDevice = deviceArea.adjusted(-10.0, -10.0, 10.0, 10.0);
    const QRectF visible = worldToDevice.inverted().mapRect(visibleDevice);
    for (const PathLine& line : pathLines_) {
        if (!touches(line.bounds, visible))
            continue;
        const QColor colour = line.alternate ? RobotPalette::alternateSortieColour(line.robot)
                                             : RobotPalette::colour(line.robot);
        drawPathLine(painter, line.points, colour, worldToDevice, visibleDevice, dense);
    }
}

// Each robot's path up to `seconds` of the timeline and a dot where it is then (ringed black once it has
// stopped for good).
void PlanRenderer::paintPathsAt(QPainter& painter, const QTransform& worldToDevice, const QRectF& deviceArea,
                                double seconds) const {
    const TimelineLayer* timeline = timelineLayerOf(*plan_);
    painter.setRenderHint(QPainter::Antialiasing, true);
    const bool dense = meanStepMetres_ * std::abs(worldToDevice.m11()) < 12.0;
    const QRectF visibleDevice = deviceArea.adjusted(-10.0, -10.0, 10.0, 10.0);
    for (const RobotTimeline& robot : timeline->robots()) {
        if (robot.robot < 0 || static_cast<std::size_t>(robot.robot) >= plan_->paths.size())
            continue;
        const std::vector<Waypoint>& waypoints =
            plan_->paths[static_cast<std::size_t>(robot.robot)].waypoints;
        const std::vector<double>& at = robot.secondsAtWaypoint;
        if (waypoints.empty() || at.size() != waypoints.size())
            continue;
        const auto reached =
            static_cast<std::size_t>(std::upper_bound(at.begin(), at.end(), seconds) - at.begin());
        QPolygonF driven;
        driven.reserve(static_cast<qsizetype>(reached) + 1);
        for (std::size_t i = 0; i < std::max<std::size_t>(reached, 1); ++i)
            driven << QPointF(waypoints[i].x, waypoints[i].y);
        if (reached > 0 && reached < waypoints.size()) {
            const double share = (seconds - at[reached - 1]) / std::max(at[reached] - at[reached - 1], 1e-9);
            const Waypoint& from = waypoints[reached - 1];
            const Waypoint& to = waypoints[reached];
            driven << QPointF(from.x + (to.x - from.x) * share, from.y + (to.y - from.y) * share);
        }
        const QColor colour = RobotPalette::colour(robot.robot);
        if (driven.size() > 1)
            drawPathLine(painter, driven, colour, worldToDevice, visibleDevice, dense);
        const bool stopped = robot.stopped && reached >= waypoints.size();
        painter.setPen(QPen(stopped ? QColor(Qt::black) : QColor(Qt::white), 2.0));
        painter.setBrush(colour);
        painter.drawEllipse(worldToDevice.map(driven.back()), 6.0, 6.0);
    }
}

void PlanRenderer::paintCrossings(QPainter& painter, const QTransform& worldToDevice,
                                  const QRectF& deviceArea) const {
    // Zoomed out, the marks would cover the map in dashes: they show once a cell is a few pixels wide.
    constexpr double smallestPixels = 6.0;
    const double pixelsPerMetre = std::abs(worldToDevice.m11());
    const QRectF visible = worldToDevice.inverted().mapRect(deviceArea);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(QPen(RobotPalette::crossingColour(), 1.0, Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    for (const QRectF& cell : crossingCells_) {
        if (cell.width() * pixelsPerMetre < smallestPixels || !cell.intersects(visible))
            continue;
        painter.drawRect(worldToDevice.mapRect(cell).adjusted(1.5, 1.5, -1.5, -1.5));
    }
}

namespace {

// A ring on the device with corners closer than about a pixel to the last one kept left out: a boundary
// traced from a survey (hundreds of thousands of corners) is stroked, dashes and all, in a few thousand.
QPolygonF onDevice(const QPolygonF& ring, const QTransform& worldToDevice) {
    constexpr double closest = 0.75; // pixels
    QPolygonF device;
    for (const QPointF& corner : ring) {
        const QPointF point = worldToDevice.map(corner);
        if (device.isEmpty() ||
            std::abs(point.x() - device.back().x()) + std::abs(point.y() - device.back().y()) >= closest)
            device << point;
    }
    if (!ring.isEmpty() && device.back() != worldToDevice.map(ring.back()))
        device << worldToDevice.map(ring.back()); // closed as it was
    return device;
}

} // namespace

void PlanRenderer::setArea(const AreaOutline& area) {
    const auto polygonsOf = [](const std::vector<AreaOutline::Polygon>& polygons) {
        std::vector<AreaPolygon> drawn;
        drawn.reserve(polygons.size());
        for (const AreaOutline::Polygon& polygon : polygons) {
            AreaPolygon rings;
            for (const AreaOutline::Ring& corners : polygon) {
                if (corners.size() < 3)
                    continue;
                QPolygonF ring;
                ring.reserve(static_cast<qsizetype>(corners.size()) + 1);
                for (const MapPoint& corner : corners)
                    ring << QPointF(corner.x, corner.y);
                if (ring.front() != ring.back())
                    ring << ring.front();
                rings.bounds = rings.bounds.united(ring.boundingRect());
                rings.rings.push_back(std::move(ring));
            }
            if (!rings.rings.empty())
                drawn.push_back(std::move(rings));
        }
        return drawn;
    };
    areaEdges_ = polygonsOf(area.include);
    noGoEdges_ = polygonsOf(area.exclude);
}

// A white halo under a dark dashed line reads on any land cover and over the paths; no-go zones are hatched
// red as well, since the land cover leaves them empty, as it does the land outside the area.
void PlanRenderer::paintArea(QPainter& painter, const QTransform& worldToDevice,
                             const QRectF& deviceArea) const {
    const QRectF visible = worldToDevice.inverted().mapRect(deviceArea);
    painter.setRenderHint(QPainter::Antialiasing, true);
    const auto draw = [&](const std::vector<AreaPolygon>& polygons, const QColor& colour,
                          const QBrush& fill) {
        QPen dashes(colour, 2.0, Qt::CustomDashLine, Qt::FlatCap, Qt::RoundJoin);
        dashes.setDashPattern({4.0, 2.5});
        const QPen halo(QColor(255, 255, 255, 220), 4.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
        for (const AreaPolygon& polygon : polygons) {
            if (!touches(polygon.bounds, visible))
                continue;
            std::vector<QPolygonF> rings;
            for (const QPolygonF& ring : polygon.rings)
                rings.push_back(onDevice(ring, worldToDevice));
            if (fill.style() != Qt::NoBrush) { // its holes left empty
                QPainterPath inside;
                inside.setFillRule(Qt::OddEvenFill);
                for (const QPolygonF& ring : rings)
                    inside.addPolygon(ring);
                painter.fillPath(inside, fill);
            }
            painter.setBrush(Qt::NoBrush);
            for (const QPolygonF& ring : rings) {
                painter.setPen(halo);
                painter.drawPolyline(ring);
                painter.setPen(dashes);
                painter.drawPolyline(ring);
            }
        }
    };
    draw(areaEdges_, RobotPalette::areaEdgeColour(), Qt::NoBrush);
    draw(noGoEdges_, RobotPalette::noGoColour(), QBrush(RobotPalette::noGoColour(), Qt::DiagCrossPattern));
}

void PlanRenderer::paintStarts(QPainter& painter, const QTransform& worldToDevice) const {
    std::vector<MapPoint> starts = starts_;
    if (starts.empty() && plan_ != nullptr) {
        for (const CoveragePath& path : plan_->paths) {
            if (path.waypoints.empty())
                continue;
            if (static_cast<std::size_t>(path.robot) >= starts.size())
                starts.resize(static_cast<std::size_t>(path.robot) + 1);
            starts[static_cast<std::size_t>(path.robot)] =
                path.takeOff ? *path.takeOff : MapPoint{path.waypoints.front().x, path.waypoints.front().y};
        }
    }
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintFlightReach(painter, worldToDevice, starts);
    paintTakeOffLegs(painter, worldToDevice);
    // Text needs the font database of a QGuiApplication; without one the markers go unnumbered.
    const bool canDrawText = qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr;
    if (canDrawText) {
        QFont font = painter.font();
        font.setBold(true);
        font.setPixelSize(11);
        painter.setFont(font);
    }
    // Drones may take off from one spot: markers at the same place are fanned out to the right so that each
    // number shows.
    std::vector<QPointF> drawn;
    for (std::size_t robot = 0; robot < starts.size(); ++robot) {
        QPointF centre = worldToDevice.map(QPointF(starts[robot].x, starts[robot].y));
        const auto sharing = std::count_if(drawn.begin(), drawn.end(), [&](const QPointF& other) {
            return QLineF(other, centre).length() < 1.0;
        });
        drawn.push_back(centre);
        centre.rx() += 1.6 * kStartRadiusPixels * static_cast<double>(sharing);
        const QColor colour = RobotPalette::colour(static_cast<int>(robot));
        if (static_cast<int>(robot) == selectedStart_) {
            painter.setPen(QPen(QColor(255, 255, 0), 3.0));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(centre, kStartRadiusPixels + 4.0, kStartRadiusPixels + 4.0);
        }
        painter.setPen(QPen(QColor(20, 20, 20), 1.5));
        painter.setBrush(colour);
        painter.drawEllipse(centre, kStartRadiusPixels, kStartRadiusPixels);
        if (!canDrawText)
            continue;
        painter.setPen(QPen(Qt::white, 1.0));
        const QRectF box(centre.x() - kStartRadiusPixels, centre.y() - kStartRadiusPixels,
                         2.0 * kStartRadiusPixels, 2.0 * kStartRadiusPixels);
        painter.drawText(box, Qt::AlignCenter, QString::number(robot + 1));
    }
    paintChargers(painter, worldToDevice);
}

// An aircraft taking off outside its path flies to where the path begins: a thin dotted line in its colour,
// under the markers.
void PlanRenderer::paintTakeOffLegs(QPainter& painter, const QTransform& worldToDevice) const {
    if (plan_ == nullptr)
        return;
    for (const CoveragePath& path : plan_->paths) {
        if (!path.takeOff || path.waypoints.empty())
            continue;
        painter.setPen(QPen(RobotPalette::colour(path.robot).darker(130), 2.0, Qt::DotLine));
        painter.drawLine(worldToDevice.map(QPointF(path.takeOff->x, path.takeOff->y)),
                         worldToDevice.map(QPointF(path.waypoints.front().x, path.waypoints.front().y)));
    }
}

// Under the markers, so that a start stays easy to pick; dashed, so that it does not read as a region border.
// Round the start, or round the charger a battery plan's sorties fly from.
void PlanRenderer::paintFlightReach(QPainter& painter, const QTransform& worldToDevice,
                                    std::vector<MapPoint> starts) const {
    if (const SortieLayer* sorties = plan_ == nullptr ? nullptr : sortieLayerOf(*plan_); sorties != nullptr)
        for (const RobotSorties& robot : sorties->robots())
            if (static_cast<std::size_t>(robot.robot) < starts.size())
                starts[static_cast<std::size_t>(robot.robot)] = robot.charger;
    const double pixelsPerMetre = std::abs(worldToDevice.m11());
    for (std::size_t robot = 0; robot < starts.size() && robot < flightReach_.size(); ++robot) {
        if (!(flightReach_[robot] > 0.0))
            continue;
        const QPointF centre = worldToDevice.map(QPointF(starts[robot].x, starts[robot].y));
        const double radius = flightReach_[robot] * pixelsPerMetre;
        QPen pen(RobotPalette::colour(static_cast<int>(robot)).darker(130), 2.0,
                 Qt::DashLine); // as the legend
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(centre, radius, radius);
    }
}

// A charger away from its robot's start: a square in the robot's colour with a white bolt, so it reads as
// the place the robot lands, not a second robot.
void PlanRenderer::paintChargers(QPainter& painter, const QTransform& worldToDevice) const {
    std::vector<std::pair<int, MapPoint>> chargers;
    for (std::size_t robot = 0; robot < chargers_.size(); ++robot)
        if (chargers_[robot])
            chargers.emplace_back(static_cast<int>(robot), *chargers_[robot]);
    const SortieLayer* sorties = plan_ == nullptr ? nullptr : sortieLayerOf(*plan_);
    if (chargers_.empty() && sorties != nullptr)
        for (const RobotSorties& robot : sorties->robots()) {
            const auto index = static_cast<std::size_t>(robot.robot);
            if (index < plan_->paths.size() && !plan_->paths[index].waypoints.empty() &&
                !plan_->paths[index].closed) // an open battery path: it flew from its start to its charger
                chargers.emplace_back(robot.robot, robot.charger);
        }
    for (const auto& [robot, point] : chargers)
        drawCharger(painter, worldToDevice.map(QPointF(point.x, point.y)), RobotPalette::colour(robot));
}

void PlanRenderer::drawCharger(QPainter& painter, QPointF centre, const QColor& colour) {
    const double half = kStartRadiusPixels;
    painter.setPen(QPen(QColor(20, 20, 20), 1.5));
    painter.setBrush(colour);
    painter.drawRect(QRectF(centre.x() - half, centre.y() - half, 2.0 * half, 2.0 * half));
    const QPolygonF bolt{{centre.x() + 0.15 * half, centre.y() - 0.75 * half},
                         {centre.x() - 0.45 * half, centre.y() + 0.1 * half},
                         {centre.x() + 0.05 * half, centre.y() + 0.1 * half},
                         {centre.x() - 0.15 * half, centre.y() + 0.75 * half},
                         {centre.x() + 0.45 * half, centre.y() - 0.1 * half},
                         {centre.x() - 0.05 * half, centre.y() - 0.1 * half}};
    painter.setPen(Qt::NoPen);
    painter.setBrush(Qt::white);
    painter.drawPolygon(bolt);
}

} // namespace mcpp::render
