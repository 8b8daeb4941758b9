#pragma once

#include "core/model/MapPoint.hpp"
#include "render/MapLayers.hpp"
#include "render/PlanRenderer.hpp"
#include "ui/MapImageCache.hpp"

#include <QPoint>
#include <QPointF>
#include <QTimer>
#include <QWidget>
#include <optional>
#include <vector>

namespace mcpp::ui {

class MissionDocument;

// The map view: land cover and plan drawn by PlanRenderer, north up. Drag to pan, wheel to zoom around
// the cursor, drag a start marker to move it; in place-start mode a click asks for a new robot. The
// canvas never changes the document itself: it asks, and MainWindow decides (and may refuse).
class MapCanvas : public QWidget {
    Q_OBJECT

  public:
    // DrawArea: click the corners of a polygon and double-click (or Enter) to finish it, or drag a
    // rectangle; Backspace takes back a corner, Escape drops the drawing.
    enum class Tool { Pan, PlaceStart, DrawArea };

    explicit MapCanvas(MissionDocument* document, QWidget* parent = nullptr);

    void setTool(Tool tool);
    [[nodiscard]] Tool tool() const { return tool_; }
    void setLayers(const render::MapLayers& layers);
    // Shows a plan simulated over time at one moment (render::PlanRenderer::setTimelineSeconds).
    void setTimelineSeconds(std::optional<double> seconds);
    [[nodiscard]] const render::MapLayers& layers() const { return renderer_.layers(); }
    void setSelectedStart(int robot);
    [[nodiscard]] int selectedStart() const { return selectedStart_; }
    // A comparison has plans to show on this map, none yet shown: the banner says how to show one.
    void setComparedPlansWaiting(bool waiting);
    // What the window is working out for this map (planning, comparing), said by the banner in place of
    // "press Plan" until it is done; empty when nothing is.
    void setWorkUnderway(const QString& text);
    // What the banner at the top of the map says: what to do next, or empty.
    [[nodiscard]] QString bannerText() const;

    // Map <-> widget coordinates, for the status bar and for tests that click at map positions.
    [[nodiscard]] QPointF devicePointOf(MapPoint point) const;
    [[nodiscard]] MapPoint mapPointAt(QPointF devicePoint) const;
    [[nodiscard]] double pixelsPerMetre() const { return scale_; }
    [[nodiscard]] QTransform worldToDevice() const;
    // The length shown by the scale bar, in metres.
    [[nodiscard]] double scaleBarMetres() const;
    // A zoom or pan step was taken recently: the map shows its last drawing, scaled, until the view rests.
    [[nodiscard]] bool isViewMoving() const;

    QSize sizeHint() const override { return {900, 700}; }

  public slots:
    void zoomToFit();
    void zoomIn();
    void zoomOut();

  signals:
    void cursorMoved(mcpp::MapPoint point);
    void cursorLeft();
    void placeStartRequested(mcpp::MapPoint point);
    void moveStartRequested(int robot, mcpp::MapPoint point);
    void removeStartRequested(int robot);
    void selectedStartChanged(int robot);
    // A polygon drawn with the DrawArea tool, in map coordinates (at least three corners, not closed).
    void areaDrawn(const std::vector<mcpp::MapPoint>& ring);

  protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

  private:
    void refreshMap();
    void refreshStarts();
    void zoomAround(QPointF devicePoint, double factor);
    void viewMoved();
    [[nodiscard]] int startAt(QPointF devicePoint) const;
    void paintScaleBar(QPainter& painter) const;
    void paintNorthArrow(QPainter& painter) const;
    void paintBanner(QPainter& painter, const QString& text, const QColor& colour) const;
    [[nodiscard]] QString bannerText(bool planStale) const;
    void updateCursor(QPointF devicePoint);
    void paintDrawing(QPainter& painter) const;
    void finishDrawing();

    MissionDocument* document_;
    render::PlanRenderer renderer_;
    MapImageCache mapImage_;
    QTimer redrawTimer_;
    Tool tool_ = Tool::Pan;
    double scale_ = 1.0; // device pixels per metre
    MapPoint centre_;
    bool fitPending_ = true;
    bool fitted_ = false; // the view is as zoomToFit left it: no pan or zoom since
    int selectedStart_ = -1;
    bool comparedPlansWaiting_ = false;
    QString workUnderway_;

    // One press-move-release gesture.
    enum class Gesture { None, Pan, DragStart, Click, DragRectangle };
    Gesture gesture_ = Gesture::None;
    QPointF pressPosition_;
    QPointF lastPosition_;
    int draggedStart_ = -1;
    std::optional<MapPoint> dragPoint_;
    // The polygon being drawn with the DrawArea tool, and the cursor for its next corner.
    std::vector<MapPoint> drawing_;
    std::optional<MapPoint> drawingCursor_;
};

} // namespace mcpp::ui
