#include "scene_document.h"

#include <QFile>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

#include "core/parse/symbol_index.h"
#include "core/scene/default_scene.h"

namespace f2::viewer {

namespace {

/// The editor's view of a file's bytes: UTF-8 without a byte order mark, lines
/// ending in `\n` (the parser accepts both; the editor writes `\n`).
QString editorText(const QByteArray& bytes) {
    QString text = QString::fromUtf8(bytes);
    if (text.startsWith(QChar(0xFEFF))) text.remove(0, 1);
    text.replace(QStringLiteral("\r\n"), QStringLiteral("\n"));
    return text;
}

}  // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {
    scene_ = std::make_shared<const SceneDesc>();
    locations_ = std::make_shared<const SceneLocations>();
    reloadTimer_.setSingleShot(true);
    reloadTimer_.setInterval(kReloadDelayMs);
    connect(&reloadTimer_, &QTimer::timeout, this, &SceneDocument::onSourcesChanged);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, [this](const QString& file) {
        changedSources_.insert(file);
        reloadTimer_.start();
    });
    connect(&watcher_, &QFileSystemWatcher::directoryChanged, this, &SceneDocument::onDirectoryChanged);
    connect(&parseWatcher_, &QFutureWatcher<std::shared_ptr<Parsed>>::finished, this,
            &SceneDocument::onParsed);
}

SceneDocument::Parsed SceneDocument::parse(std::string_view text, const std::string& name) {
    SymbolIndex index;
    Parsed parsed;
    parsed.result = parseScene(text, name, ParseLimits{}, index);
    parsed.locations = SceneLocations::fromIndex(index);
    return parsed;
}

SceneDocument::~SceneDocument() { parseWatcher_.waitForFinished(); }

QString SceneDocument::displayName() const {
    if (!path_.isEmpty()) return QFileInfo(path_).fileName();
    if (text_.isEmpty() && diskText_.isEmpty()) return tr("untitled.f2");
    return QString::fromUtf8(kDefaultSceneName.data(), qsizetype(kDefaultSceneName.size()));
}

std::string SceneDocument::sourceName() const {
    return path_.isEmpty() ? std::string(kDefaultSceneName) : QFile::encodeName(path_).toStdString();
}

void SceneDocument::unwatchAll() {
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    if (!watcher_.directories().isEmpty()) watcher_.removePaths(watcher_.directories());
    sources_.clear();
    sourceStamps_.clear();
    changedSources_.clear();
}

void SceneDocument::loadDefault() {
    unwatchAll();
    path_.clear();
    ++documentId_;
    diskText_ = QString::fromUtf8(defaultSceneText().data(), qsizetype(defaultSceneText().size()));
    text_ = diskText_;
    emit textLoaded(text_);
    apply(parse(defaultSceneText(), std::string(kDefaultSceneName)), true);
}

void SceneDocument::loadEmpty() {
    unwatchAll();
    path_.clear();
    ++documentId_;
    diskText_.clear();
    text_.clear();
    emit textLoaded(text_);
    apply(parse("", sourceName()), true);
}

std::optional<QString> SceneDocument::readDisk() const {
    QFile file(path_);
    if (!QFileInfo(path_).isFile() || !file.open(QIODevice::ReadOnly)) return std::nullopt;
    return editorText(file.readAll());
}

bool SceneDocument::load(const QString& path) {
    unwatchAll();
    path_ = path;
    ++documentId_;
    sources_ = {path};
    return reload();
}

bool SceneDocument::reload() {
    if (path_.isEmpty()) {
        if (diskText_.isEmpty()) {
            loadEmpty();
        } else {
            loadDefault();
        }
        return !hasErrors_;
    }
    stampSources();  // before reading: a change made meanwhile is seen again
    const bool newDocument = goodDocument_ != documentId_;
    const std::optional<QString> disk = readDisk();
    if (!disk) {
        // Nothing to edit; the parser words the file's problem (FILE:1:1: error: ...).
        diskText_.clear();
        text_.clear();
        emit textLoaded(text_);
        apply({parseSceneFile(sourceName()), {}}, newDocument);
        return false;
    }
    diskText_ = *disk;
    text_ = *disk;
    emit textLoaded(text_);
    if (QFileInfo(path_).size() < kBackgroundBytes) {
        apply(parse(text_.toStdString(), sourceName()), newDocument);
        return !hasErrors_;
    }
    if (newDocument) {
        // Not the previous file's scene beside this file's text while it parses.
        scene_ = std::make_shared<const SceneDesc>();
        locations_ = std::make_shared<const SceneLocations>();
        emit sceneChanged(true);
    }
    startParse();
    setOpening(true);
    return true;
}

void SceneDocument::setOpening(bool opening) {
    if (opening == opening_) return;
    opening_ = opening;
    emit openingChanged(opening);
}

void SceneDocument::setText(const QString& text) {
    if (text == text_) return;
    text_ = text;
    if (parsing_) {
        textWaiting_ = true;  // parsed when the one in flight finishes
        return;
    }
    startParse();
}

void SceneDocument::reparse() {
    if (parsing_)
        textWaiting_ = true;
    else
        startParse();
}

void SceneDocument::startParse() {
    stampSources();
    parsing_ = true;
    textWaiting_ = false;
    parseDocument_ = documentId_;
    parseWatcher_.setFuture(QtConcurrent::run(&parsePool_, [utf8 = text_.toStdString(), name = sourceName()] {
        return std::make_shared<Parsed>(parse(utf8, name));
    }));
}

void SceneDocument::onParsed() {
    Parsed result = std::move(*parseWatcher_.result());
    const bool current = parseDocument_ == documentId_;
    parsing_ = false;
    if (textWaiting_ && current) {
        startParse();  // newer text came in: this result is already stale
        return;
    }
    if (current) apply(std::move(result), goodDocument_ != documentId_);
}

void SceneDocument::markSaved(const QString& path, const QString& text) {
    if (path != path_) {
        unwatchAll();
        path_ = path;
        ++documentId_;
        goodDocument_ = documentId_;  // the same scene, now with a name: keep the view
    }
    diskText_ = text;
    if (sources_.isEmpty()) sources_ = {path_};
    sources_[0] = path_;
    stampSources();
    watchSources();
    if (text != text_) setText(text);
}

void SceneDocument::apply(Parsed parsed, bool newDocument) {
    ParseResult& result = parsed.result;
    QStringList lines;
    for (const Diagnostic& d : result.diagnostics) lines << QString::fromStdString(d.format());
    const bool errors = !result.ok();
    const bool diagnosticsDiffer = lines != diagnostics_ || errors != hasErrors_;
    diagnostics_ = lines;
    diagnosticList_ = std::move(result.diagnostics);
    hasErrors_ = errors;
    setSources(result.files);

    if (result.ok()) {
        scene_ = std::make_shared<const SceneDesc>(std::move(*result.scene));
        locations_ = std::make_shared<const SceneLocations>(std::move(parsed.locations));
        goodDocument_ = documentId_;
        emit sceneChanged(newDocument);
    } else if (newDocument) {
        // Another file that does not parse: an empty stage, not the previous
        // file's scene beside this file's text.
        scene_ = std::make_shared<const SceneDesc>();
        locations_ = std::make_shared<const SceneLocations>();
        goodDocument_ = documentId_;
        emit sceneChanged(true);
    }
    if (diagnosticsDiffer) emit diagnosticsChanged();
    setOpening(false);  // whatever was opening, this is the current text's scene
}

void SceneDocument::setSources(const std::vector<std::string>& files) {
    if (path_.isEmpty()) return;  // untitled text includes relative to the working folder, unwatched
    QStringList list;
    for (const std::string& f : files) list << QFile::decodeName(QByteArray::fromStdString(f));
    if (list.isEmpty() || list.front() != path_) list.prepend(path_);
    if (list != sources_) {
        sources_ = list;
        stampSources();
    }
    watchSources();
}

void SceneDocument::stampSources() {
    sourceStamps_.clear();
    for (const QString& source : sources_) sourceStamps_ << stampOf(source);
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
    for (const QString& f : watcher_.files())
        if (!files.contains(f)) watcher_.removePath(f);
    for (const QString& d : watcher_.directories())
        if (!directories.contains(d)) watcher_.removePath(d);
    for (const QString& d : directories)
        if (!watcher_.directories().contains(d)) watcher_.addPath(d);
    for (const QString& f : files)
        if (!watcher_.files().contains(f)) watcher_.addPath(f);
}

void SceneDocument::onDirectoryChanged() {
    // Something in a folder changed; look only if one of our files did, so
    // that exporting PNGs next to the scene does not reread it.
    for (qsizetype i = 0; i < sources_.size(); ++i)
        if (i >= sourceStamps_.size() || stampOf(sources_[i]) != sourceStamps_[i])
            changedSources_.insert(sources_[i]);
    if (!changedSources_.isEmpty()) reloadTimer_.start();
}

void SceneDocument::onSourcesChanged() {
    if (path_.isEmpty()) return;
    watchSources();
    const bool sceneFileChanged = changedSources_.contains(path_);
    const bool includeChanged = changedSources_.size() > (sceneFileChanged ? 1 : 0);
    changedSources_.clear();
    if (sceneFileChanged && checkDisk()) return;  // read again with its includes, or asked
    if (includeChanged) reparse();
}

bool SceneDocument::checkDisk() {
    const std::optional<QString> disk = readDisk();
    // A file that vanished is kept in the editor; our own save is no change.
    if (!disk || *disk == diskText_) return false;
    if (!holdsUnsavedEdits_) {
        reload();
        return true;
    }
    diskText_ = *disk;
    emit fileChangedOnDisk();
    return true;
}

SceneDocument::Stamp SceneDocument::stampOf(const QString& path) {
    const QFileInfo info(path);
    return info.exists() ? Stamp{info.lastModified(), info.size()} : Stamp{};
}

}  // namespace f2::viewer
