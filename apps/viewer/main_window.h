#pragma once
/// The viewer's window: menus, actions, docks and the wiring between the
/// studio session (document, clock, frames, selection, capture edits) and the
/// widgets. The work is done by those classes; this one stays small.
#include <QMainWindow>
#include <functional>
#include <memory>

#include "animation_exporter.h"
#include "core/render/image.h"
#include "export_actions.h"
#include "playback_antialias.h"
#include "problems_dock.h"
#include "render_controller.h"
#include "scene_files.h"
#include "selection.h"
#include "status_readouts.h"
#include "studio_session.h"

class QActionGroup;
class QListWidget;

namespace f2 {
struct SceneDesc;
class FrameSink;
}  // namespace f2

namespace f2::viewer {

class EditorDock;
class GizmoTool;
class OpeningIndicator;
class Playback;
class SceneEditor;
class SceneDocument;
class TimelineWidget;
class ViewportWidget;
class ViewModeMenu;
enum class RenderScale;

class MainWindow : public QMainWindow {
    Q_OBJECT
   public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// The scene file's commands and questions (SceneFiles).
    SceneFiles* files() const { return files_; }
    bool openFile(const QString& path) { return files_->openFile(path); }
    bool newFile() { return files_->newFile(); }
    bool openDefaultScene() { return files_->openDefaultScene(); }
    bool saveScene() { return files_->saveScene(); }
    bool saveSceneAs() { return files_->saveSceneAs(); }
    bool writeScene(const QString& path) { return files_->writeScene(path); }
    void offerAutosave() { files_->offerAutosave(); }
    using Question = SceneFiles::Question;
    using Asker = SceneFiles::Asker;
    void setAsker(Asker asker) { files_->setAsker(std::move(asker)); }
    /// Resizes the window so the picture area gets `viewportSize` (screen permitting).
    void resizeForViewport(QSize viewportSize);

    // For tests and main(): the parts of the window.
    StudioSession* session() const { return session_; }
    SceneDocument* document() const { return document_; }
    Playback* playback() const { return playback_; }
    TimelineWidget* timeline() const { return timeline_; }
    ViewportWidget* viewport() const { return viewport_; }
    GizmoTool* gizmoTool() const { return gizmo_; }
    RenderController* renderController() const { return session_->renderController(); }
    /// View › Mode: what the picture shows (shaded or a diagnostic view).
    ViewModeMenu* viewModes() const { return viewModes_; }
    QListWidget* problemsList() const;
    ProblemsDock* diagnosticsDock() const { return diagnosticsDock_; }
    EditorDock* editorDock() const { return editorDock_; }
    /// A large file is still opening (parsing, or its text being laid out):
    /// the text cannot be saved or edited by the studio's actions yet.
    bool isOpening() const;
    OpeningIndicator* openingIndicator() const { return opening_; }
    SceneEditor* editor() const;
    /// File › Save Frame and the exports (ExportActions).
    ExportActions* exports() const { return exports_; }
    QString outputFolder() const { return exports_->outputFolder(); }
    void frameToSave(std::function<void(const Image&)> done) const { exports_->frameToSave(std::move(done)); }
    ExportJob exportJob(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                        const QString& destination) const {
        return exports_->exportJob(std::move(scene), std::move(sink), destination);
    }
    /// Selects what image point `imagePoint` (pixels of the picture on
    /// screen) shows in the frame on screen, or clears the selection on the
    /// background: outlined in the picture, named in the status bar, its
    /// creating line selected in the editor. `toShape` (Ctrl+click): the line
    /// of the shape clicked in its `/model` block instead (SPEC 10.1).
    void selectAt(QPointF imagePoint, bool toShape = false);
    void setSelection(std::optional<Selection> selection) { session_->setSelection(std::move(selection)); }
    const std::optional<Selection>& selection() const { return session_->selection(); }
    /// Writes the view (the look-around, else the scene camera) into the
    /// scene's `/camera` line, keeping its size and `d`. One undo step.
    void setCameraFromView();
    /// Writes the selection's pose at the current frame as its `/key` line
    /// there (replacing one at that frame). One undo step. False without a selection.
    bool keySelectionHere();
    /// Writes the camera's `/key` line at the current frame (replacing one at
    /// that frame) with the pose that shows the view on screen: the
    /// look-around's eye and rotation while orbiting, else the scene camera's
    /// own pose there (capture_pose.h). The camera's first key away from
    /// frame 0 comes with `/key 0 camera` at the `/camera` pose, so the shot's
    /// start stays (camera_key_writer.h). One undo step.
    void keyCameraHere();
    /// View › Refine When Paused (StudioSession::setRefinement).
    void setRefinement(bool on) { session_->setRefinement(on); }
    /// The picture on screen is still to be refined.
    bool isRefining() const { return session_->isRefining(); }
    static constexpr int kRefinedAntialias = StudioSession::kRefinedAntialias;
    /// View › Playback Anti-aliasing: the samples of frames rendered while playing (saved in the settings).
    void setPlaybackAntialias(PlaybackAntialiasMode mode);
    /// Its policy: the mode, the frame budget, the estimates (tests inject a cost model).
    PlaybackAntialias& playbackAntialias() { return session_->playbackAntialias(); }
    /// The status bar's text about the samples of playing frames (empty while paused).
    QString playbackAntialiasStatus() const { return readouts_->playbackAntialias(); }
    /// The status bar's text about the selection.
    QString selectionStatus() const { return readouts_->selection(); }
    /// The window is on screen and so is a finished picture: the latest
    /// request, at the picture area's render size, refined when paused.
    bool isPictureComplete() const;
    /// The frame on screen (time, timings, size); serial 0 before the first.
    const FrameInfo& shownFrame() const { return session_->shownFrame(); }

    static constexpr int kMaxRecentFiles = SceneFiles::kMaxRecentFiles;

   public slots:
    /// Renders the current time and view soon (requests made in one event
    /// loop pass are coalesced into one).
    void scheduleFrame() { session_->scheduleFrame(); }
    void setRenderScale(RenderScale scale);

   protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

   private:
    void createActions();
    void onSceneChanged(bool newDocument);
    void onDiagnosticsChanged();
    void onProblemClicked(const QString& file, int line, int column);
    void onFrameShown(const QImage& image, const FrameInfo& info);
    /// Outline, status and key markers of the session's selection.
    void showSelection();
    /// The look-around's eye and rotation, if the user is looking around.
    std::optional<Pose> lookAround() const;
    /// Applies a capture's edits to the editor (one undo step) and shows its
    /// note. Returns whether it wrote anything.
    bool applyCapture(const StudioSession::Capture& capture);

    StudioSession* session_ = nullptr;
    ExportActions* exports_ = nullptr;
    GizmoTool* gizmo_ = nullptr;
    SceneFiles* files_ = nullptr;
    StatusReadouts* readouts_ = nullptr;
    SceneDocument* document_ = nullptr;
    Playback* playback_ = nullptr;
    ViewportWidget* viewport_ = nullptr;
    TimelineWidget* timeline_ = nullptr;
    ProblemsDock* diagnosticsDock_ = nullptr;
    EditorDock* editorDock_ = nullptr;
    OpeningIndicator* opening_ = nullptr;
    ViewModeMenu* viewModes_ = nullptr;
    QActionGroup* playbackAntialiasActions_ = nullptr;
    /// The status bar shows a frame's drive error (SPEC 10.7), to be cleared when a frame has none.
    bool showsDriveProblem_ = false;
};

}  // namespace f2::viewer
