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
    sources_.clear();
    sourceStamps_.clear();
    parseCurrent();
}

bool SceneDocument::load(const QString& path) {
    path_ = path;
    sources_ = {path};
    watchSources();
    return parseCurrent();
}

bool SceneDocument::reload() { return parseCurrent(); }

bool SceneDocument::parseCurrent() {
    ParseResult result;
    if (path_.isEmpty()) {
        result = parseScene(defaultSceneText(), kDefaultSceneName);
    } else {
        // Stamped before reading: a change made while parsing triggers another reload.
        QList<Stamp> before;
        for (const QString& source : sources_) before << stampOf(source);
        result = parseSceneFile(QFile::encodeName(path_).toStdString());
        QStringList files;
        for (const std::string& f : result.files) files << QFile::decodeName(QByteArray::fromStdString(f));
        if (files.isEmpty()) files << path_;
        if (files != sources_) {
            sources_ = files;
            before.clear();
            for (const QString& source : sources_) before << stampOf(source);
        }
        sourceStamps_ = before;
        watchSources();
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

void SceneDocument::watchSources() {
    // Editors often save by writing a new file and renaming it over the old
    // one; the watcher then loses the path. Watching the directories too lets
    // us notice a file coming back (or an included file being created) and
    // watch it again. Files no longer read are no longer watched.
    QStringList files, directories;
    for (const QString& source : sources_) {
        const QFileInfo info(source);
        if (!directories.contains(info.absolutePath())) directories << info.absolutePath();
        if (info.exists() && !files.contains(source)) files << source;
    }
    for (const QString& f : watcher_.files()) {
        if (!files.contains(f)) watcher_.removePath(f);
    }
    for (const QString& d : watcher_.directories()) {
        if (!directories.contains(d)) watcher_.removePath(d);
    }
    for (const QString& d : directories) {
        if (!watcher_.directories().contains(d)) watcher_.addPath(d);
    }
    for (const QString& f : files) {
        if (!watcher_.files().contains(f)) watcher_.addPath(f);
    }
}

void SceneDocument::onFileChanged() {
    watchSources();
    reloadTimer_.start();
}

void SceneDocument::onDirectoryChanged() {
    if (path_.isEmpty()) return;
    // Something in a folder changed; reload only if one of our files did, so
    // that exporting PNGs next to the scene does not reparse it.
    bool changed = false;
    for (qsizetype i = 0; i < sources_.size() && !changed; ++i) {
        changed = i >= sourceStamps_.size() || stampOf(sources_[i]) != sourceStamps_[i];
    }
    if (!changed) return;
    watchSources();
    reloadTimer_.start();
}

SceneDocument::Stamp SceneDocument::stampOf(const QString& path) {
    const QFileInfo info(path);
    return info.exists() ? Stamp{info.lastModified(), info.size()} : Stamp{};
}

}  // namespace f2::viewer
