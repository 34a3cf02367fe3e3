#pragma once
/// Copies of unsaved editor text under the user's state directory
/// (QStandardPaths::AppLocalDataLocation/autosave), one per scene file, so a
/// crash loses nothing: the next time that file is opened its copy is offered
/// back. A saved or discarded edit removes the copy.
#include <QString>
#include <optional>

namespace f2::viewer {

class Autosave {
   public:
    /// The folder of the copies (created on first write).
    static QString directory();
    /// The copy for the scene at `scenePath` (empty: the untitled document).
    static QString copyPath(const QString& scenePath);

    /// Writes `text` as the copy of `scenePath`, atomically. Returns false on failure.
    static bool write(const QString& scenePath, const QString& text);
    /// The copy's text, if there is one.
    static std::optional<QString> read(const QString& scenePath);
    static void remove(const QString& scenePath);
};

}  // namespace f2::viewer
