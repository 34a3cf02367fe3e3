#include "key_marker_slider.h"

#include <QContextMenuEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QStyle>
#include <QStyleOptionSlider>
#include <algorithm>

namespace f2::viewer {

KeyMarkerSlider::KeyMarkerSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {}

void KeyMarkerSlider::setMarkers(QList<int> frames) {
    if (frames == markers_) return;
    markers_ = std::move(frames);
    update();
}

void KeyMarkerSlider::setLoop(std::optional<std::pair<int, int>> loop) {
    if (loop == loop_) return;
    loop_ = loop;
    update();
}

KeyMarkerSlider::Track KeyMarkerSlider::track() const {
    // The geometry QSlider places its handle with, so marks sit under it.
    QStyleOptionSlider option;
    initStyleOption(&option);
    const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
    const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
    return {groove.left() + handle.width() / 2, std::max(1, groove.width() - handle.width()),
            option.upsideDown};
}

int KeyMarkerSlider::positionOf(int frame) const {
    const Track t = track();
    return t.start + QStyle::sliderPositionFromValue(minimum(), maximum(), frame, t.span, t.upsideDown);
}

int KeyMarkerSlider::frameAtPosition(int x) const {
    const Track t = track();
    return QStyle::sliderValueFromPosition(minimum(), maximum(), std::clamp(x - t.start, 0, t.span), t.span,
                                           t.upsideDown);
}

void KeyMarkerSlider::paintEvent(QPaintEvent* event) {
    QSlider::paintEvent(event);
    if (markers_.isEmpty() && !loop_) return;
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(Qt::NoPen);
    if (loop_) {
        // A bar above the groove over the looped frames (the handle stays
        // clear) and a flag at each end, pointing inward.
        const int in = positionOf(loop_->first), out = positionOf(loop_->second);
        const int s = kLoopFlagSize;
        painter.setBrush(QColor(40, 140, 255, 110));
        painter.drawRect(QRect(QPoint(in, 0), QPoint(out, s / 2)));
        painter.setBrush(QColor(40, 140, 255));
        const QPoint inFlag[3] = {{in, 0}, {in + 2 * s, 0}, {in, 2 * s}};
        const QPoint outFlag[3] = {{out, 0}, {out - 2 * s, 0}, {out, 2 * s}};
        painter.drawPolygon(inFlag, 3);
        painter.drawPolygon(outFlag, 3);
    }
    painter.setBrush(QColor(255, 170, 0));
    for (int frame : markers_) {
        // A small diamond under the groove, like key frames in animation tools.
        const int x = positionOf(frame), y = height() - 5;
        const QPoint diamond[4] = {{x, y - 4}, {x + 4, y}, {x, y + 4}, {x - 4, y}};
        painter.drawPolygon(diamond, 4);
    }
}

void KeyMarkerSlider::mousePressEvent(QMouseEvent* event) {
    const QPoint at = event->position().toPoint();
    if (event->button() == Qt::LeftButton && loop_ && at.y() <= 2 * kLoopFlagSize) {
        // The out flag first: when both sit on one frame, dragging right must be possible.
        for (const auto& [flag, frame] :
             {std::pair{LoopFlag::Out, loop_->second}, {LoopFlag::In, loop_->first}}) {
            if (std::abs(positionOf(frame) - at.x()) > kMarkerReach + kLoopFlagSize) continue;
            dragging_ = flag;
            event->accept();
            return;
        }
    }
    if (event->button() == Qt::LeftButton) {
        for (int frame : markers_) {
            if (std::abs(positionOf(frame) - at.x()) <= kMarkerReach && at.y() >= height() / 2) {
                emit markerClicked(frame);
                event->accept();
                return;
            }
        }
    }
    QSlider::mousePressEvent(event);
}

void KeyMarkerSlider::mouseMoveEvent(QMouseEvent* event) {
    if (dragging_ == LoopFlag::None) return QSlider::mouseMoveEvent(event);
    const int frame = frameAtPosition(event->position().toPoint().x());
    if (dragging_ == LoopFlag::In)
        emit loopInRequested(frame);
    else
        emit loopOutRequested(frame);
    event->accept();
}

void KeyMarkerSlider::mouseReleaseEvent(QMouseEvent* event) {
    if (dragging_ == LoopFlag::None) return QSlider::mouseReleaseEvent(event);
    dragging_ = LoopFlag::None;
    event->accept();
}

std::unique_ptr<QMenu> KeyMarkerSlider::loopMenu(int frame) {
    auto menu = std::make_unique<QMenu>(this);
    menu->addAction(tr("Set Loop &In at Frame %1").arg(frame), this,
                    [this, frame] { emit loopInRequested(frame); });
    menu->addAction(tr("Set Loop &Out at Frame %1").arg(frame), this,
                    [this, frame] { emit loopOutRequested(frame); });
    menu->addAction(tr("&Clear Loop"), this, &KeyMarkerSlider::loopClearRequested)
        ->setEnabled(loop_.has_value());
    return menu;
}

void KeyMarkerSlider::contextMenuEvent(QContextMenuEvent* event) {
    loopMenu(frameAtPosition(event->pos().x()))->exec(event->globalPos());
}

}  // namespace f2::viewer
