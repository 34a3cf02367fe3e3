#include "scene_editor.h"

#include <QFontDatabase>
#include <QHelpEvent>
#include <QPainter>
#include <QPlainTextDocumentLayout>
#include <QTextBlock>
#include <QThread>
#include <QToolTip>

#include "core/parse/diagnostic.h"
#include "scene_highlighter.h"

namespace f2::viewer {

namespace {
const QColor kCurrentLine(0xff, 0xf8, 0xd8);
const QColor kLineNumberBackground(0xf0, 0xf0, 0xf0);
const QColor kLineNumberText(0x90, 0x90, 0x90);
constexpr int kLineNumberMargin = 6;
}  // namespace

/// The gutter; it asks the editor to paint it.
class LineNumberArea : public QWidget {
   public:
    explicit LineNumberArea(SceneEditor* editor) : QWidget(editor), editor_(editor) {}
    QSize sizeHint() const override { return {editor_->lineNumberAreaWidth(), 0}; }

   protected:
    void paintEvent(QPaintEvent* event) override { editor_->paintLineNumbers(event); }

   private:
    SceneEditor* editor_;
};

int charIndexOfByteColumn(const QString& lineText, int byteColumn) {
    int bytes = 0;
    int i = 0;
    while (i < lineText.size() && bytes < byteColumn - 1) {
        const char32_t c = lineText[i].isHighSurrogate() && i + 1 < lineText.size()
                               ? QChar::surrogateToUcs4(lineText[i], lineText[i + 1])
                               : lineText[i].unicode();
        bytes += c < 0x80 ? 1 : c < 0x800 ? 2 : c < 0x10000 ? 3 : 4;
        i += c >= 0x10000 ? 2 : 1;
    }
    return i;
}

SceneEditor::SceneEditor(QWidget* parent) : QPlainTextEdit(parent) {
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setTabStopDistance(fontMetrics().horizontalAdvance(QLatin1Char(' ')) * 4);
    highlighter_ = new SceneHighlighter(document());
    lineNumbers_ = new LineNumberArea(this);
    connect(this, &QPlainTextEdit::blockCountChanged, this,
            [this] { setViewportMargins(lineNumberAreaWidth(), 0, 0, 0); });
    connect(this, &QPlainTextEdit::updateRequest, this, &SceneEditor::updateLineNumberArea);
    connect(this, &QPlainTextEdit::cursorPositionChanged, this, &SceneEditor::updateSelections);
    setViewportMargins(lineNumberAreaWidth(), 0, 0, 0);
    updateSelections();
}

QTextDocument* SceneEditor::makeDocument(const QString& text, const QFont& font, QThread* owner) {
    auto* document = new QTextDocument;
    document->setDefaultFont(font);
    document->setDocumentLayout(new QPlainTextDocumentLayout(document));
    // Attached before the text goes in, so each line is coloured as it is
    // added, in this thread (attached later, it would colour all of them at once
    // in the GUI thread).
    new SceneHighlighter(document);
    document->setUndoRedoEnabled(false);
    document->setPlainText(text);
    document->setUndoRedoEnabled(true);
    document->setModified(false);
    document->moveToThread(owner);  // its layout and highlighter are children: they go with it
    return document;
}

void SceneEditor::adoptDocument(QTextDocument* document) {
    QTextDocument* previous = this->document();
    // Asked before setDocument(): that deletes a previous document the text
    // control made itself (ASan: reading its parent afterwards was a use after free).
    const bool adoptedBefore = previous && previous != document && previous->parent() == this;
    document->setParent(this);
    setDocument(document);
    highlighter_ = document->findChild<SceneHighlighter*>();
    setTabStopDistance(fontMetrics().horizontalAdvance(QLatin1Char(' ')) * 4);
    if (adoptedBefore) delete previous;
    setViewportMargins(lineNumberAreaWidth(), 0, 0, 0);
    updateSelections();
}

int SceneEditor::lineNumberAreaWidth() const {
    int digits = 1;
    for (int n = std::max(1, blockCount()); n >= 10; n /= 10) ++digits;
    return 2 * kLineNumberMargin + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(3, digits);
}

void SceneEditor::updateLineNumberArea(const QRect& rect, int dy) {
    if (dy != 0)
        lineNumbers_->scroll(0, dy);
    else
        lineNumbers_->update(0, rect.y(), lineNumbers_->width(), rect.height());
}

void SceneEditor::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    const QRect r = contentsRect();
    lineNumbers_->setGeometry(QRect(r.left(), r.top(), lineNumberAreaWidth(), r.height()));
}

void SceneEditor::paintLineNumbers(QPaintEvent* event) {
    QPainter painter(lineNumbers_);
    painter.fillRect(event->rect(), kLineNumberBackground);
    const int current = textCursor().blockNumber();
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    while (block.isValid() && top <= event->rect().bottom()) {
        const int height = qRound(blockBoundingRect(block).height());
        if (block.isVisible() && top + height >= event->rect().top()) {
            QFont font = painter.font();
            font.setBold(block.blockNumber() == current);
            painter.setFont(font);
            painter.setPen(block.blockNumber() == current ? palette().text().color() : kLineNumberText);
            painter.drawText(0, top, lineNumbers_->width() - kLineNumberMargin, fontMetrics().height(),
                             Qt::AlignRight, QString::number(block.blockNumber() + 1));
        }
        block = block.next();
        top += height;
    }
}

std::pair<int, int> SceneEditor::problemRange(const EditorProblem& problem) const {
    const QTextBlock block = document()->findBlockByNumber(problem.line - 1);
    if (!block.isValid()) return {-1, 0};
    const QString text = block.text();
    // The language server's rule (core markedBytes), in the line's UTF-8 bytes.
    Diagnostic diagnostic;
    diagnostic.loc.column = problem.column;
    diagnostic.length = problem.length;
    const QByteArray utf8 = text.toUtf8();
    const ByteSpan span =
        markedBytes(diagnostic, std::string_view(utf8.constData(), std::size_t(utf8.size())));
    const int start = charIndexOfByteColumn(text, int(span.first) + 1);
    const int end = charIndexOfByteColumn(text, int(span.first + span.length) + 1);
    return {block.position() + start, end - start};
}

QString SceneEditor::problemAt(int pos) const {
    QStringList messages;
    for (const EditorProblem& p : problems_) {
        const auto [start, length] = problemRange(p);
        if (start >= 0 && pos >= start && pos < start + std::max(1, length)) messages << p.message;
    }
    return messages.join('\n');
}

void SceneEditor::setProblems(std::vector<EditorProblem> problems) {
    problems_ = std::move(problems);
    updateSelections();
}

void SceneEditor::updateSelections() {
    QList<QTextEdit::ExtraSelection> selections;
    QTextEdit::ExtraSelection line;
    line.format.setBackground(kCurrentLine);
    line.format.setProperty(QTextFormat::FullWidthSelection, true);
    line.cursor = textCursor();
    line.cursor.clearSelection();
    selections << line;
    for (const EditorProblem& p : problems_) {
        const auto [start, length] = problemRange(p);
        if (start < 0) continue;
        QTextEdit::ExtraSelection mark;
        mark.format.setUnderlineStyle(QTextCharFormat::SpellCheckUnderline);
        mark.format.setUnderlineColor(p.error ? Qt::red : QColor(0xd0, 0x90, 0x00));
        mark.format.setToolTip(p.message);
        mark.cursor = QTextCursor(document());
        mark.cursor.setPosition(start);
        mark.cursor.setPosition(start + length, QTextCursor::KeepAnchor);
        selections << mark;
    }
    setExtraSelections(selections);
    lineNumbers_->update();
}

bool SceneEditor::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QPoint inViewport = viewport()->mapFromGlobal(help->globalPos());
        const QString message = problemAt(cursorForPosition(inViewport).position());
        if (message.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), message, this);
        return true;
    }
    return QPlainTextEdit::event(event);
}

void SceneEditor::goTo(int line, int column) {
    const QTextBlock block = document()->findBlockByNumber(std::clamp(line, 1, blockCount()) - 1);
    QTextCursor cursor(block);
    cursor.setPosition(block.position() + charIndexOfByteColumn(block.text(), column));
    setTextCursor(cursor);
    centerCursor();
    setFocus();
}

void SceneEditor::toggleComment() {
    QTextCursor cursor = textCursor();
    const QTextBlock first = document()->findBlock(cursor.selectionStart());
    QTextBlock last = document()->findBlock(cursor.selectionEnd());
    // A selection ending at the start of a line does not take that line.
    if (cursor.hasSelection() && last != first && cursor.selectionEnd() == last.position())
        last = last.previous();

    bool allCommented = true;
    for (QTextBlock b = first; b.isValid(); b = b.next()) {
        const QString t = b.text().trimmed();
        if (!t.isEmpty() && !t.startsWith(u'#')) allCommented = false;
        if (b == last) break;
    }
    cursor.beginEditBlock();
    for (QTextBlock b = first; b.isValid(); b = b.next()) {
        const QString t = b.text();
        int indent = 0;
        while (indent < t.size() && t[indent].isSpace()) ++indent;
        QTextCursor edit(b);
        if (allCommented) {
            if (indent < t.size() && t[indent] == u'#') {
                edit.setPosition(b.position() + indent);
                const bool space = indent + 1 < t.size() && t[indent + 1] == u' ';
                edit.setPosition(b.position() + indent + (space ? 2 : 1), QTextCursor::KeepAnchor);
                edit.removeSelectedText();
            }
        } else if (!t.trimmed().isEmpty()) {
            edit.setPosition(b.position() + indent);
            edit.insertText(QStringLiteral("# "));
        }
        if (b == last) break;
    }
    cursor.endEditBlock();
}

}  // namespace f2::viewer
