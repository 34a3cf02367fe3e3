#include "scene_document.h"

#include <QFile>
#include <QFileInfo>

#include "core/parse/parser.h"
#include "core/scene/default_scene.h"

namespace f2::viewer {

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {
    reloadTimer_.setSingleShot(true);
    reloadTimer_.setInterval(kReloadDelayMs);
    connect(&reloadTimer_, &QTimer::timeout, this, &SceneDocument::reload);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, &SceneDocument::onFileChanged);
    connect(&watcher_, &QFileSystemWatcher::directoryChanged, this, &SceneDocument::onDirectoryChanged);
}

QString SceneDocument::displayName() const {
    return path_.isEmpty() ? QString::fromUtf8(kDefaultSceneName.data(), qsizetype(kDefaultSceneName.size()))
                           : QFileInfo(path_).fileName();
}

void SceneDocument::loadDefault() {
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    if (!watcher_.directories().isEmpty()) watcher_.removePaths(watcher_.directories());
    path_.clear();
    parseCurrent();
}

bool SceneDocument::load(const QString& path) {
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    if (!watcher_.directories().isEmpty()) watcher_.removePaths(watcher_.directories());
    path_ = path;
    watchCurrent();
    return parseCurrent();
}

bool SceneDocument::reload() {
    if (!path_.isEmpty()) watchCurrent();
    return parseCurrent();
}

bool SceneDocument::parseCurrent() {
    ParseResult result;
    if (path_.isEmpty()) {
        result = parseScene(defaultSceneText(), kDefaultSceneName);
    } else {
        lastStamp_ = currentStamp();
        const QFileInfo info(path_);
        lastSize_ = info.exists() ? info.size() : -1;
        result = parseSceneFile(QFile::encodeName(path_).toStdString());
    }

    QStringList lines;
    for (const Diagnostic& d : result.diagnostics) lines << QString::fromStdString(d.format());
    const bool errors = !result.ok();
    const bool diagnosticsDiffer = lines != diagnostics_ || errors != hasErrors_;
    diagnostics_ = lines;
    hasErrors_ = errors;

    if (result.ok()) {
        const bool newDocument = !goodIsSet_ || goodPath_ != path_;
        scene_ = std::make_shared<const SceneDesc>(std::move(*result.scene));
        goodPath_ = path_;
        goodIsSet_ = true;
        emit sceneChanged(newDocument);
    }
    if (diagnosticsDiffer) emit diagnosticsChanged();
    return result.ok();
}

void SceneDocument::watchCurrent() {
    // Editors often save by writing a new file and renaming it over the old
    // one; the watcher then loses the path. Watching the directory too lets us
    // notice the file coming back and watch it again.
    const QFileInfo info(path_);
    const QString dir = info.absolutePath();
    if (!watcher_.directories().contains(dir)) watcher_.addPath(dir);
    if (info.exists() && !watcher_.files().contains(path_)) watcher_.addPath(path_);
}

void SceneDocument::onFileChanged() {
    watchCurrent();
    reloadTimer_.start();
}

void SceneDocument::onDirectoryChanged() {
    if (path_.isEmpty()) return;
    // Something in the folder changed; reload only if our file did, so that
    // exporting PNGs next to the scene does not reparse it.
    const QFileInfo info(path_);
    if (currentStamp() == lastStamp_ && (info.exists() ? info.size() : -1) == lastSize_) return;
    watchCurrent();
    reloadTimer_.start();
}

QDateTime SceneDocument::currentStamp() const {
    const QFileInfo info(path_);
    return info.exists() ? info.lastModified() : QDateTime();
}

}  // namespace f2::viewer
