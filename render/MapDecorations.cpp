#include "render/MapDecorations.hpp"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPolygonF>
#include <algorithm>
#include <cmath>

namespace mcpp::render {

double scaleBarMetres(double pixelsPerMetre, double targetPixels) {
    const double metres = targetPixels / pixelsPerMetre;
    const double magnitude = std::pow(10.0, std::floor(std::log10(metres)));
    for (const double step : {5.0, 2.0, 1.0})
        if (step * magnitude <= metres)
            return step * magnitude;
    return magnitude;
}

void paintScaleBar(QPainter& painter, QPointF bottomLeft, double pixelsPerMetre, double targetPixels) {
    const double metres = scaleBarMetres(pixelsPerMetre, targetPixels);
    const double pixels = metres * pixelsPerMetre;
    const QString label =
        metres >= 1000.0 ? QStringLiteral("%1 km").arg(metres / 1000.0) : QStringLiteral("%1 m").arg(metres);
    const QFontMetricsF metrics(painter.font());
    const double height = metrics.height() + 18.0;
    const QRectF box(bottomLeft.x(), bottomLeft.y() - height,
                     std::max(pixels, metrics.horizontalAdvance(label)) + 20.0, height);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 210));
    painter.drawRect(box);
    const double left = box.left() + 10.0;
    const double baseline = box.bottom() - 8.0;
    painter.setPen(QPen(Qt::black, 2.0));
    painter.drawLine(QPointF(left, baseline), QPointF(left + pixels, baseline));
    painter.drawLine(QPointF(left, baseline - 6.0), QPointF(left, baseline));
    painter.drawLine(QPointF(left + pixels, baseline - 6.0), QPointF(left + pixels, baseline));
    painter.drawText(
        QRectF(left, box.top() + 2.0, std::max(pixels, metrics.horizontalAdvance(label)), metrics.height()),
        Qt::AlignCenter, label);
    painter.restore();
}

void paintNorthArrow(QPainter& painter, QPointF tip, double trueNorthRadians) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    // About the arrow's middle; the painter turns clockwise on screen, true north lies counter-clockwise.
    const QPointF middle = tip + QPointF(0, 18);
    painter.translate(middle);
    painter.rotate(-trueNorthRadians * 180.0 / std::acos(-1.0));
    painter.translate(-middle);
    painter.setPen(QPen(Qt::black, 1.0));
    painter.setBrush(Qt::black);
    painter.drawPolygon(QPolygonF({tip, tip + QPointF(7, 20), tip + QPointF(0, 15), tip + QPointF(-7, 20)}));
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    painter.drawText(QRectF(tip.x() - 10, tip.y() + 20, 20, 16), Qt::AlignCenter, QStringLiteral("N"));
    painter.restore();
}

} // namespace mcpp::render
