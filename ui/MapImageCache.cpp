#include "ui/MapImageCache.hpp"

#include "render/PlanRenderer.hpp"

#include <QPainter>

namespace mcpp::ui {

bool MapImageCache::fits(const QTransform& worldToDevice, const QSize& size, double pixelRatio) const {
    return canPreview() && imageTransform_ == worldToDevice && image_.devicePixelRatio() == pixelRatio &&
           image_.size() == size * pixelRatio;
}

void MapImageCache::render(const render::PlanRenderer& renderer, const QTransform& worldToDevice,
                           const QSize& size, double pixelRatio) {
    image_ = QImage(size * pixelRatio, QImage::Format_ARGB32_Premultiplied);
    image_.setDevicePixelRatio(pixelRatio);
    image_.fill(Qt::transparent);
    QPainter painter(&image_);
    renderer.paintMap(painter, worldToDevice, QRectF(QPointF(0, 0), QSizeF(size)));
    imageTransform_ = worldToDevice;
    imageVersion_ = contentVersion_;
}

void MapImageCache::draw(QPainter& painter, const QTransform& worldToDevice) const {
    if (image_.isNull())
        return;
    painter.save();
    // Device pixels of the old view -> map -> device pixels of the new one.
    painter.setTransform(imageTransform_.inverted() * worldToDevice, true);
    painter.drawImage(QPointF(0, 0), image_);
    painter.restore();
}

} // namespace mcpp::ui
