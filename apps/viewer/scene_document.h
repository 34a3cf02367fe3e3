#pragma once
/// The open scene: loads and parses it, watches the file and every file it
/// includes (SPEC 9.5), keeps the last scene that parsed without errors and
/// the diagnostics of the latest attempt. The viewer only ever reads the user's files.
#include <QDateTime>
#include <QFileSystemWatcher>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <memory>

#include "core/scene/scene_desc.h"

namespace f2::viewer {

class SceneDocument : public QObject {
    Q_OBJECT
   public:
    explicit SceneDocument(QObject* parent = nullptr);

    /// The scene compiled into the binary (scenes/demo.f2).
    void loadDefault();
    /// Opens and watches `path`. If it has errors, the last good scene stays
    /// current and the diagnostics say why. Returns whether it parsed.
    bool load(const QString& path);
    /// Parses the current file (or the default scene) again.
    bool reload();

    /// Empty for the embedded default scene.
    QString path() const { return path_; }
    /// The files the latest parse read or tried, the scene file first; each
    /// is watched, so editing an included file reloads the scene.
    QStringList sources() const { return sources_; }
    QString displayName() const;
    /// The last scene without errors; null only if nothing has parsed yet.
    std::shared_ptr<const SceneDesc> scene() const { return scene_; }
    /// `FILE:LINE:COL: error: ...` lines of the latest parse (warnings included).
    QStringList diagnostics() const { return diagnostics_; }
    bool hasErrors() const { return hasErrors_; }

    /// How long to wait after a change before reading: editors often write a
    /// file in several steps.
    static constexpr int kReloadDelayMs = 120;

   signals:
    /// A new good scene replaced the current one. `newDocument` is true when it
    /// comes from another file than the previous good scene (reset the view),
    /// false for an edit of the same file (keep time and camera).
    void sceneChanged(bool newDocument);
    /// Diagnostics changed (errors appeared, changed or went away).
    void diagnosticsChanged();

   private:
    /// Modification time and size of a file (null time and -1 if missing).
    struct Stamp {
        QDateTime modified;
        qint64 size = -1;
        bool operator==(const Stamp&) const = default;
    };

    bool parseCurrent();
    void watchSources();
    void onFileChanged();
    void onDirectoryChanged();
    static Stamp stampOf(const QString& path);

    QString path_;      // file being shown/watched; empty = default scene
    QString goodPath_;  // file the current good scene came from
    bool goodIsSet_ = false;
    std::shared_ptr<const SceneDesc> scene_;
    QStringList diagnostics_;
    bool hasErrors_ = false;
    QFileSystemWatcher watcher_;
    QTimer reloadTimer_;
    QStringList sources_;          // files of the latest parse, watched
    QList<Stamp> sourceStamps_;    // parallel to sources_: as they were when parsed
};

}  // namespace f2::viewer
