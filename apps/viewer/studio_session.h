#pragma once
/// The studio under the widgets: the open document, the playback clock, the
/// frames asked of the render controller (coalesced, refined when paused, with
/// the playback anti-aliasing policy), the selection and the capture edits.
/// No widgets: the window shows what it says and applies the edits it returns,
/// and tests drive the editor-to-picture path through it without a window.
#include <QImage>
#include <QList>
#include <QObject>
#include <QPointF>
#include <QString>
#include <QTimer>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/render/camera.h"
#include "core/render/image.h"
#include "dope_sheet_model.h"
#include "gizmo.h"
#include "key_target.h"
#include "playback_antialias.h"
#include "render_controller.h"
#include "scene_locations.h"
#include "selection.h"
#include "text_capture.h"
#include "write_back.h"

namespace f2::viewer {

class Playback;
class SceneDocument;

class StudioSession : public QObject {
    Q_OBJECT
   public:
    explicit StudioSession(QObject* parent = nullptr);
    ~StudioSession() override;

    SceneDocument* document() const { return document_; }
    Playback* playback() const { return playback_; }
    RenderController* renderController() const { return controller_.get(); }

    /// The camera a frame is rendered with, given the scene's camera at its
    /// time: the window's picture size and look-around. Without one, the
    /// scene's camera at its /camera size.
    using ViewCamera = std::function<Camera(const Camera& sceneCamera)>;
    void setViewCamera(ViewCamera view) { viewCamera_ = std::move(view); }
    /// What the frames show (View › Mode); asks for a frame.
    void setViewMode(ViewMode mode);
    ViewMode viewMode() const { return viewMode_; }

    /// While paused, the picture refines: the same frame again with 2x2, then
    /// kRefinedAntialias x kRefinedAntialias samples. Only the shaded view
    /// refines: the diagnostic views trace pixel centres.
    void setRefinement(bool on);
    bool refinement() const { return refinement_; }
    /// The frame shown is still to be refined.
    bool isRefining() const;
    /// The last step of refinement: what `f2 render --aa 4` computes.
    static constexpr int kRefinedAntialias = 4;
    /// The samples of frames rendered while playing: mode, budget, estimates.
    PlaybackAntialias& playbackAntialias() { return playbackAntialias_; }
    const PlaybackAntialias& playbackAntialias() const { return playbackAntialias_; }
    /// The latest frame delivered (time, timings, size); serial 0 before the first.
    const FrameInfo& shownFrame() const { return shownFrame_; }
    /// A frame is shown and it is the last one coming: nothing asked, waiting
    /// or left to refine.
    bool isFrameSettled() const;
    /// The current time and `camera`'s view in the current view mode, rendered
    /// by the render controller before any waiting frame (Save Frame); `done`
    /// gets it on the GUI thread. Nothing happens without a scene.
    void renderStill(const Camera& camera, std::function<void(const Image&)> done);

    /// Selects what image point `imagePoint` shows in the frame shown when it
    /// is seen through `camera` (the view at that frame's size), or clears the
    /// selection on the background. Returns whether something is selected.
    bool pick(QPointF imagePoint, const Camera& camera);
    void setSelection(std::optional<Selection> selection);
    /// Selects `target` (`name`, `name.part`, a named light or `camera`) in
    /// the current scene; false (and nothing selected) when there is no scene
    /// or no such target.
    bool selectTarget(const QString& target);
    const std::optional<Selection>& selection() const { return selection_; }
    /// What shows the selection at the frame shown.
    struct SelectionView {
        QString label;         ///< the status bar's text: its target and centre
        Bounds bounds;         ///< to outline in the picture
        QList<int> keyFrames;  ///< its keys on the timeline (nearest whole frames)
    };
    /// Nothing without a selection (also after an edit deleted or renamed it).
    const std::optional<SelectionView>& selectionView() const { return selectionView_; }

    /// The dope sheet's rows: the selection's key tracks (the camera's
    /// without one), made from document()->text(), which dopeSheetText() keeps.
    const std::vector<DopeRow>& dopeSheetRows() const { return dopeRows_; }
    const QString& dopeSheetText() const { return dopeText_; }

    /// The editor line to select for the selection's creating command, and
    /// what the status bar says about it (empty: leave it).
    struct CreatingLine {
        int line = 0;  ///< 1-based line of `text`; 0 selects nothing
        QString message;
    };
    CreatingLine creatingLine(const QString& text) const;
    /// The editor line of the selected shape in its model's `/model` block
    /// (Ctrl+click), or the creating line for a primitive; the robot's and the
    /// human's shapes have no line, which the message says.
    CreatingLine shapeLine(const QString& text) const;

    /// The edits of one capture command (one undo step) and the status
    /// bar's note about them (shown for noteMs; empty: none).
    struct Capture {
        std::vector<TextEdit> edits;
        QString note;
        int noteMs = 0;
    };
    /// Set Camera from View: `lookAround` (the view's eye and rotation), else
    /// the scene camera's own pose, into the `/camera` line of `text`.
    Capture cameraFromView(const QString& text, const std::optional<Pose>& lookAround) const;
    /// Key Selection Here: the selection's pose at the current frame as its
    /// `/key` line in `text`. No edits (and a note) without a selection.
    Capture keySelectionHere(const QString& text) const;
    /// Key Camera Here: the camera's `/key` line at the current frame with
    /// the pose that shows `lookAround`, else the scene camera's own pose
    /// there (capture_pose.h, camera_key_writer.h).
    Capture keyCameraHere(const QString& text, const std::optional<Pose>& lookAround) const;

    /// The selection's key as the handles drag it (key_target.h): at the
    /// frame on the timeline, in the scene on screen. Nothing without a selection.
    std::optional<GizmoFrame> selectionKeyFrame() const;
    /// A handle is being dragged: the frame on the timeline is rendered with
    /// the selection's key there set to `key`, at a quarter of the view's size
    /// and without refinement, while the text stays as it is. The first call
    /// pauses playback.
    void previewKey(const Pose& key);
    /// The drag ended without writing (Esc): the text's picture again, at full size.
    void cancelPreview();
    /// The drag ended: the edits that write `key` at the frame on the
    /// timeline into `text` (write_back.h: the key line's numbers in place, a
    /// new key line, or the creating command's numbers; one undo step), and
    /// the edited text goes to the document at once. The picture keeps
    /// showing `key`, at full size, until that text has parsed (no flash of
    /// the old pose). A refusal (a target made in a loop or an included
    /// file) or no change: the text's picture again.
    WriteBack releaseKey(const QString& text, const Pose& key);
    bool isDragging() const { return dragging_; }

    /// The selection's path over the animation in the scene on screen: its
    /// origin (a part: its shape's centre) at every frame, and where it is at
    /// each of its keys.
    struct MotionPath {
        std::vector<Vec3> points;  ///< frames 0..last, at most kMaxPathPoints evenly spaced
        struct Dot {
            int frame;  ///< the key's time, to the nearest whole frame (as the timeline shows it)
            Vec3 at;
        };
        std::vector<Dot> keys;
    };
    /// Nothing without a selection; follows the frames shown.
    const std::optional<MotionPath>& motionPath() const { return motionPath_; }
    /// The named lights and the camera where they are in the frame shown:
    /// what the picture marks for a click to select them.
    std::vector<TargetMarker> targetMarkers() const;
    static constexpr int kMaxPathPoints = 1000;
    /// write_back.h's writeBack() on `text` with the document's last parse
    /// (a refusal without a scene): what a gesture released at the current
    /// frame writes. The window applies `edits` (or, asked, `offer`) with
    /// applySourceEdits() as one undo step.
    WriteBack writeBack(const QString& text, const WriteRequest& request) const;

   public slots:
    /// Renders the current time and view soon (requests made in one event
    /// loop pass are coalesced into one).
    void scheduleFrame();

   signals:
    /// The document has a new good scene; the clock already runs over it
    /// (`newDocument`: another file, back at frame 0 without a loop).
    void sceneChanged(bool newDocument);
    /// A frame came back and is now shownFrame() (selectionView() follows it).
    void frameShown(const QImage& image, const f2::viewer::FrameInfo& info);
    /// selection() or selectionView() changed.
    void selectionChanged();

   private:
    void onSceneChanged(bool newDocument);
    void requestFrame();
    /// Asks for the frame shown again with more samples, if it should refine.
    void refine();
    void onFrameReady(const QImage& image, const FrameInfo& info);
    /// selectionView_ for the frame shown; forgets a selection the scene lost.
    void updateSelectionView();
    /// dopeSheetRows() for the current scene, selection and text (made again
    /// only when one of them changed: this runs for every frame shown).
    void updateDopeSheet();
    /// What a request for `scene` asks the bounds of: the selection, if `scene` has it.
    std::optional<BoundsOf> selectionIn(const SceneDesc& scene) const;
    /// The line of `text` holding `created` (an object of type `type`: "sphere",
    /// "robot", "lamp"), or 0 when it is in another file or the text has
    /// changed there since the scene parsed.
    int lineOf(const QString& text, const CreatedAt& created, std::string_view type) const;
    /// The scene the picture shows: the drag's preview, else the document's.
    std::shared_ptr<const SceneDesc> sceneShown() const;
    void updateMotionPath(const std::shared_ptr<const SceneDesc>& scene);

    SceneDocument* document_ = nullptr;
    Playback* playback_ = nullptr;
    ViewCamera viewCamera_;
    ViewMode viewMode_ = ViewMode::Shaded;
    bool refinement_ = true;
    PlaybackAntialias playbackAntialias_;
    RenderRequest lastRequest_;  // the view the latest request showed, at 1 sample (paused)
    QTimer frameTimer_;          // coalesces scheduleFrame() calls
    FrameInfo shownFrame_;
    std::optional<Selection> selection_;
    std::optional<SelectionView> selectionView_;
    // A drag's picture (sceneWithKey): kept after the release until the edited text parses.
    std::shared_ptr<const SceneDesc> previewScene_;
    bool dragging_ = false;
    std::optional<MotionPath> motionPath_;
    // What motionPath_ was computed for.
    std::shared_ptr<const SceneDesc> pathScene_;
    std::optional<Selection> pathSelection_;
    std::vector<DopeRow> dopeRows_;
    QString dopeText_;
    std::shared_ptr<const SceneDesc> dopeScene_;
    std::optional<Selection> dopeSelection_;
    // Declared last so it is destroyed first: its worker joins while every
    // object it could talk to still exists.
    std::unique_ptr<RenderController> controller_;
};

}  // namespace f2::viewer
