#pragma once
/// Applying a write-back (write_back.h) in the window: its edits as one undo
/// step, or, when it is refused, the reason and its offer put to the user
/// (never a silent edit of a loop or an included file).
#include <QString>
#include <functional>

#include "write_back.h"

class QPlainTextEdit;
class QWidget;

namespace f2::viewer {

enum class WriteBackOutcome {
    Written,    ///< the edits are in the text
    Offered,    ///< refused; the user took the offer, which is in the text
    Declined,   ///< refused; the text is unchanged
    Unchanged,  ///< nothing to write: the text already says it
};

/// Asks whether to take a refused write-back's offer: `why` it was refused,
/// `offer` what the offer does.
using OfferQuestion = std::function<bool(const QString& why, const QString& offer)>;

/// Applies `write` to `editor` as one undo step (the offer only if `ask`
/// says yes) and selects the line written, as the capture commands do.
WriteBackOutcome applyWriteBack(QPlainTextEdit* editor, const WriteBack& write, const OfferQuestion& ask);

/// The window's question: a message box with the reason and the offer as its button.
OfferQuestion offerBox(QWidget* parent);

}  // namespace f2::viewer
