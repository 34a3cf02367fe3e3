#include "write_back_prompt.h"

#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>

namespace f2::viewer {

namespace {

/// Applies `edits` (a write-back's: one line changed or inserted) and selects that line, as a capture does.
void applyAndSelect(QPlainTextEdit* editor, const std::vector<SpanEdit>& edits) {
    const SpanEdit& first = edits.front();
    const QString before = editor->toPlainText();
    // Its line in the text after the edits: the line ends before it, one more for an inserted "\n…".
    const int line =
        int(QStringView(before).left(first.begin).count(u'\n')) + (first.text.startsWith(u'\n') ? 1 : 0);
    applySourceEdits(editor, edits);
    QTextCursor select(editor->document()->findBlockByNumber(line));
    select.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
    editor->setTextCursor(select);
    editor->centerCursor();
}

}  // namespace

WriteBackOutcome applyWriteBack(QPlainTextEdit* editor, const WriteBack& write, const OfferQuestion& ask) {
    if (!write.refused()) {
        if (write.edits.empty()) return WriteBackOutcome::Unchanged;
        applyAndSelect(editor, write.edits);
        return WriteBackOutcome::Written;
    }
    if (write.offer.empty() || !ask || !ask(write.refusal, write.offerLabel))
        return WriteBackOutcome::Declined;
    applyAndSelect(editor, write.offer);
    return WriteBackOutcome::Offered;
}

OfferQuestion offerBox(QWidget* parent) {
    return [parent](const QString& why, const QString& offer) {
        QMessageBox box(QMessageBox::Question, QObject::tr("Not Written"), why, QMessageBox::Cancel, parent);
        QPushButton* take = box.addButton(offer, QMessageBox::AcceptRole);
        box.setDefaultButton(take);
        box.exec();
        return box.clickedButton() == take;
    };
}

}  // namespace f2::viewer
