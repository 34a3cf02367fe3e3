#pragma once
/// Command line of f2-viewer, kept out of main() so main stays a few lines.
#include <QSize>
#include <QString>
#include <optional>

class QApplication;

namespace f2::viewer {

class MainWindow;

struct ViewerOptions {
    QString scene;                ///< empty: the embedded default scene
    std::optional<double> frame;  ///< start paused at this frame
    std::optional<int> scale;     ///< RenderScale as int
    QSize viewportSize;           ///< invalid: the default 800x600
    double quitAfterSeconds = 0;  ///< > 0: quit after this long (scripts)
    bool stats = false;           ///< print achieved FPS on stderr when quitting
    QString screenshot;           ///< save the window here once a frame is complete, then quit
};

/// Parses argv; exits with a message on --help, --version or a bad option.
ViewerOptions parseViewerOptions(const QApplication& app);
/// Opens the scene, sets scale/size/frame, starts playing, arms --quit-after.
void applyViewerOptions(const ViewerOptions& options, MainWindow& window);

}  // namespace f2::viewer
