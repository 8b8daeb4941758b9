#include "render/PlanRenderer.hpp"

#include "io/PlanExport.hpp"
#include "render/RobotPalette.hpp"

#include <QFont>
#include <QGuiApplication>
#include <QLineF>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <algorithm>
#include <cmath>
#include <unordered_map>

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

int robotOf(const Plan& plan, int cell) {
    const auto& owners = plan.regions.robotOfCell;
    return static_cast<std::size_t>(cell) < owners.size() ? owners[static_cast<std::size_t>(cell)] : -1;
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

// Qt strokes a wide polyline as one polygon whose filling slows down sharply as the line crosses itself
// (coverage paths pass close by themselves all the time); pieces of a few hundred points draw the same
// picture, joined by their round caps, many times faster.
void drawPolylineInPieces(QPainter& painter, const QPolygonF& line) {
    constexpr qsizetype piece = 8;
    for (qsizetype first = 0; first + 1 < line.size(); first += piece) {
        const qsizetype count = std::min(piece + 1, line.size() - first);
        painter.drawPolyline(line.constData() + first, static_cast<int>(count));
    }
}

} // namespace

void PlanRenderer::setMap(const ClassGrid* grid, const ClassTable* classes) {
    grid_ = grid;
    classes_ = classes;
    landCoverImage_ = QImage();
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
}

void PlanRenderer::setPlan(const Plan* plan) {
    plan_ = plan;
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
    painter.save();
    painter.setTransform(QTransform());
    if (layers_.landCover)
        paintLandCover(painter, worldToDevice, deviceArea);
    if (plan_ != nullptr) {
        if (planStale_)
            painter.setOpacity(0.45);
        if (layers_.regions)
            paintRegions(painter, worldToDevice, deviceArea);
        if (layers_.unreachable)
            paintUnreachable(painter, worldToDevice, deviceArea);
        if (layers_.quadTree)
            paintQuadTree(painter, worldToDevice, deviceArea);
        if (layers_.regions)
            paintRegionBorders(painter, worldToDevice);
        if (layers_.paths)
            paintPaths(painter, worldToDevice);
        painter.setOpacity(1.0);
    }
    if (layers_.starts)
        paintStarts(painter, worldToDevice);
    painter.restore();
}

void PlanRenderer::paintLandCover(QPainter& painter, const QTransform& worldToDevice,
                                  const QRectF& deviceArea) const {
    if (grid_ == nullptr || landCoverImage_.isNull())
        return;
    const QRectF full =
        deviceRectOf(worldToDevice, grid_->originX, grid_->minY(), grid_->maxX(), grid_->originY);
    const QRectF visible = full.intersected(deviceArea);
    if (visible.isEmpty())
        return;
    // Only the visible pixels are drawn, on whole-pixel boundaries, so deep zooms stay fast and crisp.
    const double pixelsPerColumn = full.width() / grid_->columns;
    const double pixelsPerRow = full.height() / grid_->rows;
    const int firstColumn =
        std::clamp(static_cast<int>(std::floor((visible.left() - full.left()) / pixelsPerColumn)), 0,
                   grid_->columns - 1);
    const int lastColumn =
        std::clamp(static_cast<int>(std::ceil((visible.right() - full.left()) / pixelsPerColumn)),
                   firstColumn + 1, grid_->columns);
    const int firstRow = std::clamp(static_cast<int>(std::floor((visible.top() - full.top()) / pixelsPerRow)),
                                    0, grid_->rows - 1);
    const int lastRow =
        std::clamp(static_cast<int>(std::ceil((visible.bottom() - full.top()) / pixelsPerRow)), firstRow + 1,
                   grid_->rows);
    const QRect source(firstColumn, firstRow, lastColumn - firstColumn, lastRow - firstRow);
    const QRectF target(full.left() + firstColumn * pixelsPerColumn, full.top() + firstRow * pixelsPerRow,
                        source.width() * pixelsPerColumn, source.height() * pixelsPerRow);
    // Zoomed out, smoothing averages many raster pixels into one; zoomed in, the pixels stay square.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, pixelsPerColumn < 1.0);
    painter.drawImage(target, landCoverImage_, source);
}

void PlanRenderer::paintRegions(QPainter& painter, const QTransform& worldToDevice,
                                const QRectF& deviceArea) const {
    const CellGraph& graph = plan_->cells;
    std::unordered_map<int, std::vector<QRectF>> rectanglesByRobot;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const int robot = robotOf(*plan_, static_cast<int>(id));
        if (robot < 0)
            continue;
        const QRectF rectangle = deviceRectOf(worldToDevice, graph.cell(static_cast<int>(id)));
        if (rectangle.intersects(deviceArea))
            rectanglesByRobot[robot].push_back(rectangle);
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    for (const auto& [robot, rectangles] : rectanglesByRobot) {
        QColor fill = RobotPalette::colour(robot);
        fill.setAlpha(80);
        painter.setBrush(fill);
        painter.drawRects(rectangles.data(), static_cast<int>(rectangles.size()));
    }
}

void PlanRenderer::paintRegionBorders(QPainter& painter, const QTransform& worldToDevice) const {
    // A dark line wherever two neighbouring cells belong to different robots, so regions read as areas.
    const CellGraph& graph = plan_->cells;
    std::vector<QLineF> borders;
    for (std::size_t a = 0; a < graph.size(); ++a) {
        const int first = static_cast<int>(a);
        const int firstRobot = robotOf(*plan_, first);
        for (const int second : graph.neighbours(first)) {
            if (second <= first)
                continue;
            if (robotOf(*plan_, second) == firstRobot)
                continue;
            const Cell& one = graph.cell(first);
            const Cell& other = graph.cell(second);
            const double tolerance = 1e-6 * std::max(one.size, other.size);
            const double bottom = std::max(one.minY, other.minY);
            const double top = std::min(one.maxY(), other.maxY());
            const double left = std::max(one.minX, other.minX);
            const double right = std::min(one.maxX(), other.maxX());
            if (std::abs(one.maxX() - other.minX) < tolerance ||
                std::abs(other.maxX() - one.minX) < tolerance) {
                const double x = std::abs(one.maxX() - other.minX) < tolerance ? one.maxX() : one.minX;
                borders.emplace_back(worldToDevice.map(QPointF(x, bottom)),
                                     worldToDevice.map(QPointF(x, top)));
            } else if (std::abs(one.maxY() - other.minY) < tolerance ||
                       std::abs(other.maxY() - one.minY) < tolerance) {
                const double y = std::abs(one.maxY() - other.minY) < tolerance ? one.maxY() : one.minY;
                borders.emplace_back(worldToDevice.map(QPointF(left, y)),
                                     worldToDevice.map(QPointF(right, y)));
            }
        }
    }
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(30, 30, 30, 200), 1.5));
    painter.drawLines(borders.data(), static_cast<int>(borders.size()));
}

void PlanRenderer::paintUnreachable(QPainter& painter, const QTransform& worldToDevice,
                                    const QRectF& deviceArea) const {
    const CellGraph& graph = plan_->cells;
    std::vector<QRectF> rectangles;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        if (robotOf(*plan_, static_cast<int>(id)) >= 0)
            continue;
        const QRectF rectangle = deviceRectOf(worldToDevice, graph.cell(static_cast<int>(id)));
        if (rectangle.intersects(deviceArea))
            rectangles.push_back(rectangle);
    }
    if (rectangles.empty())
        return;
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(120, 0, 0, 50));
    painter.drawRects(rectangles.data(), static_cast<int>(rectangles.size()));
    painter.setBrush(QBrush(QColor(140, 0, 0, 220), Qt::BDiagPattern));
    painter.drawRects(rectangles.data(), static_cast<int>(rectangles.size()));
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
    for (const Cell& cell : graph.cells()) {
        const QRectF rectangle = deviceRectOf(worldToDevice, cell);
        if (rectangle.width() < kSmallestOutlinedCellPixels || !rectangle.intersects(visible))
            continue;
        const auto level = static_cast<std::size_t>(std::clamp(cell.level, 1, levels));
        rectanglesByLevel[level].push_back(rectangle);
    }
    painter.save();
    painter.setClipRect(visible);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setBrush(Qt::NoBrush);
    for (std::size_t level = 1; level < rectanglesByLevel.size(); ++level) {
        const auto& rectangles = rectanglesByLevel[level];
        if (rectangles.empty())
            continue;
        QColor outline = RobotPalette::levelColour(static_cast<int>(level), levels);
        outline.setAlpha(110);
        QPen pen(outline, 0.0); // cosmetic: one device pixel at any zoom
        painter.setPen(pen);
        painter.drawRects(rectangles.data(), static_cast<int>(rectangles.size()));
    }
    painter.restore();
}

void PlanRenderer::paintPaths(QPainter& painter, const QTransform& worldToDevice) const {
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Zoomed out, neighbouring passes sit a few pixels apart: full-width lines would hide the land cover,
    // so they thin out and fade until the user zooms in.
    double totalLength = 0.0;
    std::size_t segments = 0;
    for (const CoveragePath& path : plan_->paths) {
        for (std::size_t i = 1; i < path.waypoints.size(); ++i)
            totalLength += std::hypot(path.waypoints[i].x - path.waypoints[i - 1].x,
                                      path.waypoints[i].y - path.waypoints[i - 1].y);
        segments += path.waypoints.size() > 1 ? path.waypoints.size() - 1 : 0;
    }
    const double meanSegmentPixels =
        segments == 0 ? 0.0 : totalLength / static_cast<double>(segments) * std::abs(worldToDevice.m11());
    const bool dense = meanSegmentPixels < 12.0;
    const double arrowSpacing = kArrowSpacingPixels;
    for (const CoveragePath& path : plan_->paths) {
        if (path.waypoints.size() < 2)
            continue;
        // The turning points draw the same line with far fewer vertices.
        const std::vector<Waypoint> corners = io::turningPoints(path);
        QPolygonF line;
        line.reserve(static_cast<qsizetype>(corners.size()) + 1);
        for (const Waypoint& waypoint : corners)
            line << worldToDevice.map(QPointF(waypoint.x, waypoint.y));
        if (path.closed && line.front() != line.back())
            line << line.front();

        const QColor colour = RobotPalette::colour(path.robot);
        // A pale casing under the line keeps it readable over any land-cover colour.
        painter.setBrush(Qt::NoBrush);
        if (dense) {
            QColor faded = colour;
            faded.setAlpha(150);
            painter.setPen(QPen(faded, 1.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            drawPolylineInPieces(painter, line);
        } else {
            painter.setPen(QPen(QColor(255, 255, 255, 190), 4.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            drawPolylineInPieces(painter, line);
            painter.setPen(QPen(colour, 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            drawPolylineInPieces(painter, line);
        }

        // Arrows at even on-screen spacing show the direction of travel; a dense overview has no room for
        // them.
        if (dense)
            continue;
        double untilNextArrow = arrowSpacing / 2.0;
        for (qsizetype i = 1; i < line.size(); ++i) {
            const QPointF from = line[i - 1];
            const QPointF to = line[i];
            const double segment = QLineF(from, to).length();
            double along = 0.0;
            while (segment - along >= untilNextArrow) {
                along += untilNextArrow;
                const QPointF tip = from + (to - from) * (along / segment);
                drawArrow(painter, tip, to - from, colour);
                untilNextArrow = arrowSpacing;
            }
            untilNextArrow -= segment - along;
        }
    }
}

void PlanRenderer::paintStarts(QPainter& painter, const QTransform& worldToDevice) const {
    std::vector<MapPoint> starts = starts_;
    if (starts.empty() && plan_ != nullptr) {
        for (const CoveragePath& path : plan_->paths) {
            if (path.waypoints.empty())
                continue;
            if (static_cast<std::size_t>(path.robot) >= starts.size())
                starts.resize(static_cast<std::size_t>(path.robot) + 1);
            starts[static_cast<std::size_t>(path.robot)] = {path.waypoints.front().x,
                                                            path.waypoints.front().y};
        }
    }
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Text needs the font database of a QGuiApplication; without one the markers go unnumbered.
    const bool canDrawText = qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr;
    if (canDrawText) {
        QFont font = painter.font();
        font.setBold(true);
        font.setPixelSize(11);
        painter.setFont(font);
    }
    for (std::size_t robot = 0; robot < starts.size(); ++robot) {
        const QPointF centre = worldToDevice.map(QPointF(starts[robot].x, starts[robot].y));
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
}

} // namespace mcpp::render
