#pragma once

#include <QImage>
#include <QTransform>
#include <cstdint>

class QPainter;

namespace mcpp::render {
class PlanRenderer;
}

namespace mcpp::ui {

// The map as last drawn, so that a zoom or pan step costs one image draw instead of a repaint of millions
// of cells: while the view moves, the image is shown scaled and shifted to the new view, and the map is
// drawn afresh once the view rests. A change of what is drawn (plan, layers, classes) makes it stale.
class MapImageCache {
  public:
    // Something the map shows has changed: the image no longer shows it, whatever the view.
    void invalidate() { ++contentVersion_; }
    // The image shows the current content at exactly this view and size.
    [[nodiscard]] bool fits(const QTransform& worldToDevice, const QSize& size, double pixelRatio) const;
    // The image shows the current content, at some view: it can stand in while the view moves.
    [[nodiscard]] bool canPreview() const { return !image_.isNull() && imageVersion_ == contentVersion_; }
    // Draws the map into the image at this view.
    void render(const render::PlanRenderer& renderer, const QTransform& worldToDevice, const QSize& size,
                double pixelRatio);
    // Draws the image onto the view, scaled and shifted from the view it was drawn at.
    void draw(QPainter& painter, const QTransform& worldToDevice) const;

  private:
    QImage image_;
    QTransform imageTransform_;
    std::uint64_t contentVersion_ = 1;
    std::uint64_t imageVersion_ = 0;
};

} // namespace mcpp::ui
