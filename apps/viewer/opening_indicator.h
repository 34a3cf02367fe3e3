#pragma once
/// The status bar's line while a large file opens: "Opening big.f2 (19.1 MB)…"
/// with a busy bar, from the moment the file is read until its scene is parsed
/// and its text is in the editor (both happen off the GUI thread), then
/// "Opened big.f2 in 2.4 s" as a message.
#include <QElapsedTimer>
#include <QWidget>

class QLabel;
class QStatusBar;

namespace f2::viewer {

class EditorDock;
class SceneDocument;

class OpeningIndicator : public QWidget {
    Q_OBJECT
   public:
    /// Adds itself to `bar` (hidden until a file opens in the background).
    OpeningIndicator(QStatusBar* bar, SceneDocument* document, EditorDock* editor);

    /// The scene is parsing or the text is being laid out.
    bool isBusy() const;
    /// What the line says ("" when hidden).
    QString text() const;

   signals:
    /// The scene and the text of the file are both ready.
    void opened();

   private:
    void update();

    QStatusBar* bar_;
    SceneDocument* document_;
    EditorDock* editor_;
    QLabel* label_;
    QElapsedTimer clock_;  // valid while busy
};

}  // namespace f2::viewer
