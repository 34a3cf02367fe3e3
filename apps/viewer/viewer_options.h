#pragma once
/// Command line of f2-viewer, kept out of main() so main stays a few lines.
#include <QSize>
#include <QString>
#include <optional>

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
    QString select;               ///< select this target (`name`, `name.part`) once the scene is there
};

/// Parses argv before any window system is opened: prints the usage or the
/// version and exits 0 on --help / --version, prints one line and exits 2 on
/// a bad option or value. Numbers are read by f2's rules (io/option_value.h).
ViewerOptions parseViewerOptions(int& argc, char** argv);
/// Sets scale and size, shows the window, opens the scene, sets the frame,
/// starts playing, arms --quit-after, --stats and --screenshot.
void applyViewerOptions(const ViewerOptions& options, MainWindow& window);

}  // namespace f2::viewer
