#pragma once
/// Opening the window system without Qt's abort: QGuiApplication's constructor
/// calls qFatal (abort, exit 134, six lines about reinstalling) when its
/// platform plugin cannot start, e.g. xcb without an X display. f2-viewer
/// says so in one line and exits 1 instead (docs/viewer.md, "Without a display").
#include <QProcessEnvironment>
#include <QString>
#include <memory>

class QApplication;

namespace f2::viewer {

/// Exit code when no window can be opened.
inline constexpr int kNoDisplayExit = 1;

/// Why Qt's platform plugins, as QT_QPA_PLATFORM names them (a `;` list; unset:
/// xcb or wayland), cannot reach a display in `env` — "DISPLAY is not set",
/// "neither DISPLAY nor WAYLAND_DISPLAY is set" — or "" when one may: xcb needs
/// DISPLAY; wayland needs WAYLAND_DISPLAY, WAYLAND_SOCKET or
/// $XDG_RUNTIME_DIR/wayland-0; every other plugin (offscreen, minimal, vnc,
/// eglfs, ...) is left to Qt to try.
QString displayProblem(const QProcessEnvironment& env);

/// Constructs the QApplication. Without a display (displayProblem) or when a
/// platform plugin fails anyway (DISPLAY names no server), prints
/// "f2-viewer: cannot open a display (REASON); use f2 render to render without one"
/// on stderr and exits kNoDisplayExit. Qt's messages during a successful start
/// are passed on as before.
std::unique_ptr<QApplication> openWindowSystem(int& argc, char** argv);

}  // namespace f2::viewer
