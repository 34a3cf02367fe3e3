#include "number_scrubber.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QTextBlock>
#include <QWheelEvent>

#include "source_edit.h"

namespace f2::viewer {

NumberScrubber::NumberScrubber(QPlainTextEdit* editor) : QObject(editor), editor_(editor) {
    editor->installEventFilter(this);
    editor->viewport()->installEventFilter(this);
}

std::optional<NumberScrubber::Number> NumberScrubber::numberAt(int position) const {
    const QTextBlock block = editor_->document()->findBlock(position);
    if (!block.isValid()) return std::nullopt;
    const int column = position - block.position();
    const std::vector<SourceLine> line = scanSource(block.text());
    for (const SourceToken& token : line.front().tokens) {
        if (column < token.begin || column > token.end) continue;
        if (!plainNumber(token.text)) return std::nullopt;
        return Number{block.position() + int(token.begin), int(token.text.size()), token.text};
    }
    return std::nullopt;
}

void NumberScrubber::write(Number& number, int steps, bool join) {
    const auto written = scrubNumber(number.original, steps);
    if (!written) return;
    QTextCursor cursor(editor_->document());
    if (join)
        cursor.joinPreviousEditBlock();
    else
        cursor.beginEditBlock();
    cursor.setPosition(number.begin);
    cursor.setPosition(number.begin + number.length, QTextCursor::KeepAnchor);
    cursor.insertText(*written);
    cursor.endEditBlock();
    number.length = int(written->size());
    // The number stays selected, so the user sees what moves.
    cursor.setPosition(number.begin);
    cursor.setPosition(number.begin + number.length, QTextCursor::KeepAnchor);
    editor_->setTextCursor(cursor);
    emit scrubbed();
}

bool NumberScrubber::eventFilter(QObject* watched, QEvent* event) {
    // Only input events touch the editor: others come while it is being destroyed too.
    switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseMove:
        case QEvent::MouseButtonRelease:
        case QEvent::ShortcutOverride:
        case QEvent::KeyPress:
        case QEvent::Wheel:
            if (editor_->isReadOnly()) return false;
            break;
        default:
            return false;
    }
    switch (event->type()) {
        case QEvent::MouseButtonPress: {
            auto* mouse = static_cast<QMouseEvent*>(event);
            if (watched != editor_->viewport() || mouse->button() != Qt::LeftButton ||
                !(mouse->modifiers() & Qt::ControlModifier))
                return false;
            const QPoint at = mouse->position().toPoint();
            const auto number = numberAt(editor_->cursorForPosition(at).position());
            if (!number) return false;
            drag_ = Drag{*number, at.x(), 0, false};
            return true;
        }
        case QEvent::MouseMove: {
            if (!drag_ || watched != editor_->viewport()) return false;
            const int steps =
                (static_cast<QMouseEvent*>(event)->position().toPoint().x() - drag_->startX) / kPixelsPerStep;
            if (steps != drag_->steps) {
                // The first change of a drag starts its undo step, the others join it.
                write(drag_->number, steps, drag_->written);
                drag_->steps = steps;
                drag_->written = true;
            }
            return true;
        }
        case QEvent::MouseButtonRelease:
            if (!drag_ || watched != editor_->viewport()) return false;
            drag_.reset();
            return true;
        case QEvent::ShortcutOverride:
        case QEvent::KeyPress: {
            auto* key = static_cast<QKeyEvent*>(event);
            if (!drag_ || key->key() != Qt::Key_Escape) return false;
            if (event->type() == QEvent::KeyPress) {
                if (drag_->written) write(drag_->number, 0, true);  // the number as it was
                drag_.reset();
            }
            event->accept();
            return true;
        }
        case QEvent::Wheel: {
            auto* wheel = static_cast<QWheelEvent*>(event);
            if (watched != editor_->viewport() || !(wheel->modifiers() & Qt::AltModifier)) return false;
            // With Alt some platforms turn the wheel sideways.
            const int delta =
                wheel->angleDelta().y() != 0 ? wheel->angleDelta().y() : wheel->angleDelta().x();
            const auto number = numberAt(editor_->cursorForPosition(wheel->position().toPoint()).position());
            if (!number || delta == 0) return false;
            const bool join = wheel_ && wheel_->begin == number->begin && wheelClock_.isValid() &&
                              wheelClock_.elapsed() < kWheelJoinMs;
            if (!join) {
                wheel_ = *number;
                wheelSteps_ = 0;
            }
            wheelSteps_ += delta > 0 ? 1 : -1;
            write(*wheel_, wheelSteps_, join);
            wheelClock_.start();
            return true;
        }
        default:
            return false;
    }
}

}  // namespace f2::viewer
