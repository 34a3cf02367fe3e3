#include "write_back_prompt.h"

#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>

namespace f2::viewer {

WriteBackOutcome applyWriteBack(QPlainTextEdit* editor, const WriteBack& write, const OfferQuestion& ask) {
    if (!write.refused()) {
        if (write.edits.empty()) return WriteBackOutcome::Unchanged;
        applySourceEdits(editor, write.edits);
        return WriteBackOutcome::Written;
    }
    if (write.offer.empty() || !ask || !ask(write.refusal, write.offerLabel))
        return WriteBackOutcome::Declined;
    applySourceEdits(editor, write.offer);
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
