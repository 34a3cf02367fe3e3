// f2-viewer: plays an F2 scene live in a Qt window.
#include <QApplication>

#include "main_window.h"
#include "viewer_options.h"
#include "window_system.h"

int main(int argc, char** argv) {
    QApplication::setOrganizationName("F2Stage");
    QApplication::setApplicationName("f2-viewer");
    QApplication::setApplicationVersion("0.1.0");

    // Options first: --help, --version and a bad option need no display.
    const f2::viewer::ViewerOptions options = f2::viewer::parseViewerOptions(argc, argv);
    const auto app = f2::viewer::openWindowSystem(argc, argv);  // or one line and exit 1
    f2::viewer::MainWindow window;
    f2::viewer::applyViewerOptions(options, window);  // shows the window
    return QApplication::exec();
}
