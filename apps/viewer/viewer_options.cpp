#include "viewer_options.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QPixmap>
#include <QSaveFile>
#include <QTimer>
#include <QWindow>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "io/option_value.h"
#include "main_window.h"
#include "opening_indicator.h"
#include "playback.h"
#include "scene_document.h"
#include "studio_session.h"
#include "viewport_widget.h"

namespace f2::viewer {

namespace {
constexpr double kStatsWarmUpSeconds = 1.0;  // skip start-up (first frames, window mapping)

/// A usage error as f2 reports one: one line with a pointer to --help, exit 2.
[[noreturn]] void fail(QString message) {
    if (message.endsWith('.')) message.chop(1);  // Qt's "Unknown option 'x'."
    std::fprintf(stderr, "f2-viewer: %s (see f2-viewer --help)\n", qPrintable(message));
    std::exit(2);
}

/// The option's value read by `read` (an io::readXxx), or a usage error naming the option.
template <typename Read>
auto valueOf(const QCommandLineParser& parser, const QCommandLineOption& option, Read read) {
    const auto value = read(parser.value(option).toStdString());
    if (!value.ok()) fail("--" + option.names().constFirst() + ": " + QString::fromStdString(value.error));
    return value.value;
}

/// The longest --quit-after: a day (QTimer counts milliseconds in an int).
constexpr double kMaxQuitAfterSeconds = 86400;
/// The shortest: one millisecond (less is 0 ms, i.e. no timer at all).
constexpr double kMinQuitAfterSeconds = 0.001;
/// The smallest picture area --size accepts, a side.
constexpr int kMinViewportSide = 16;
/// Prints on quitting the longest time the GUI thread did not come back to its
/// event loop: a timer that should tick every few milliseconds measures its gaps.
void watchGuiPauses(MainWindow& window) {
    auto* ticker = new QTimer(&window);
    ticker->setInterval(5);
    auto since = std::make_shared<QElapsedTimer>();
    auto longestNs = std::make_shared<qint64>(0);
    since->start();
    QObject::connect(ticker, &QTimer::timeout, &window, [since, longestNs] {
        *longestNs = std::max(*longestNs, since->nsecsElapsed());
        since->restart();
    });
    ticker->start();
    QObject::connect(qApp, &QCoreApplication::aboutToQuit, &window, [longestNs] {
        std::fprintf(stderr, "f2-viewer: the GUI thread's longest pause was %.0f ms\n",
                     double(*longestNs) * 1e-6);
    });
}
}  // namespace

ViewerOptions parseViewerOptions(int& argc, char** argv) {
    QCommandLineParser parser;
    parser.setApplicationDescription("Plays an F2 scene (default: the embedded demo scene) live.");
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    parser.addPositionalArgument("scene", "Scene file (.f2) to open");
    QCommandLineOption frame("frame", "Start paused at frame <n>.", "n");
    QCommandLineOption scale("scale", "Render scale: 25, 50, 100 or scene.", "scale");
    QCommandLineOption size("size", "Picture area size WIDTHxHEIGHT (default 800x600).", "size");
    QCommandLineOption quitAfter("quit-after", "Quit after <seconds> (for scripts).", "seconds");
    QCommandLineOption stats(
        "stats", "Print the achieved frames per second and the GUI thread's longest pause on exit.");
    QCommandLineOption screenshot("screenshot",
                                  "Save the window as PNG <file> once the picture is complete (rendered at "
                                  "the window's size and, when paused, refined), then quit.",
                                  "file");
    QCommandLineOption select(
        "select",
        "Select <target> (name, name.part, a named light or camera): its outline or marker, its keys in "
        "the dope sheet.",
        "target");
    parser.addOptions({frame, scale, size, quitAfter, stats, screenshot, select});
    // Read argv as QCoreApplication::arguments() does, without an application:
    // no window system is needed to show the usage or to refuse an option.
    QStringList arguments;
    for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
    // process() would exit 1 on an unknown option; parse first, then let it show --help or --version
    // (it needs an application object for the program's name; a QCoreApplication opens no display).
    if (!parser.parse(arguments)) fail(parser.errorText());
    if (parser.isSet(help) || parser.isSet("help-all") || parser.isSet(version)) {
        QCoreApplication app(argc, argv);
        parser.process(app);  // prints and exits 0
    }

    ViewerOptions options;
    const QStringList args = parser.positionalArguments();
    if (args.size() > 1) fail("expected at most one scene file");
    if (!args.isEmpty()) options.scene = args.first();
    if (parser.isSet(frame))
        options.frame = valueOf(parser, frame, [](const std::string& text) {
            return io::readFiniteNumber(text, 0.0, 1e7, "a frame time");  // as f2 render --frame
        });
    if (parser.isSet(scale)) {
        const QString s = parser.value(scale);
        if (s == "25")
            options.scale = int(RenderScale::Quarter);
        else if (s == "50")
            options.scale = int(RenderScale::Half);
        else if (s == "100")
            options.scale = int(RenderScale::Full);
        else if (s == "scene")
            options.scale = int(RenderScale::SceneSize);
        else
            fail("--scale: expected 25, 50, 100 or scene");
    }
    if (parser.isSet(size)) {
        const io::ImageSize wh = valueOf(parser, size, io::readImageSize);  // as f2 render --size
        if (wh.width < kMinViewportSide || wh.height < kMinViewportSide)
            fail(QString("--size: %1 is smaller than the smallest picture area, %2x%2")
                     .arg(parser.value(size))
                     .arg(kMinViewportSide));
        options.viewportSize = QSize(wh.width, wh.height);
    }
    if (parser.isSet(quitAfter))
        options.quitAfterSeconds = valueOf(parser, quitAfter, [](const std::string& text) {
            return io::readFiniteNumber(text, kMinQuitAfterSeconds, kMaxQuitAfterSeconds, "a duration");
        });
    options.stats = parser.isSet(stats);
    options.screenshot = parser.value(screenshot);
    if (parser.isSet(screenshot) && options.screenshot.isEmpty()) fail("--screenshot: expected a file");
    options.select = parser.value(select);
    return options;
}

void applyViewerOptions(const ViewerOptions& options, MainWindow& window) {
    if (options.scale) window.setRenderScale(RenderScale(*options.scale));
    if (options.viewportSize.isValid()) window.resizeForViewport(options.viewportSize);
    // Shown before the scene opens: a Problems dock that opens for it measures
    // the laid-out window and grows it (a hidden one would shrink the picture).
    window.show();
    // --stats: the GUI thread's longest pause from here (opening the file) to quitting.
    if (options.stats) watchGuiPauses(window);
    if (!options.scene.isEmpty())
        window.openFile(options.scene);
    else
        window.offerAutosave();
    if (!options.select.isEmpty()) {
        // The scene may still be parsing (a file): select when it is there.
        StudioSession* session = window.session();
        if (!session->selectTarget(options.select))
            QObject::connect(
                session, &StudioSession::sceneChanged, &window,
                [session, target = options.select] { session->selectTarget(target); },
                Qt::SingleShotConnection);
    }
    if (options.frame) {
        auto startAt = [&window, frame = *options.frame] {
            window.playback()->pause();
            window.playback()->seek(frame);
        };
        startAt();
        // A large file's scene arrives later and starts at frame 0: seek again then.
        if (window.document()->isOpening())
            QObject::connect(window.document(), &SceneDocument::openingChanged, &window, startAt,
                             Qt::SingleShotConnection);
    } else {
        window.playback()->play();
    }

    if (options.stats) {
        // Count the frames shown after a warm-up, until quitting.
        auto clock = std::make_shared<QElapsedTimer>();
        auto startCount = std::make_shared<quint64>(0);
        QTimer::singleShot(int(kStatsWarmUpSeconds * 1000), &window, [&window, clock, startCount] {
            *startCount = window.renderController()->framesDelivered();
            clock->start();
        });
        QObject::connect(qApp, &QCoreApplication::aboutToQuit, &window, [&window, clock, startCount] {
            if (!clock->isValid()) return;
            const double seconds = double(clock->nsecsElapsed()) * 1e-9;
            const quint64 frames = window.renderController()->framesDelivered() - *startCount;
            const FrameInfo& last = window.shownFrame();
            std::fprintf(stderr,
                         "f2-viewer: %llu frames in %.2f s = %.1f fps achieved (scene %d fps), %dx%d, "
                         "last frame %.1f ms with %dx%d samples, %llu requests skipped\n",
                         static_cast<unsigned long long>(frames), seconds, frames / seconds,
                         window.playback()->fps(), last.size.width(), last.size.height(),
                         last.timings.totalMs(), last.antialias, last.antialias,
                         static_cast<unsigned long long>(window.renderController()->framesSkipped()));
        });
    }
    if (!options.screenshot.isEmpty()) {
        // Wait for a real condition, not a delay: the window is on screen, the
        // frame just shown is complete and a large file has finished opening.
        // Checked after every frame (this connection runs after the window's
        // own, which has shown it) and when the file's text is in the editor.
        auto shootWhenReady = [&window, file = options.screenshot, taken = std::make_shared<bool>(false)] {
            if (*taken || !window.isPictureComplete() || window.isOpening()) return;
            *taken = true;
            // Let the window paint that frame first, then grab it.
            QTimer::singleShot(0, &window, [&window, file] {
                QSaveFile out(file);
                const bool ok =
                    out.open(QIODevice::WriteOnly) && window.grab().save(&out, "PNG") && out.commit();
                if (!ok) std::fprintf(stderr, "f2-viewer: cannot write %s\n", qPrintable(file));
                QCoreApplication::exit(ok ? 0 : 1);
            });
        };
        QObject::connect(window.renderController(), &RenderController::frameReady, &window, shootWhenReady);
        QObject::connect(window.openingIndicator(), &OpeningIndicator::opened, &window, shootWhenReady);
    }
    if (options.quitAfterSeconds > 0)
        QTimer::singleShot(int(std::lround(options.quitAfterSeconds * 1000)), qApp, &QCoreApplication::quit);
}

}  // namespace f2::viewer
