#pragma once
/// The dock beside the picture that holds the scene editor and its find bar.
/// It tells the window when the user's typing has paused (so parsing and the
/// autosave copy follow edits without running on every keystroke).
#include <QDockWidget>
#include <QFutureWatcher>
#include <QList>
#include <QThreadPool>
#include <QTimer>

class QLineEdit;
class QLabel;
class QTextDocument;

namespace f2::viewer {

class NumberScrubber;
class SceneEditor;

class EditorDock : public QDockWidget {
    Q_OBJECT
   public:
    explicit EditorDock(QWidget* parent = nullptr);

    SceneEditor* editor() const { return editor_; }
    /// Ctrl+drag and Alt+wheel on the editor's numbers; each change is parsed at once.
    NumberScrubber* scrubber() const { return scrubber_; }
    QLineEdit* findField() const { return findField_; }

    /// Shows `text` as the file's content: not modified, undo history cleared,
    /// no textSettled. A text of kBackgroundChars or more is laid out and
    /// highlighted on a worker (seconds for a 20 MB file): meanwhile the editor
    /// is empty and read-only, isLoading() is true, and textShown() follows.
    void setSceneText(const QString& text);
    /// A text given to setSceneText is still being laid out.
    bool isLoading() const { return waitingForLayout_; }
    /// Layouts still on the worker, the latest text's or older ones that will be dropped.
    bool hasLayoutsInFlight() const { return !layouts_.isEmpty(); }
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
    /// Texts from this size on are laid out off the GUI thread (a 1 MB text
    /// takes about 0.3 s; smaller ones are shown at once).
    static inline qsizetype kBackgroundChars = 1'000'000;

    ~EditorDock() override;

   signals:
    /// The user changed the text and then paused for kSettleMs.
    void textSettled();
    /// The text's modified state changed (the window's title shows it).
    void modificationChanged(bool modified);
    /// The text of the latest setSceneText is in the editor.
    void textShown();
    /// isLoading() changed.
    void loadingChanged(bool loading);

   private:
    SceneEditor* editor_ = nullptr;
    NumberScrubber* scrubber_ = nullptr;
    QWidget* findBar_ = nullptr;
    QLineEdit* findField_ = nullptr;
    QLabel* findStatus_ = nullptr;
    void showDocument(QTextDocument* document, quint64 generation);

    QTimer settleTimer_;
    bool loading_ = false;           // the editor's text is being replaced: not the user's edit
    quint64 generation_ = 0;         // one per setSceneText: an older layout is dropped
    bool waitingForLayout_ = false;  // the latest text is being laid out on the worker
    QList<QFutureWatcher<QTextDocument*>*> layouts_;  // in flight, waited for on destruction
    // Not Qt's global pool: the GUI thread's own painting (QPainter scales
    // images there) would wait behind a layout of seconds.
    QThreadPool layoutPool_;
};

}  // namespace f2::viewer
