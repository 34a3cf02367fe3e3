#pragma once
/// The viewer's window: menus, actions, docks and the wiring between the
/// document, the clock, the render controller and the widgets. The work is
/// done by those classes; this one stays small.
#include <QMainWindow>
#include <QTimer>
#include <memory>

#include "render_controller.h"

class QLabel;
class QMenu;
class QPlainTextEdit;
class QDockWidget;

namespace f2 {
struct SceneDesc;
class FrameSink;
}  // namespace f2

namespace f2::viewer {

class Playback;
class SceneDocument;
class TimelineWidget;
class ViewportWidget;
enum class RenderScale;

class MainWindow : public QMainWindow {
    Q_OBJECT
   public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens a scene file (command line, dialog, recent files, drops).
    void openFile(const QString& path);
    /// Resizes the window so the picture area gets `viewportSize` (screen permitting).
    void resizeForViewport(QSize viewportSize);

    // For tests and main(): the parts of the window.
    SceneDocument* document() const { return document_; }
    Playback* playback() const { return playback_; }
    TimelineWidget* timeline() const { return timeline_; }
    ViewportWidget* viewport() const { return viewport_; }
    RenderController* renderController() const { return controller_.get(); }
    QPlainTextEdit* diagnosticsView() const { return diagnosticsView_; }
    QDockWidget* diagnosticsDock() const { return diagnosticsDock_; }
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

   private:
    void createActions();
    void onSceneChanged(bool newDocument);
    void onDiagnosticsChanged();
    void showDiagnostics();
    void onFrameReady(const QImage& image, const FrameInfo& info);
    void requestFrame();
    void updateStatus();
    void openDialog();
    void saveFrame();
    void exportPngSequence();
    void exportVideo();
    /// The scene's name as the start of an exported file's name.
    QString exportStem() const;
    /// True (after saying so) if `path` is the scene file, which the viewer never writes.
    bool refuseSceneFile(const QString& path, const QString& title);
    /// The export flow shared by both: renders frames 0..last of `scene` at its
    /// /camera size from the current view into `sink`, with progress; errors
    /// go to a message box. `destination` names the output in messages.
    void runExport(std::shared_ptr<const SceneDesc> scene, std::unique_ptr<FrameSink> sink,
                   const QString& destination);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    SceneDocument* document_ = nullptr;
    Playback* playback_ = nullptr;
    ViewportWidget* viewport_ = nullptr;
    TimelineWidget* timeline_ = nullptr;
    QDockWidget* diagnosticsDock_ = nullptr;
    QPlainTextEdit* diagnosticsView_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QLabel* frameStatus_ = nullptr;
    QLabel* timeStatus_ = nullptr;
    QLabel* fpsStatus_ = nullptr;
    QLabel* sizeStatus_ = nullptr;
    QTimer frameTimer_;   // coalesces scheduleFrame() calls
    QTimer statusTimer_;  // lets the FPS readout fall to 0 when nothing renders
    FrameInfo shownFrame_;
    // Declared last so it is destroyed first: its worker joins while every
    // widget it could talk to still exists.
    std::unique_ptr<RenderController> controller_;
};

}  // namespace f2::viewer
