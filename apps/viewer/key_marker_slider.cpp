#include "key_marker_slider.h"

#include <QMouseEvent>
#include <QPainter>
#include <QStyle>
#include <QStyleOptionSlider>

namespace f2::viewer {

KeyMarkerSlider::KeyMarkerSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {}

void KeyMarkerSlider::setMarkers(QList<int> frames) {
    if (frames == markers_) return;
    markers_ = std::move(frames);
    update();
}

int KeyMarkerSlider::positionOf(int frame) const {
    QStyleOptionSlider option;
    initStyleOption(&option);
    const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
    const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
    const int span = groove.width() - handle.width();
    return groove.left() + handle.width() / 2 +
           QStyle::sliderPositionFromValue(minimum(), maximum(), frame, span, option.upsideDown);
}

void KeyMarkerSlider::paintEvent(QPaintEvent* event) {
    QSlider::paintEvent(event);
    if (markers_.isEmpty()) return;
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 170, 0));
    for (int frame : markers_) {
        // A small diamond under the groove, like key frames in animation tools.
        const int x = positionOf(frame), y = height() - 5;
        const QPoint diamond[4] = {{x, y - 4}, {x + 4, y}, {x, y + 4}, {x - 4, y}};
        painter.drawPolygon(diamond, 4);
    }
}

void KeyMarkerSlider::mousePressEvent(QMouseEvent* event) {
    const int x = event->position().toPoint().x();
    for (int frame : markers_) {
        if (std::abs(positionOf(frame) - x) <= kMarkerReach && event->position().y() >= height() / 2) {
            emit markerClicked(frame);
            event->accept();
            return;
        }
    }
    QSlider::mousePressEvent(event);
}

}  // namespace f2::viewer
