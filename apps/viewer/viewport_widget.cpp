#include "viewport_widget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "core/scene/limits.h"

namespace f2::viewer {

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);                 // the overlay lights the handle under the mouse
    setAttribute(Qt::WA_OpaquePaintEvent);  // paintEvent covers every pixel
    setCursor(Qt::OpenHandCursor);
    setToolTip(tr("Drag to orbit, wheel to zoom; View > Scene Camera to go back"));
}

void ViewportWidget::setSceneCamera(const Camera& camera, float targetDistance, bool keepOrbit) {
    sceneCamera_ = camera;
    targetDistance_ = targetDistance;
    if (!keepOrbit) orbit_.reset();
    emit viewChanged();
}

void ViewportWidget::resetView() {
    orbit_.reset();
    emit viewChanged();
}

void ViewportWidget::setRenderScale(RenderScale scale) {
    if (scale == scale_) return;
    scale_ = scale;
    emit viewChanged();
}

QSize ViewportWidget::renderSize() const {
    if (scale_ == RenderScale::SceneSize) return {sceneCamera_.width, sceneCamera_.height};
    const double factor = scale_ == RenderScale::Quarter ? 0.25 : scale_ == RenderScale::Half ? 0.5 : 1.0;
    // Device pixels, so a high-DPI screen gets a sharp picture at 100 %.
    const double k = factor * devicePixelRatioF();
    // SPEC 7 limits on the image; a huge high-DPI window must not exceed them.
    int w = std::clamp(int(std::lround(width() * k)), 1, kMaxImageSide);
    int h = std::clamp(int(std::lround(height() * k)), 1, kMaxImageSide);
    if (!imageSizeAllowed(w, h)) {
        const double shrink = std::sqrt(double(kMaxImagePixels) / (double(w) * h));
        w = std::max(1, int(w * shrink));
        h = std::max(1, int(h * shrink));
    }
    return {w, h};
}

Camera ViewportWidget::viewCamera(QSize size) const {
    const Camera base = sceneCamera_.resized(size.width(), size.height());
    return orbit_ ? orbit_->apply(base) : base;
}

void ViewportWidget::setImage(const QImage& image) {
    image_ = image;
    update();
}

void ViewportWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().color(QPalette::Window).darker(300));
    if (image_.isNull()) {
        painter.setPen(Qt::lightGray);
        painter.drawText(rect(), Qt::AlignCenter, tr("Rendering…"));
        return;
    }
    const QRectF target = imageRect();
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    painter.drawImage(target, image_);
    if (outline_) {
        const double sx = target.width() / image_.width(), sy = target.height() / image_.height();
        const QRectF r(target.left() + outline_->left() * sx, target.top() + outline_->top() * sy,
                       outline_->width() * sx, outline_->height() * sy);
        painter.setRenderHint(QPainter::Antialiasing, true);
        painter.setPen(QPen(QColor(255, 200, 40), 2, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(r.adjusted(-2, -2, 2, 2));
    }
    if (overlay_) overlay_->paint(painter);
}

Camera ViewportWidget::displayCamera() const {
    const QRectF r = imageRect();
    return viewCamera(
        QSize(std::max(1, int(std::lround(r.width()))), std::max(1, int(std::lround(r.height())))));
}

QRectF ViewportWidget::imageRect() const {
    // Fit the image into the widget keeping its aspect; while a resize is
    // being rendered the old frame is simply stretched.
    if (image_.isNull()) return {};
    const QSizeF fitted = QSizeF(image_.size()).scaled(QSizeF(size()), Qt::KeepAspectRatio);
    return {(width() - fitted.width()) / 2, (height() - fitted.height()) / 2, fitted.width(),
            fitted.height()};
}

std::optional<QPointF> ViewportWidget::imagePointAt(QPointF pos) const {
    const QRectF target = imageRect();
    if (target.isEmpty() || !target.contains(pos)) return std::nullopt;
    return QPointF((pos.x() - target.left()) * image_.width() / target.width(),
                   (pos.y() - target.top()) * image_.height() / target.height());
}

void ViewportWidget::setSelectionOutline(std::optional<QRectF> rect) {
    if (rect == outline_) return;
    outline_ = rect;
    update();
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (scale_ != RenderScale::SceneSize) emit viewChanged();
}

OrbitCamera& ViewportWidget::startOrbit() {
    if (!orbit_) orbit_ = OrbitCamera::fromCamera(sceneCamera_, targetDistance_);
    return *orbit_;
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
    if (overlay_ && !image_.isNull() && overlay_->press(event->position(), event->modifiers())) {
        overlayDrag_ = true;
        pressAt_ = event->position().toPoint();
        return;
    }
    dragFrom_ = event->position().toPoint();
    pressAt_ = *dragFrom_;
    dragged_ = false;
    setCursor(Qt::ClosedHandCursor);
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
    if (overlayDrag_) return overlay_->move(event->position(), event->modifiers());
    if (!dragFrom_) {
        if (overlay_ && event->buttons() == Qt::NoButton && !image_.isNull())
            overlay_->hover(event->position());
        return QWidget::mouseMoveEvent(event);
    }
    const QPoint now = event->position().toPoint();
    // A hand that shakes during a click does not turn the view.
    if (!dragged_ && (now - pressAt_).manhattanLength() <= kClickSlop) return;
    dragged_ = true;
    const QPoint delta = now - *dragFrom_;
    dragFrom_ = now;
    if (delta.isNull()) return;
    // Like grabbing a turntable: dragging right carries the near side of the
    // scene to the right (the eye swings left round the target); dragging
    // down shows it more from above.
    startOrbit().orbit(float(delta.x()) * kOrbitDegPerPixel, float(delta.y()) * kOrbitDegPerPixel);
    emit viewChanged();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mouseReleaseEvent(event);
    if (overlayDrag_) {
        overlayDrag_ = false;
        const bool click = (event->position().toPoint() - pressAt_).manhattanLength() <= kClickSlop;
        if (overlay_->release(event->position(), event->modifiers()) && click)
            if (const auto point = imagePointAt(event->position())) emit clicked(*point, event->modifiers());
        return;
    }
    const bool click = dragFrom_ && !dragged_;
    dragFrom_.reset();
    setCursor(Qt::OpenHandCursor);
    if (click)
        if (const auto point = imagePointAt(event->position())) emit clicked(*point, event->modifiers());
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;  // one notch = 120
    if (steps == 0) return;
    startOrbit().zoom(float(std::pow(kZoomPerWheelStep, steps)));
    emit viewChanged();
    event->accept();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
    if (overlay_ && overlay_->key(event)) return event->accept();
    QWidget::keyPressEvent(event);
}

}  // namespace f2::viewer
