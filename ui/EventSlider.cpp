#include "ui/EventSlider.hpp"

#include <QPainter>
#include <QStyle>
#include <QStyleOptionSlider>

namespace mcpp::ui {

EventSlider::EventSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {}

void EventSlider::setMarks(std::vector<int> values) {
    marks_ = std::move(values);
    update();
}

void EventSlider::paintEvent(QPaintEvent* event) {
    QSlider::paintEvent(event);
    if (marks_.empty())
        return;
    QStyleOptionSlider option;
    initStyleOption(&option);
    const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
    const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
    // Positions as the handle's centre takes them, so a mark sits under the handle at its time.
    const int span = groove.width() - handle.width();
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0xd9, 0x48, 0x01));
    for (const int value : marks_) {
        const int x = groove.left() + handle.width() / 2 +
                      QStyle::sliderPositionFromValue(minimum(), maximum(), value, span);
        const QPolygonF mark{QPointF(x - 5.0, 0.0), QPointF(x + 5.0, 0.0), QPointF(x, 7.0)};
        painter.drawPolygon(mark);
    }
}

} // namespace mcpp::ui
