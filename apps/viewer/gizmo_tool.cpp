#include "gizmo_tool.h"

#include <QAction>
#include <QActionGroup>
#include <QKeyEvent>
#include <QMenu>
#include <QPainter>
#include <QPainterPath>
#include <QPlainTextEdit>
#include <cmath>

#include "playback.h"
#include "source_edit.h"
#include "studio_session.h"

namespace f2::viewer {

namespace {

const QColor kAxisColours[3] = {QColor(235, 70, 60), QColor(90, 200, 70), QColor(70, 130, 240)};
const QColor kScreenColour(250, 220, 90);
const QColor kPathColour(120, 220, 250);
constexpr double kDotRadius = 4;

QColor lit(QColor colour, bool active) { return active ? colour.lighter(150) : colour; }

/// A press or the mouse at `pos` is on what is drawn at `at`.
bool near(QPointF pos, QPointF at) {
    return std::hypot(pos.x() - at.x(), pos.y() - at.y()) <= Gizmo::kHitPixels;
}

}  // namespace

GizmoTool::GizmoTool(StudioSession* session, ViewportWidget* viewport, QPlainTextEdit* editor,
                     QObject* parent)
    : QObject(parent), session_(session), viewport_(viewport), editor_(editor) {
    viewport_->setOverlay(this);
    offer_ = offerBox(viewport_->window());
    // The handles follow the selection; the frames shown redraw the picture already.
    connect(session_, &StudioSession::selectionChanged, viewport_, qOverload<>(&QWidget::update));
}

GizmoTool::~GizmoTool() {
    if (viewport_) viewport_->setOverlay(nullptr);
}

void GizmoTool::addActions(QMenu* menu, QWidget* stage) {
    QMenu* handles = menu->addMenu(tr("&Handles"));
    auto* modes = new QActionGroup(this);
    const auto add = [&](const QString& label, Qt::Key key, auto slot) {
        QAction* action = handles->addAction(label, this, slot);
        action->setShortcut(QKeySequence(key));
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        action->setCheckable(true);
        stage->addAction(action);
        return action;
    };
    moveAction_ = add(tr("&Move"), Qt::Key_W, [this] { setMode(GizmoMode::Move); });
    turnAction_ = add(tr("&Turn"), Qt::Key_E, [this] { setMode(GizmoMode::Turn); });
    modes->addAction(moveAction_);
    modes->addAction(turnAction_);
    handles->addSeparator();
    localAction_ = add(tr("&Local Axes"), Qt::Key_L, [this] { setLocalAxes(!local_); });
    syncActions();
}

void GizmoTool::syncActions() {
    if (!moveAction_) return;
    moveAction_->setChecked(mode_ == GizmoMode::Move);
    turnAction_->setChecked(mode_ == GizmoMode::Turn);
    localAction_->setChecked(local_);
}

void GizmoTool::setMode(GizmoMode mode) {
    if (drag_) return;  // a drag keeps its handle
    mode_ = mode;
    syncActions();
    viewport_->update();
}

void GizmoTool::setLocalAxes(bool local) {
    if (drag_) return;
    local_ = local;
    syncActions();
    emit message(local ? tr("Handles along the target's own axes") : tr("Handles along its parent's axes"),
                 3000);
    viewport_->update();
}

QPointF GizmoTool::displayPoint(QPointF pos) const { return pos - viewport_->imageRect().topLeft(); }

std::optional<Gizmo> GizmoTool::gizmo() const {
    if (viewport_->image().isNull()) return std::nullopt;
    if (drag_) {
        // The frame the drag started from, with the key where the mouse has it.
        GizmoFrame frame = drag_->gizmo().frame();
        frame.pose = dragPose_;
        return Gizmo(drag_->gizmo().camera(), frame, mode_, local_);
    }
    const auto frame = session_->selectionKeyFrame();
    if (!frame) return std::nullopt;
    Gizmo g(viewport_->displayCamera(), *frame, mode_, local_);
    return g.visible() ? std::optional(g) : std::nullopt;
}

std::vector<std::pair<QPointF, int>> GizmoTool::pathDots() const {
    std::vector<std::pair<QPointF, int>> dots;
    const auto& path = session_->motionPath();
    if (!path || viewport_->image().isNull()) return dots;
    const Camera camera = viewport_->displayCamera();
    const QPointF offset = viewport_->imageRect().topLeft();
    for (const auto& key : path->keys) {
        float px = 0, py = 0;
        if (camera.project(key.at, px, py)) dots.emplace_back(offset + QPointF(px, py), key.frame);
    }
    return dots;
}

std::vector<std::pair<QPointF, Selection>> GizmoTool::markers() const {
    std::vector<std::pair<QPointF, Selection>> out;
    if (viewport_->image().isNull()) return out;
    const Camera camera = viewport_->displayCamera();
    const QPointF offset = viewport_->imageRect().topLeft();
    for (const TargetMarker& marker : session_->targetMarkers()) {
        // Nearer than this the marker is the eye itself (the camera seen through).
        if (length(marker.at - camera.eye) < 1e-3f) continue;
        float px = 0, py = 0;
        if (camera.project(marker.at, px, py)) out.emplace_back(offset + QPointF(px, py), marker.target);
    }
    return out;
}

std::optional<int> GizmoTool::dotAt(QPointF pos) const {
    for (const auto& [at, frame] : pathDots())
        if (near(pos, at)) return frame;
    return std::nullopt;
}

std::optional<Selection> GizmoTool::markerAt(QPointF pos) const {
    for (const auto& [at, target] : markers())
        if (near(pos, at)) return target;
    return std::nullopt;
}

void GizmoTool::paint(QPainter& painter) {
    if (viewport_->image().isNull()) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const QPointF offset = viewport_->imageRect().topLeft();
    painter.setClipRect(viewport_->imageRect());
    paintMarkers(painter);
    if (session_->selection()) {
        paintPath(painter, viewport_->displayCamera(), offset);
        if (const auto g = gizmo()) paintGizmo(painter, *g, offset);
    }
    painter.restore();
}

void GizmoTool::paintMarkers(QPainter& painter) const {
    for (const auto& [at, target] : markers()) {
        const bool selected = session_->selection() == target;
        painter.setPen(QPen(selected ? kScreenColour : QColor(230, 230, 230), selected ? 2 : 1.2));
        painter.setBrush(QColor(40, 40, 40, 160));
        if (target.kind == Selection::Kind::Camera) {
            // A box with a lens.
            painter.drawRect(QRectF(at - QPointF(6, 4), QSizeF(9, 8)));
            painter.drawPolygon(QPolygonF({at + QPointF(3, 0), at + QPointF(7, -4), at + QPointF(7, 4)}));
            continue;
        }
        // A bulb with rays.
        painter.drawEllipse(at, 4, 4);
        for (int k = 0; k < 8; ++k) {
            const double a = k * kPi / 4;
            const QPointF d(std::cos(a), std::sin(a));
            painter.drawLine(at + d * 6, at + d * 8.5);
        }
    }
}

void GizmoTool::paintPath(QPainter& painter, const Camera& camera, QPointF offset) const {
    const auto& path = session_->motionPath();
    if (!path) return;
    // A polyline broken where the path goes behind the eye.
    QPainterPath line;
    bool drawing = false;
    for (const Vec3& p : path->points) {
        float px = 0, py = 0;
        if (!camera.project(p, px, py)) {
            drawing = false;
            continue;
        }
        const QPointF at = offset + QPointF(px, py);
        drawing ? line.lineTo(at) : line.moveTo(at);
        drawing = true;
    }
    painter.setPen(QPen(kPathColour, 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(line);
    const int frame = session_->playback()->frame();
    for (const auto& [at, keyFrame] : pathDots()) {
        painter.setPen(QPen(Qt::black, 1));
        painter.setBrush(keyFrame == frame ? kScreenColour : kPathColour);
        painter.drawEllipse(at, kDotRadius, kDotRadius);
    }
}

void GizmoTool::paintGizmo(QPainter& painter, const Gizmo& g, QPointF offset) const {
    const int active = drag_ ? int(drag_->handle()) : hovered_;
    const QPointF c = offset + g.centre();
    painter.setBrush(Qt::NoBrush);
    for (int i = 0; i < 3; ++i) {
        const bool on = active == i;
        painter.setPen(QPen(lit(kAxisColours[i], on), on ? 3.5 : 2.2, Qt::SolidLine, Qt::RoundCap));
        if (g.mode() == GizmoMode::Turn) {
            QPolygonF ring;
            for (const QPointF& p : g.ring(i)) ring << offset + p;
            painter.drawPolygon(ring);
            continue;
        }
        const QPointF end = offset + g.arrowEnd(i);
        painter.drawLine(c, end);
        // The head: a small triangle pointing along the arrow.
        const QPointF d = end - c;
        const double length = std::hypot(d.x(), d.y());
        if (length < 1) continue;
        const QPointF u = d / length, n(-u.y(), u.x());
        painter.setBrush(lit(kAxisColours[i], on));
        painter.drawPolygon(QPolygonF({end + u * 7, end - u * 3 + n * 4.5, end - u * 3 - n * 4.5}));
        painter.setBrush(Qt::NoBrush);
    }
    if (g.mode() == GizmoMode::Move) {
        const bool on = active == int(GizmoHandle::Screen);
        const double h = g.squareHalf();
        painter.setPen(QPen(lit(kScreenColour, on), on ? 3 : 2));
        painter.drawRect(QRectF(c - QPointF(h, h), c + QPointF(h, h)));
    }
}

bool GizmoTool::press(QPointF pos, Qt::KeyboardModifiers) {
    if (const auto g = gizmo()) {
        if (const auto handle = g->hit(displayPoint(pos))) {
            if (canEdit_ && !canEdit_()) return true;  // the press is the handle's all the same
            drag_.emplace(*g, *handle, displayPoint(pos));
            dragPose_ = g->frame().pose;
            pressedAt_ = pos;
            moved_ = false;
            viewport_->setCursor(Qt::ClosedHandCursor);
            viewport_->update();
            return true;
        }
    }
    if (const auto frame = dotAt(pos)) {
        session_->playback()->pause();
        session_->playback()->seek(*frame);
        return true;
    }
    // A light or the camera has no surface for a click: its marker selects it.
    if (const auto target = markerAt(pos)) {
        session_->setSelection(*target);
        return true;
    }
    return false;
}

void GizmoTool::updateDrag(QPointF pos, Qt::KeyboardModifiers modifiers) {
    const Pose pose = drag_->update(displayPoint(pos), modifiers.testFlag(Qt::ControlModifier));
    if (pose == dragPose_) return;
    dragPose_ = pose;
    session_->previewKey(pose);
    const auto numbers = [](Vec3 v) {
        return QStringLiteral("%1 %2 %3").arg(shortestNumber(v.x), shortestNumber(v.y), shortestNumber(v.z));
    };
    emit message(tr("%1 at frame %2: %3  %4  (Ctrl snaps, Esc cancels)")
                     .arg(session_->selection()->target())
                     .arg(session_->playback()->frame())
                     .arg(numbers(pose.position), numbers(pose.rotation)));
    viewport_->update();
}

void GizmoTool::move(QPointF pos, Qt::KeyboardModifiers modifiers) {
    if (!drag_) return;
    if (!moved_ && (pos - pressedAt_).manhattanLength() <= ViewportWidget::kClickSlop) return;
    moved_ = true;
    updateDrag(pos, modifiers);
}

bool GizmoTool::release(QPointF pos, Qt::KeyboardModifiers modifiers) {
    if (!drag_) return false;  // a path dot, or a drag Esc cancelled
    if (!moved_) {
        drag_.reset();
        viewport_->setCursor(Qt::OpenHandCursor);
        viewport_->update();
        return true;  // a click on a handle
    }
    updateDrag(pos, modifiers);
    const Pose start = drag_->gizmo().frame().pose;
    drag_.reset();
    viewport_->setCursor(Qt::OpenHandCursor);
    viewport_->update();
    if (dragPose_ == start) {  // dragged back to where it started
        if (session_->isDragging()) session_->cancelPreview();
        return false;
    }
    const WriteBack write = session_->releaseKey(editor_->toPlainText(), dragPose_);
    // A loop or an included file made the target: say why, and offer the key elsewhere.
    if (write.refused()) emit message(write.refusal, 10000);
    if (applyWriteBack(editor_, write, offer_) == WriteBackOutcome::Written) emit message({});
    return false;
}

void GizmoTool::cancelDrag() {
    drag_.reset();
    session_->cancelPreview();
    viewport_->setCursor(Qt::OpenHandCursor);
    viewport_->update();
    emit message(tr("Drag cancelled"), 3000);
}

void GizmoTool::hover(QPointF pos) {
    const auto g = gizmo();
    const auto handle = g ? g->hit(displayPoint(pos)) : std::nullopt;
    const int hovered = handle ? int(*handle) : -1;
    // A pointing hand over what a click acts on: a handle, a key's dot, a marker.
    const bool onSomething = handle || dotAt(pos) || markerAt(pos);
    viewport_->setCursor(onSomething ? Qt::PointingHandCursor : Qt::OpenHandCursor);
    if (hovered == hovered_) return;
    hovered_ = hovered;
    viewport_->update();
}

bool GizmoTool::key(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && drag_) {
        cancelDrag();
        return true;
    }
    // The same keys as the actions, for a viewport without them (tests, embedding).
    if (event->modifiers() != Qt::NoModifier) return false;
    switch (event->key()) {
        case Qt::Key_W:
            setMode(GizmoMode::Move);
            return true;
        case Qt::Key_E:
            setMode(GizmoMode::Turn);
            return true;
        case Qt::Key_L:
            setLocalAxes(!local_);
            return true;
        default:
            return false;
    }
}

}  // namespace f2::viewer
