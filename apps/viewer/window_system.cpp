#include "window_system.h"

#include <QApplication>
#include <QFileInfo>
#include <QStringList>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace f2::viewer {

namespace {
[[noreturn]] void noDisplay(const QString& reason) {
    std::fprintf(stderr, "f2-viewer: cannot open a display (%s); use f2 render to render without one\n",
                 qPrintable(reason));
    std::fflush(stderr);
    // _Exit, not exit: this may run inside QGuiApplication's constructor.
    std::_Exit(kNoDisplayExit);
}

bool isSet(const QProcessEnvironment& env, const QString& name) { return !env.value(name).isEmpty(); }

/// Messages Qt gives while the application is constructed, held back until
/// it is known whether the platform plugin started.
struct StartMessage {
    QtMsgType type;
    QString text;
    QByteArray file, function, category;  // of its QMessageLogContext, which cannot be copied
    int line;
};
std::vector<StartMessage>* startMessages = nullptr;

void holdStartMessage(QtMsgType type, const QMessageLogContext& context, const QString& text) {
    if (type == QtFatalMsg) {
        // The platform plugin failed: the first thing Qt said is the cause
        // ("could not connect to display :97"); the fatal text itself is
        // about reinstalling the application.
        QString reason = startMessages->empty() ? text.section('\n', 0, 0) : startMessages->front().text;
        noDisplay(reason.trimmed());
    }
    startMessages->push_back({type, text, context.file, context.function, context.category, context.line});
}
}  // namespace

QString displayProblem(const QProcessEnvironment& env) {
    QStringList platforms;
    for (const QString& entry : env.value("QT_QPA_PLATFORM").split(';', Qt::SkipEmptyParts))
        platforms << entry.section(':', 0, 0).trimmed();  // "xcb:option=value" names xcb
    const bool fromDefault = platforms.isEmpty();
    if (fromDefault) platforms = {"xcb", "wayland"};  // what Qt tries on Linux desktops

    const bool x11 = isSet(env, "DISPLAY");
    const QString runtime = env.value("XDG_RUNTIME_DIR");
    const bool wayland = isSet(env, "WAYLAND_DISPLAY") || isSet(env, "WAYLAND_SOCKET") ||
                         (!runtime.isEmpty() && QFileInfo::exists(runtime + "/wayland-0"));
    QStringList missing;
    for (const QString& name : platforms) {
        if (name == "xcb") {
            if (x11) return {};
            if (!missing.contains("DISPLAY")) missing << "DISPLAY";
        } else if (name.startsWith("wayland")) {
            if (wayland) return {};
            if (!missing.contains("WAYLAND_DISPLAY")) missing << "WAYLAND_DISPLAY";
        } else {
            return {};  // offscreen, minimal, vnc, eglfs, an unknown name: Qt decides
        }
    }
    const QString unset = missing.size() == 1 ? missing.first() + " is not set"
                                              : "neither " + missing.join(" nor ") + " is set";
    return fromDefault ? unset : unset + " for QT_QPA_PLATFORM=" + env.value("QT_QPA_PLATFORM");
}

std::unique_ptr<QApplication> openWindowSystem(int& argc, char** argv) {
    if (const QString problem = displayProblem(QProcessEnvironment::systemEnvironment()); !problem.isEmpty())
        noDisplay(problem);
    std::vector<StartMessage> held;
    startMessages = &held;
    const QtMessageHandler previous = qInstallMessageHandler(holdStartMessage);
    auto app = std::make_unique<QApplication>(argc, argv);
    qInstallMessageHandler(previous);
    startMessages = nullptr;
    for (const StartMessage& m : held) {
        const auto chars = [](const QByteArray& a) { return a.isNull() ? nullptr : a.constData(); };
        const QMessageLogContext context(chars(m.file), m.line, chars(m.function), chars(m.category));
        qt_message_output(m.type, context, m.text);
    }
    return app;
}

}  // namespace f2::viewer
