#pragma once
/// The scene text editor: a QPlainTextEdit with the scene highlighter, line
/// numbers, the current line marked, problems underlined at their line and
/// column (the message as a tooltip), go to line and comment/uncomment.
#include <QPlainTextEdit>
#include <QString>
#include <vector>

class QThread;

namespace f2::viewer {

class SceneHighlighter;

/// One diagnostic placed in the editor's text.
struct EditorProblem {
    int line = 1;    ///< 1-based
    int column = 1;  ///< 1-based, in bytes of the UTF-8 line (as the parser counts)
    QString message;
    bool error = true;
    int length = 0;  ///< bytes it covers (Diagnostic::length; 0: the token there)
};

class SceneEditor : public QPlainTextEdit {
    Q_OBJECT
   public:
    explicit SceneEditor(QWidget* parent = nullptr);

    /// Underlines these (replacing the previous ones).
    void setProblems(std::vector<EditorProblem> problems);
    const std::vector<EditorProblem>& problems() const { return problems_; }
    /// The document range a problem underlines: from its column to the end of
    /// that token. {-1, 0} if the line does not exist.
    std::pair<int, int> problemRange(const EditorProblem& problem) const;
    /// The message of the problem under document position `pos`, if any.
    QString problemAt(int pos) const;

    /// Moves the cursor to `line`:`column` (1-based; the column in UTF-8 bytes)
    /// and shows it.
    void goTo(int line, int column = 1);
    /// Comments the selected lines out with `# `, or uncomments them if every
    /// non-blank one is a comment. One undo step.
    void toggleComment();

    /// Wide enough for a /camera line with its comment; the picture keeps the rest.
    QSize sizeHint() const override { return {kPreferredWidth, 400}; }
    static constexpr int kPreferredWidth = 440;

    SceneHighlighter* highlighter() const { return highlighter_; }

    /// A document of `text` as this editor shows it: laid out for plain text,
    /// in `font`, highlighted. Runs in any thread (a large file is laid out
    /// off the GUI thread) and hands the document to `owner`, the GUI thread.
    static QTextDocument* makeDocument(const QString& text, const QFont& font, QThread* owner);
    /// Shows `document` (from makeDocument) instead of the current one, which
    /// is deleted. Its undo history is empty and it is not modified.
    void adoptDocument(QTextDocument* document);
    int lineNumberAreaWidth() const;

   protected:
    void resizeEvent(QResizeEvent* event) override;
    bool event(QEvent* event) override;

   private:
    friend class LineNumberArea;
    void paintLineNumbers(QPaintEvent* event);
    void updateLineNumberArea(const QRect& rect, int dy);
    void updateSelections();

    QWidget* lineNumbers_ = nullptr;
    SceneHighlighter* highlighter_ = nullptr;
    std::vector<EditorProblem> problems_;
};

/// Index into `lineText` (UTF-16) of the 1-based UTF-8 byte column `byteColumn`.
int charIndexOfByteColumn(const QString& lineText, int byteColumn);

}  // namespace f2::viewer
