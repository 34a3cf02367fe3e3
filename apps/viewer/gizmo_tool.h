#pragma once
/// The selection's handles and motion path over the picture: draws them (in
/// the viewport's overlay), turns a drag of a handle into the session's live
/// preview and, on release, into one `/key` edit of the editor (one undo
/// step); a click on a key's dot on the path jumps to its frame. W moves, E
/// turns, L switches between the parent's and the target's own axes, Esc
/// cancels a drag, Ctrl snaps.
#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

#include "gizmo.h"
#include "selection.h"
#include "viewport_widget.h"
#include "write_back_prompt.h"

class QAction;
class QMenu;
class QPlainTextEdit;

namespace f2::viewer {

class StudioSession;

class GizmoTool : public QObject, public ViewportOverlay {
    Q_OBJECT
   public:
    /// Draws over `viewport` and writes into `editor`.
    GizmoTool(StudioSession* session, ViewportWidget* viewport, QPlainTextEdit* editor, QObject* parent);
    ~GizmoTool() override;

    /// Its actions (Move W, Turn E, Local Axes L) in `menu`, with their keys
    /// acting while `stage` (the picture and timeline) has the focus.
    void addActions(QMenu* menu, QWidget* stage);
    /// Asked before a drag starts: false (the text is not in the editor yet) refuses it.
    void setCanEdit(std::function<bool()> canEdit) { canEdit_ = std::move(canEdit); }
    /// Asks whether to take the write-back's offer when it refuses;
    /// write_back_prompt.h's question box unless a test sets one.
    void setOffer(OfferQuestion offer) { offer_ = std::move(offer); }

    GizmoMode mode() const { return mode_; }
    void setMode(GizmoMode mode);
    bool localAxes() const { return local_; }
    void setLocalAxes(bool local);
    bool isDragging() const { return drag_.has_value(); }
    /// The handles as the picture shows them now, in the viewport's
    /// displayCamera() pixels; nothing without a selection or a picture.
    std::optional<Gizmo> gizmo() const;
    /// The key dots of the motion path where they are drawn (widget positions) and their frames.
    std::vector<std::pair<QPointF, int>> pathDots() const;
    /// The named lights' and the camera's markers where they are drawn (widget
    /// positions; the camera's only while looking around, else it is the eye).
    std::vector<std::pair<QPointF, Selection>> markers() const;

    void paint(QPainter& painter) override;
    bool press(QPointF pos, Qt::KeyboardModifiers modifiers) override;
    void move(QPointF pos, Qt::KeyboardModifiers modifiers) override;
    bool release(QPointF pos, Qt::KeyboardModifiers modifiers) override;
    bool key(QKeyEvent* event) override;
    void hover(QPointF pos) override;

   signals:
    /// For the status bar: what the drag does (empty: clear it).
    void message(const QString& text, int timeoutMs = 0);

   private:
    /// The frame of the path dot, or the target of the marker, at widget position `pos`.
    std::optional<int> dotAt(QPointF pos) const;
    std::optional<Selection> markerAt(QPointF pos) const;
    /// `pos` (widget) in displayCamera() pixels.
    QPointF displayPoint(QPointF pos) const;
    void updateDrag(QPointF pos, Qt::KeyboardModifiers modifiers);
    void cancelDrag();
    void syncActions();
    void paintPath(QPainter& painter, const Camera& camera, QPointF offset) const;
    void paintMarkers(QPainter& painter) const;
    void paintGizmo(QPainter& painter, const Gizmo& gizmo, QPointF offset) const;

    StudioSession* session_;
    QPointer<ViewportWidget> viewport_;  // the window may delete it first
    QPlainTextEdit* editor_;
    std::function<bool()> canEdit_;
    OfferQuestion offer_;
    GizmoMode mode_ = GizmoMode::Move;
    bool local_ = false;
    std::optional<GizmoDrag> drag_;
    Pose dragPose_;  // the key with the mouse where it is
    QPointF pressedAt_;
    int hovered_ = -1;    // the GizmoHandle under the mouse, lit; -1: none
    bool moved_ = false;  // past the click slop: a shaking click moves nothing
    QAction* moveAction_ = nullptr;
    QAction* turnAction_ = nullptr;
    QAction* localAction_ = nullptr;
};

}  // namespace f2::viewer
