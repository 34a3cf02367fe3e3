#pragma once
/// The viewer's window: menus, actions, docks and the wiring between the
/// document, the clock, the render controller and the widgets. The work is
/// done by those classes; this one stays small.
#include <QMainWindow>
#include <QMessageBox>
#include <QTimer>
#include <functional>
#include <memory>

#include "animation_exporter.h"
#include "core/render/image.h"
#include "playback_antialias.h"
#include "problems_dock.h"
#include "render_controller.h"
#include "scene_locations.h"
#include "selection.h"

class QActionGroup;
class QLabel;
class QListWidget;
class QMenu;
class QDockWidget;

namespace f2 {
struct SceneDesc;
class FrameSink;
}  // namespace f2

namespace f2::viewer {

class EditorDock;
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

    /// Opens a scene file (command line, dialog, recent files, drops), after
    /// asking about unsaved edits; offers back an autosaved copy of it.
    /// Returns false if the user cancelled.
    bool openFile(const QString& path);
    /// Starts an empty untitled scene (after asking about unsaved edits).
    bool newFile();
    /// Opens the built-in default scene as untitled text.
    bool openDefaultScene();
    /// Writes the editor's text to the scene file (Save As for an untitled
    /// one), atomically. Returns whether it was written.
    bool saveScene();
    /// Asks for a file name and writes the editor's text there.
    bool saveSceneAs();
    /// Writes the editor's text to `path` atomically and makes it the document's file.
    bool writeScene(const QString& path);

    /// Offers back the autosaved copy of the open document, if there is one
    /// (opening a file does this; main() does it for the untitled start).
    void offerAutosave();

    /// The questions the window asks; tests answer them through setAsker().
    enum class Question {
        SaveChanges,        ///< Save / Discard / Cancel
        RestoreAutosave,    ///< Yes (restore the copy) / No (discard it)
        ReloadChangedFile,  ///< Yes (take the file on disk) / No (keep the editor's text)
    };
    using Asker = std::function<QMessageBox::StandardButton(Question, const QString& text)>;
    /// Replaces the message boxes (tests).
    void setAsker(Asker asker) { asker_ = std::move(asker); }
    /// Resizes the window so the picture area gets `viewportSize` (screen permitting).
    void resizeForViewport(QSize viewportSize);

    // For tests and main(): the parts of the window.
    SceneDocument* document() const { return document_; }
    Playback* playback() const { return playback_; }
    TimelineWidget* timeline() const { return timeline_; }
    ViewportWidget* viewport() const { return viewport_; }
    RenderController* renderController() const { return controller_.get(); }
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
    /// The folder the save and export dialogs start in: the scene's (the
    /// working folder for an untitled scene).
    QString outputFolder() const;
    /// The frame *Save Frame* writes: the current time and view, rendered at
    /// the render size (the scene's /camera size at *Scene Size*, whatever
    /// the docks take from the window).
    Image frameToSave() const;
    /// Selects what image point `imagePoint` (pixels of the picture on
    /// screen) shows in the frame on screen, or clears the selection on the
    /// background: outlined in the picture, named in the status bar, its
    /// creating line selected in the editor.
    void selectAt(QPointF imagePoint);
    void setSelection(std::optional<Selection> selection);
    const std::optional<Selection>& selection() const { return selection_; }
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
    /// While paused, the picture refines: the same frame again with 2x2, then
    /// kRefinedAntialias x kRefinedAntialias samples (View › Refine When Paused).
    /// Only the shaded view refines: the diagnostic views trace pixel centres.
    void setRefinement(bool on);
    /// The picture on screen is still to be refined.
    bool isRefining() const;
    /// The last step of refinement: what `f2 render --aa 4` computes.
    static constexpr int kRefinedAntialias = 4;
    /// View › Playback Anti-aliasing: the samples of frames rendered while playing (saved in the settings).
    void setPlaybackAntialias(PlaybackAntialiasMode mode);
    /// Its policy: the mode, the frame budget, the estimates (tests inject a cost model).
    PlaybackAntialias& playbackAntialias() { return playbackAntialias_; }
    /// The status bar's text about the samples of playing frames (empty while paused).
    QString playbackAntialiasStatus() const;
    /// The export of `scene` into `sink` from the current view: the loop's
    /// frames when loop points are set, else frames 0..last, at the scene's
    /// /camera size. `destination` names the output in messages.
    ExportJob exportJob(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                        const QString& destination) const;
    /// The status bar's text about the selection.
    QString selectionStatus() const;
    /// The window is on screen and so is a finished picture: the latest
    /// request, at the picture area's render size, refined when paused.
    bool isPictureComplete() const;
    /// The frame on screen (time, timings, size); serial 0 before the first.
    const FrameInfo& shownFrame() const { return shownFrame_; }

    static constexpr int kMaxRecentFiles = 8;

   public slots:
    /// Renders the current time and view soon (requests made in one event
    /// loop pass are coalesced into one).
    void scheduleFrame();
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
    void onTextLoaded(const QString& text);
    void onTextSettled();
    void onFileChangedOnDisk();
    /// True when there are no unsaved edits or the user saved or discarded them.
    bool maybeSave();
    /// False, with a status message, while the file's text is not in the editor yet.
    bool textIsReady();
    QMessageBox::StandardButton ask(Question question, const QString& text);
    void updateTitle();
    void onFrameReady(const QImage& image, const FrameInfo& info);
    void requestFrame();
    /// Asks for the frame on screen again with more samples, if it should refine.
    void refine();
    void updateStatus();
    /// Outline and status of the selection for the frame on screen.
    void updateSelectionView();
    /// Selects the selection's creating line in the editor; says in the status
    /// bar when a loop made it or it is in another file.
    void showCreatingLine();
    /// The editor's line of `created` (an object of `kind`), or 0 when it is
    /// in another file or the text has changed there since the scene parsed.
    int editorLineOf(const CreatedAt& created, ObjectKind kind) const;
    void openDialog();
    void saveFrame();
    void exportPngSequence();
    void exportVideo();
    /// The scene's name as the start of an exported file's name.
    QString exportStem() const;
    /// True (after saying so) if `path` is the scene file, which the viewer never writes.
    bool refuseSceneFile(const QString& path, const QString& title);
    /// The export flow shared by both: runs exportJob() with progress; errors
    /// go to a message box.
    void runExport(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                   const QString& destination);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    SceneDocument* document_ = nullptr;
    Playback* playback_ = nullptr;
    ViewportWidget* viewport_ = nullptr;
    TimelineWidget* timeline_ = nullptr;
    ProblemsDock* diagnosticsDock_ = nullptr;
    EditorDock* editorDock_ = nullptr;
    OpeningIndicator* opening_ = nullptr;
    QMetaObject::Connection deferredAutosaveOffer_;  // waits for a large file's text
    Asker asker_;
    QMenu* recentMenu_ = nullptr;
    QLabel* frameStatus_ = nullptr;
    QLabel* timeStatus_ = nullptr;
    QLabel* fpsStatus_ = nullptr;
    QLabel* sizeStatus_ = nullptr;
    QLabel* selectionStatus_ = nullptr;
    std::optional<Selection> selection_;
    QLabel* refineStatus_ = nullptr;
    QLabel* viewStatus_ = nullptr;  ///< the view mode of the picture on screen
    ViewModeMenu* viewModes_ = nullptr;
    bool refinement_ = true;
    QLabel* playbackAntialiasStatus_ = nullptr;
    QActionGroup* playbackAntialiasActions_ = nullptr;
    PlaybackAntialias playbackAntialias_;
    RenderRequest lastRequest_;  // the view the latest request showed, at 1 sample (paused)
    QTimer frameTimer_;          // coalesces scheduleFrame() calls
    QTimer statusTimer_;         // lets the FPS readout fall to 0 when nothing renders
    FrameInfo shownFrame_;
    // Declared last so it is destroyed first: its worker joins while every
    // widget it could talk to still exists.
    std::unique_ptr<RenderController> controller_;
};

}  // namespace f2::viewer
