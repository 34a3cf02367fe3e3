#pragma once
/// The dock beside the picture that holds the scene editor and its find bar.
/// It tells the window when the user's typing has paused (so parsing and the
/// autosave copy follow edits without running on every keystroke).
#include <QDockWidget>
#include <QTimer>

class QLineEdit;
class QLabel;

namespace f2::viewer {

class SceneEditor;

class EditorDock : public QDockWidget {
    Q_OBJECT
   public:
    explicit EditorDock(QWidget* parent = nullptr);

    SceneEditor* editor() const { return editor_; }
    QLineEdit* findField() const { return findField_; }

    /// Shows `text` as the file's content: not modified, undo history cleared,
    /// no textSettled.
    void setSceneText(const QString& text);
    bool isModified() const;
    void setModified(bool modified);

    /// Opens the find bar with the selection (if any) as the search.
    void showFind();
    /// Selects the next (or previous) match of the find field, wrapping round.
    /// Returns whether there is one.
    bool findNext(bool backward = false);
    /// Asks for a line number and goes there.
    void goToLineDialog();

    /// Typing pauses this long before the text is parsed and autosaved.
    static constexpr int kSettleMs = 150;

   signals:
    /// The user changed the text and then paused for kSettleMs.
    void textSettled();
    /// The text's modified state changed (the window's title shows it).
    void modificationChanged(bool modified);

   private:
    SceneEditor* editor_ = nullptr;
    QWidget* findBar_ = nullptr;
    QLineEdit* findField_ = nullptr;
    QLabel* findStatus_ = nullptr;
    QTimer settleTimer_;
    bool loading_ = false;
};

}  // namespace f2::viewer
