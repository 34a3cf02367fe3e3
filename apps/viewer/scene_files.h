#pragma once
/// The scene file's commands and questions: New, Open (dialog, recent files,
/// drops), Open Default Scene, Reload, Save and Save As, the autosaved copy
/// offered back, and the questions about unsaved edits and a file changed on
/// disk. Keeps the editor's text, the document and the window's title in step.
#include <QMessageBox>
#include <QObject>
#include <QString>
#include <functional>

class QMainWindow;
class QMenu;

namespace f2::viewer {

class EditorDock;
class SceneDocument;

class SceneFiles : public QObject {
    Q_OBJECT
   public:
    /// Dialogs, messages and the title go to `window`.
    SceneFiles(QMainWindow* window, SceneDocument* document, EditorDock* editorDock);

    /// Opens a scene file (command line, dialog, recent files, drops), after
    /// asking about unsaved edits; offers back an autosaved copy of it.
    /// Returns false if the user cancelled.
    bool openFile(const QString& path);
    /// Asks for a scene file and opens it.
    void openDialog();
    /// Starts an empty untitled scene (after asking about unsaved edits).
    bool newFile();
    /// Opens the built-in default scene as untitled text.
    bool openDefaultScene();
    /// Reads the file again (after asking about unsaved edits).
    void reload();
    /// Writes the editor's text to the scene file (Save As for an untitled
    /// one), atomically. Returns whether it was written.
    bool saveScene();
    /// Asks for a file name and writes the editor's text there.
    bool saveSceneAs();
    /// Writes the editor's text to `path` atomically and makes it the document's file.
    bool writeScene(const QString& path);
    /// Offers back the autosaved copy of the open document, if there is one
    /// (opening a file does this; main() does it for the untitled start).
    void offerAutosave();
    /// True when there are no unsaved edits or the user saved or discarded them.
    bool maybeSave();
    /// False, with a status message, while the file's text is not in the editor yet.
    bool textIsReady();
    /// The window's title: the document's name, marked while modified.
    void updateTitle();

    /// File › Open Recent: filled from the settings, kept up to date.
    void setRecentMenu(QMenu* menu);
    static constexpr int kMaxRecentFiles = 8;

    /// The questions asked; tests answer them through setAsker().
    enum class Question {
        SaveChanges,        ///< Save / Discard / Cancel
        RestoreAutosave,    ///< Yes (restore the copy) / No (discard it)
        ReloadChangedFile,  ///< Yes (take the file on disk) / No (keep the editor's text)
    };
    using Asker = std::function<QMessageBox::StandardButton(Question, const QString& text)>;
    /// Replaces the message boxes (tests).
    void setAsker(Asker asker) { asker_ = std::move(asker); }

   private:
    QMessageBox::StandardButton ask(Question question, const QString& text);
    void onTextLoaded(const QString& text);
    void onTextSettled();
    void onFileChangedOnDisk();
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    QMainWindow* window_;
    SceneDocument* document_;
    EditorDock* editorDock_;
    QMenu* recentMenu_ = nullptr;
    QMetaObject::Connection deferredAutosaveOffer_;  // waits for a large file's text
    Asker asker_;
};

}  // namespace f2::viewer
