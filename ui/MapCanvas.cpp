#include "ui/MapCanvas.hpp"

#include "core/planners/PlannerRegistry.hpp"
#include "io/AutopilotMission.hpp"
#include "render/MapDecorations.hpp"
#include "render/PlanFrame.hpp"
#include "ui/CellToolTip.hpp"
#include "ui/MissionDocument.hpp"

#include <QHelpEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace mcpp::ui {

namespace {

constexpr double kMarkerHitRadiusPixels = 13.0;
constexpr double kDragThresholdPixels = 4.0;
constexpr double kSmallestRectanglePixels = 10.0;
constexpr double kScaleBarTargetPixels = 130.0;
// How long the view must rest after a zoom or pan step before the map is drawn afresh.
constexpr int kRedrawAfterMilliseconds = 150;

} // namespace

MapCanvas::MapCanvas(MissionDocument* document, QWidget* parent) : QWidget(parent), document_(document) {
    setObjectName(QStringLiteral("mapCanvas"));
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(200, 150);
    redrawTimer_.setSingleShot(true);
    redrawTimer_.setInterval(kRedrawAfterMilliseconds);
    connect(&redrawTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
    connect(document_, &MissionDocument::mapChanged, this, [this] {
        comparedPlansWaiting_ = false; // they were planned on the map before
        refreshMap();
        fitPending_ = true;
        zoomToFit();
    });
    connect(document_, &MissionDocument::classesChanged, this, &MapCanvas::refreshMap);
    // A comparison of other inputs has no plan to offer for these.
    for (const auto changed : {&MissionDocument::classesChanged, &MissionDocument::robotsChanged,
                               &MissionDocument::settingsChanged, &MissionDocument::eventsChanged})
        connect(document_, changed, this, [this] { comparedPlansWaiting_ = false; });
    connect(document_, &MissionDocument::robotsChanged, this, [this] {
        refreshStarts();
        if (selectedStart_ >= static_cast<int>(document_->robots().size()))
            setSelectedStart(-1);
    });
    connect(document_, &MissionDocument::settingsChanged, this, &MapCanvas::refreshStarts);
    connect(document_, &MissionDocument::planChanged, this, [this] {
        renderer_.setPlan(document_->plan());
        mapImage_.invalidate();
        if (fitted_) // a view the user has not moved follows the plan's frame
            zoomToFit();
        update();
    });
    connect(document_, &MissionDocument::staleChanged, this, [this](bool stale) {
        renderer_.setPlanStale(stale);
        mapImage_.invalidate();
        update();
    });
    refreshMap();
}

void MapCanvas::refreshMap() {
    renderer_.setMap(document_->grid(), &document_->classes());
    renderer_.setArea(document_->raster() != nullptr ? document_->raster()->area : AreaOutline{});
    // Preparing a plan's drawing takes a while on large maps: redone only for another plan (planChanged
    // always passes the new one).
    if (renderer_.plan() != document_->plan())
        renderer_.setPlan(document_->plan());
    renderer_.setPlanStale(document_->planStale());
    mapImage_.invalidate();
    refreshStarts();
}

void MapCanvas::refreshStarts() {
    std::vector<MapPoint> starts = document_->starts();
    if (dragPoint_ && draggedStart_ >= 0 && draggedStart_ < static_cast<int>(starts.size()))
        starts[static_cast<std::size_t>(draggedStart_)] = *dragPoint_;
    renderer_.setStarts(std::move(starts));
    // Chargers show while the planner flies on batteries, the only ones that use them.
    const auto planner = findPlannerDescription(document_->plannerChoice().planner);
    renderer_.setChargers(planner && planner->fliesOnBatteries() ? document_->chargers()
                                                                 : std::vector<std::optional<MapPoint>>{});
    renderer_.setFlightReach(io::flightReachesMetres(io::robotVehicles(document_->mission())));
    update();
}

void MapCanvas::setTool(Tool tool) {
    tool_ = tool;
    drawing_.clear();
    drawingCursor_.reset();
    update();
    updateCursor(mapFromGlobal(QCursor::pos()));
}

void MapCanvas::setTimelineSeconds(std::optional<double> seconds) {
    if (renderer_.timelineSeconds() == seconds)
        return;
    renderer_.setTimelineSeconds(seconds);
    mapImage_.invalidate();
    update();
}

void MapCanvas::setLayers(const render::MapLayers& layers) {
    renderer_.setLayers(layers);
    mapImage_.invalidate();
    update();
}

void MapCanvas::setSelectedStart(int robot) {
    if (robot == selectedStart_)
        return;
    selectedStart_ = robot;
    renderer_.setSelectedStart(robot);
    update();
    emit selectedStartChanged(robot);
}

QTransform MapCanvas::worldToDevice() const {
    return QTransform(scale_, 0.0, 0.0, -scale_, width() / 2.0 - centre_.x * scale_,
                      height() / 2.0 + centre_.y * scale_);
}

QPointF MapCanvas::devicePointOf(MapPoint point) const {
    return worldToDevice().map(QPointF(point.x, point.y));
}

MapPoint MapCanvas::mapPointAt(QPointF devicePoint) const {
    return {centre_.x + (devicePoint.x() - width() / 2.0) / scale_,
            centre_.y - (devicePoint.y() - height() / 2.0) / scale_};
}

void MapCanvas::zoomToFit() {
    const ClassGrid* grid = document_->grid();
    if (grid == nullptr || width() <= 0 || height() <= 0)
        return;
    // The plan's frame, as plan.png shows it: a plan over an area of interest fills the view, not a corner.
    // Before any plan, the area of interest's.
    const Plan* plan = document_->plan();
    const ClassGrid frame =
        plan == nullptr
            ? render::taskAreaFrame(*grid)
            : render::planFrame(*grid, {plan},
                                render::flightReachRings(
                                    *plan, io::flightReachesMetres(io::robotVehicles(document_->mission()))));
    const double margin = 12.0;
    scale_ = std::min((width() - 2.0 * margin) / std::max(frame.width(), 1e-9),
                      (height() - 2.0 * margin) / std::max(frame.height(), 1e-9));
    scale_ = std::max(scale_, 1e-9);
    centre_ = {frame.originX + frame.width() / 2.0, frame.originY - frame.height() / 2.0};
    fitPending_ = false;
    fitted_ = true;
    update();
}

void MapCanvas::zoomIn() {
    zoomAround(QPointF(width() / 2.0, height() / 2.0), 1.5);
}

void MapCanvas::zoomOut() {
    zoomAround(QPointF(width() / 2.0, height() / 2.0), 1.0 / 1.5);
}

void MapCanvas::zoomAround(QPointF devicePoint, double factor) {
    const ClassGrid* grid = document_->grid();
    if (grid == nullptr)
        return;
    // Limits: the whole map at least ~50 px wide; at most ~200 px per raster pixel.
    const double smallest = 50.0 / std::max(grid->width(), grid->height());
    const double largest = 200.0 / std::min(grid->pixelWidth, grid->pixelHeight);
    const double newScale = std::clamp(scale_ * factor, smallest, largest);
    const MapPoint anchor = mapPointAt(devicePoint);
    scale_ = newScale;
    // Keep the map point under the cursor where it was.
    centre_ = {anchor.x - (devicePoint.x() - width() / 2.0) / scale_,
               anchor.y + (devicePoint.y() - height() / 2.0) / scale_};
    viewMoved();
}

void MapCanvas::viewMoved() {
    fitted_ = false;
    redrawTimer_.start();
    update();
}

bool MapCanvas::isViewMoving() const {
    return redrawTimer_.isActive();
}

double MapCanvas::scaleBarMetres() const {
    return render::scaleBarMetres(scale_, kScaleBarTargetPixels);
}

int MapCanvas::startAt(QPointF devicePoint) const {
    const auto& robots = document_->robots();
    int best = -1;
    double bestDistance = kMarkerHitRadiusPixels;
    for (std::size_t robot = 0; robot < robots.size(); ++robot) {
        const double distance = QLineF(devicePointOf(robots[robot].start), devicePoint).length();
        if (distance <= bestDistance) {
            best = static_cast<int>(robot);
            bestDistance = distance;
        }
    }
    return best;
}

void MapCanvas::updateCursor(QPointF devicePoint) {
    if (gesture_ == Gesture::Pan)
        setCursor(Qt::ClosedHandCursor);
    else if (gesture_ == Gesture::DragStart)
        setCursor(Qt::SizeAllCursor);
    else if (startAt(devicePoint) >= 0)
        setCursor(Qt::OpenHandCursor);
    else if (tool_ == Tool::PlaceStart || tool_ == Tool::DrawArea)
        setCursor(Qt::CrossCursor);
    else
        setCursor(Qt::ArrowCursor);
}

void MapCanvas::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (fitPending_)
        zoomToFit();
}

bool MapCanvas::event(QEvent* event) {
    if (event->type() != QEvent::ToolTip || !document_->hasMap())
        return QWidget::event(event);
    const auto* help = static_cast<QHelpEvent*>(event);
    const QString text = cellToolTip(*document_, mapPointAt(help->pos()));
    if (text.isEmpty())
        QToolTip::hideText();
    else
        QToolTip::showText(help->globalPos(), text, this);
    return true;
}

void MapCanvas::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(232, 232, 228));
    if (!document_->hasMap()) {
        painter.setPen(QColor(90, 90, 90));
        QFont font = painter.font();
        font.setPointSizeF(font.pointSizeF() * 1.2);
        painter.setFont(font);
        painter.drawText(
            rect().adjusted(40, 40, -40, -40), Qt::AlignCenter | Qt::TextWordWrap,
            tr("No map open.\n\nOpen a land-cover raster (Ctrl+O) or a mission (Ctrl+Shift+O), drop a file "
               "here, or choose Help ▸ Open sample mission."));
        return;
    }
    // While the view moves, the last drawing stands in, scaled and shifted; the map is drawn afresh when
    // the view rests or what it shows changes.
    const QTransform view = worldToDevice();
    if (!mapImage_.fits(view, size(), devicePixelRatioF()) && !(mapImage_.canPreview() && isViewMoving()))
        mapImage_.render(renderer_, view, size(), devicePixelRatioF());
    mapImage_.draw(painter, view);
    renderer_.paintStartMarkers(painter, view);
    paintDrawing(painter);
    paintScaleBar(painter);
    paintNorthArrow(painter);
    // planStale compares every input with the plan's: once per paint.
    const bool stale = document_->planStale();
    if (const QString banner = bannerText(stale); !banner.isEmpty())
        paintBanner(painter, banner, stale ? QColor(255, 236, 179) : QColor(227, 242, 253));
}

QString MapCanvas::bannerText() const {
    return bannerText(document_->planStale());
}

QString MapCanvas::bannerText(bool planStale) const {
    if (!document_->hasMap())
        return {};
    if (!workUnderway_.isEmpty() && (planStale || document_->plan() == nullptr))
        return workUnderway_;
    if (planStale)
        return tr("Plan is out of date: inputs changed since it was computed. Press Plan (F5).");
    if (document_->robots().empty())
        return tr("Place robot starts with the Place start tool (S), then press Plan (F5).");
    if (document_->plan() != nullptr)
        return {};
    if (comparedPlansWaiting_)
        return tr("Planners compared: select a row under Compare planners to show its plan, or press Plan "
                  "(F5).");
    return tr("Not planned yet. Press Plan (F5).");
}

void MapCanvas::setWorkUnderway(const QString& text) {
    workUnderway_ = text;
    update();
}

void MapCanvas::setComparedPlansWaiting(bool waiting) {
    comparedPlansWaiting_ = waiting;
    update();
}

void MapCanvas::paintBanner(QPainter& painter, const QString& text, const QColor& colour) const {
    // As wide as the text, wrapped where the canvas is narrower (a narrow window, docks open).
    const QFontMetrics metrics(painter.font());
    const int widest = std::max(width() - 40, 80);
    const QRect textBox = metrics.boundingRect(QRect(0, 0, widest, 1000), Qt::TextWordWrap, text);
    const QRect box((width() - textBox.width()) / 2 - 12, 8, textBox.width() + 24, textBox.height() + 10);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(120, 120, 120), 1.0));
    painter.setBrush(colour);
    painter.drawRoundedRect(box, 5, 5);
    painter.setPen(QColor(40, 40, 40));
    painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, text);
}

void MapCanvas::paintScaleBar(QPainter& painter) const {
    render::paintScaleBar(painter, QPointF(10, height() - 10), scale_, kScaleBarTargetPixels);
}

void MapCanvas::paintNorthArrow(QPainter& painter) const {
    const ClassGrid* grid = document_->grid();
    render::paintNorthArrow(painter, QPointF(width() - 24, 40),
                            grid != nullptr ? grid->trueNorthRadians : 0.0);
}

void MapCanvas::mousePressEvent(QMouseEvent* event) {
    setFocus(Qt::MouseFocusReason);
    pressPosition_ = event->position();
    lastPosition_ = event->position();
    if (event->button() == Qt::MiddleButton) {
        gesture_ = Gesture::Pan;
    } else if (event->button() == Qt::LeftButton) {
        const int start = startAt(event->position());
        if (start >= 0) {
            setSelectedStart(start);
            gesture_ = Gesture::DragStart;
            draggedStart_ = start;
        } else {
            gesture_ = Gesture::Click;
        }
    }
    updateCursor(event->position());
}

void MapCanvas::mouseMoveEvent(QMouseEvent* event) {
    const QPointF position = event->position();
    if (document_->hasMap())
        emit cursorMoved(mapPointAt(position));
    const bool farEnough = QLineF(position, pressPosition_).length() >= kDragThresholdPixels;
    if (gesture_ == Gesture::Click && farEnough) {
        // A click that moves becomes a pan, or a rectangle when drawing an area that has no corner yet.
        gesture_ = tool_ == Tool::DrawArea && drawing_.empty() ? Gesture::DragRectangle : Gesture::Pan;
    }
    if (tool_ == Tool::DrawArea && document_->hasMap()) {
        drawingCursor_ = mapPointAt(position);
        if (!drawing_.empty() || gesture_ == Gesture::DragRectangle)
            update();
    }
    if (gesture_ == Gesture::Pan) {
        const QPointF delta = position - lastPosition_;
        centre_.x -= delta.x() / scale_;
        centre_.y += delta.y() / scale_;
        viewMoved();
    } else if (gesture_ == Gesture::DragStart && farEnough) {
        dragPoint_ = mapPointAt(position);
        refreshStarts();
    }
    lastPosition_ = position;
    updateCursor(position);
}

void MapCanvas::mouseReleaseEvent(QMouseEvent* event) {
    const Gesture gesture = gesture_;
    gesture_ = Gesture::None;
    if (gesture == Gesture::DragStart) {
        const int robot = draggedStart_;
        const std::optional<MapPoint> target = dragPoint_;
        draggedStart_ = -1;
        dragPoint_.reset();
        refreshStarts();
        if (target)
            emit moveStartRequested(robot, *target);
    } else if (gesture == Gesture::DragRectangle) {
        const MapPoint a = mapPointAt(pressPosition_);
        const MapPoint b = mapPointAt(event->position());
        drawingCursor_.reset();
        update();
        // A slip of the hand while clicking the first corner is no rectangle.
        const QPointF size = event->position() - pressPosition_;
        if (std::abs(size.x()) >= kSmallestRectanglePixels && std::abs(size.y()) >= kSmallestRectanglePixels)
            emit areaDrawn({{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}});
    } else if (gesture == Gesture::Click && event->button() == Qt::LeftButton && document_->hasMap()) {
        if (tool_ == Tool::DrawArea) {
            drawing_.push_back(mapPointAt(event->position()));
            update();
        } else if (tool_ == Tool::PlaceStart)
            emit placeStartRequested(mapPointAt(event->position()));
        else
            setSelectedStart(-1);
    }
    updateCursor(event->position());
}

void MapCanvas::mouseDoubleClickEvent(QMouseEvent* event) {
    // The double-click's first click has usually added this corner already; finishDrawing drops repeats.
    if (tool_ == Tool::DrawArea && event->button() == Qt::LeftButton) {
        gesture_ = Gesture::None;
        drawing_.push_back(mapPointAt(event->position()));
        finishDrawing();
        return;
    }
    QWidget::mouseDoubleClickEvent(event);
}

void MapCanvas::finishDrawing() {
    std::vector<MapPoint> ring;
    for (const MapPoint& corner : drawing_)
        if (ring.empty() || std::hypot(corner.x - ring.back().x, corner.y - ring.back().y) * scale_ >= 1.0)
            ring.push_back(corner);
    drawing_.clear();
    drawingCursor_.reset();
    update();
    if (ring.size() >= 3)
        emit areaDrawn(ring);
}

void MapCanvas::paintDrawing(QPainter& painter) const {
    if (tool_ != Tool::DrawArea)
        return;
    QPolygonF corners;
    if (gesture_ == Gesture::DragRectangle && drawingCursor_) {
        const QPointF a = pressPosition_;
        const QPointF b = devicePointOf(*drawingCursor_);
        corners << a << QPointF(b.x(), a.y()) << b << QPointF(a.x(), b.y()) << a;
    } else {
        for (const MapPoint& corner : drawing_)
            corners << devicePointOf(corner);
        if (drawingCursor_ && !drawing_.empty())
            corners << devicePointOf(*drawingCursor_) << devicePointOf(drawing_.front());
    }
    if (corners.size() < 2)
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(255, 255, 255, 200), 4.0));
    painter.drawPolyline(corners);
    painter.setPen(QPen(QColor(20, 20, 20), 1.5, Qt::DashLine));
    painter.drawPolyline(corners);
    painter.setBrush(Qt::white);
    for (const MapPoint& corner : drawing_)
        painter.drawEllipse(devicePointOf(corner), 3.0, 3.0);
    painter.restore();
}

void MapCanvas::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps != 0.0)
        zoomAround(event->position(), std::pow(1.25, steps));
    event->accept();
}

void MapCanvas::keyPressEvent(QKeyEvent* event) {
    if (tool_ == Tool::DrawArea && !drawing_.empty()) {
        if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) {
            finishDrawing();
            return;
        }
        if (event->key() == Qt::Key_Backspace) {
            drawing_.pop_back();
            update();
            return;
        }
        if (event->key() == Qt::Key_Escape) {
            drawing_.clear();
            update();
            return;
        }
    }
    if ((event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) && selectedStart_ >= 0) {
        emit removeStartRequested(selectedStart_);
        return;
    }
    if (event->key() == Qt::Key_Escape) {
        if (gesture_ == Gesture::DragStart) {
            gesture_ = Gesture::None;
            draggedStart_ = -1;
            dragPoint_.reset();
            refreshStarts();
        }
        setSelectedStart(-1);
        return;
    }
    QWidget::keyPressEvent(event);
}

void MapCanvas::leaveEvent(QEvent* event) {
    emit cursorLeft();
    QWidget::leaveEvent(event);
}

} // namespace mcpp::ui
