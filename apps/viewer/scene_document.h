#pragma once
/// The open scene: its file, the text being edited, the last scene that parsed
/// without errors and the diagnostics of the latest parse. The file and every
/// file it includes (SPEC 9.5) are watched. The text comes from
/// the file when it is opened or reloaded and from the editor while the user
/// types; edits are parsed on a worker thread (latest text wins), so typing
/// never waits for the parser.
#include <QDateTime>
#include <QFileSystemWatcher>
#include <QFutureWatcher>
#include <QObject>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QThreadPool>
#include <QTimer>
#include <memory>
#include <optional>
#include <vector>

#include "core/parse/parser.h"
#include "core/scene/scene_desc.h"
#include "scene_locations.h"

namespace f2::viewer {

class SceneDocument : public QObject {
    Q_OBJECT
   public:
    explicit SceneDocument(QObject* parent = nullptr);
    ~SceneDocument() override;

    /// The scene compiled into the binary (scenes/demo.f2), as untitled text.
    void loadDefault();
    /// An empty untitled scene.
    void loadEmpty();
    /// Opens and watches `path` and parses its text. If it cannot be read or
    /// has errors, the stage is empty and the diagnostics say why. Returns
    /// whether it parsed. A file of kBackgroundBytes or more is parsed on the
    /// worker instead (seconds for a 20 MB file): the stage is empty
    /// meanwhile, isOpening() is true, load returns true and sceneChanged or
    /// diagnosticsChanged follows.
    bool load(const QString& path);
    /// Reads the current file again and parses it (the default scene's text
    /// for an untitled document); a large file as load() does, keeping the
    /// current scene until the new one is ready.
    bool reload();
    /// The editor's text changed: parse it on the worker (the file is not read).
    void setText(const QString& text);
    /// The file was written with `text` (by the editor's save, or Save As to
    /// `path`): watch it as the file's content without reading it back.
    void markSaved(const QString& path, const QString& text);

    /// While set, a change of the file on disk is reported by fileChangedOnDisk
    /// instead of being reloaded (the editor holds unsaved text).
    void setHoldsUnsavedEdits(bool holds) { holdsUnsavedEdits_ = holds; }

    /// Empty for an untitled document (the default scene or a new one).
    QString path() const { return path_; }
    /// The files the latest parse read or tried, the scene file first; each
    /// is watched: a change of the scene file is read (or reported while there
    /// are unsaved edits), a change of an included one parses the text again.
    QStringList sources() const { return sources_; }
    QString displayName() const;
    /// The text last loaded or set.
    const QString& text() const { return text_; }
    /// The file's text as last read or saved.
    const QString& diskText() const { return diskText_; }
    /// The last scene without errors of this document (an empty stage if it
    /// never parsed).
    std::shared_ptr<const SceneDesc> scene() const { return scene_; }
    /// Where the objects of scene() are created (from the same parse).
    std::shared_ptr<const SceneLocations> locations() const { return locations_; }
    /// `FILE:LINE:COL: error: ...` lines of the latest parse (warnings included).
    QStringList diagnostics() const { return diagnostics_; }
    const std::vector<Diagnostic>& diagnosticList() const { return diagnosticList_; }
    bool hasErrors() const { return hasErrors_; }
    /// The file name the parser puts in diagnostics of this document's own text.
    std::string sourceName() const;
    /// A parse of edited text is running or waiting.
    bool isParsing() const { return parsing_; }
    /// A large file read by load() or reload() is being parsed.
    bool isOpening() const { return opening_; }

    /// How long to wait after a change on disk before reading: editors often
    /// write a file in several steps.
    static constexpr int kReloadDelayMs = 120;
    /// Files from this size on are parsed off the GUI thread (a 1 MB scene
    /// parses in about 0.1 s; smaller ones at once).
    static inline qint64 kBackgroundBytes = 1'000'000;

   signals:
    /// A new good scene replaced the current one. `newDocument` is true when it
    /// comes from another file than the previous good scene (reset the view),
    /// false for an edit of the same file (keep time and camera).
    void sceneChanged(bool newDocument);
    /// Diagnostics changed (errors appeared, changed or went away).
    void diagnosticsChanged();
    /// The document's text was replaced by a file's (open, reload): the editor shows it.
    void textLoaded(const QString& text);
    /// While there are unsaved edits, the file changed on disk to something
    /// other than what was last read or saved. The owner asks whether to reload().
    void fileChangedOnDisk();
    /// isOpening() changed.
    void openingChanged(bool opening);

   private:
    /// A parse and the object locations its symbol index gave.
    struct Parsed {
        ParseResult result;
        SceneLocations locations;
    };
    static Parsed parse(std::string_view text, const std::string& name);

    /// Modification time and size of a file (null time and -1 if missing).
    struct Stamp {
        QDateTime modified;
        qint64 size = -1;
        bool operator==(const Stamp&) const = default;
    };

    void startParse();
    void setOpening(bool opening);
    /// Parses the current text again (an included file changed).
    void reparse();
    void onParsed();
    void apply(Parsed parsed, bool newDocument);
    void setSources(const std::vector<std::string>& files);
    void stampSources();
    void watchSources();
    void unwatchAll();
    void onDirectoryChanged();
    void onSourcesChanged();
    /// The scene file changed on disk: reload it, or report it while there are
    /// unsaved edits. False if its text is what was last read or saved.
    bool checkDisk();
    std::optional<QString> readDisk() const;
    static Stamp stampOf(const QString& path);

    QString path_;            // file being shown/watched; empty = untitled
    QString text_;            // the text of the latest load or edit
    QString diskText_;        // the file's content as last read or saved
    QString goodPath_;        // document the current good scene came from
    quint64 documentId_ = 0;  // a new id per load of another document
    quint64 goodDocument_ = 0;
    std::shared_ptr<const SceneDesc> scene_;
    std::shared_ptr<const SceneLocations> locations_;
    QStringList diagnostics_;
    std::vector<Diagnostic> diagnosticList_;
    bool hasErrors_ = false;
    bool holdsUnsavedEdits_ = false;
    bool opening_ = false;  // the parse in flight is of a file just read

    // Parsing edits off the GUI thread: one parse in flight, the newest text waiting.
    // Not Qt's global pool: the GUI thread's own painting (QPainter scales
    // images there) would wait behind a parse of seconds.
    QThreadPool parsePool_;
    // A pointer: QFuture hands out copies of its result, and a large scene's copy takes seconds.
    QFutureWatcher<std::shared_ptr<Parsed>> parseWatcher_;
    bool parsing_ = false;
    bool textWaiting_ = false;
    quint64 parseDocument_ = 0;  // documentId_ of the parse in flight

    QFileSystemWatcher watcher_;
    QTimer reloadTimer_;
    QStringList sources_;           // files of the latest parse, watched
    QList<Stamp> sourceStamps_;     // parallel to sources_: as they were when read
    QSet<QString> changedSources_;  // reported by the watcher since the last check
};

}  // namespace f2::viewer
