#pragma once
/// Room for the status bar's messages. A QStatusBar draws a message only in
/// the space its permanent widgets leave, so a message that names a pick or
/// an error was cut off behind the frame, timing and size readouts. While a
/// message shows, the readouts that yield are hidden, as many as the message
/// needs (in the order given), and the whole message is the bar's tooltip.
#include <QList>
#include <QObject>
#include <QPointer>

class QStatusBar;
class QWidget;

namespace f2::viewer {

class StatusBarRoom : public QObject {
    Q_OBJECT
   public:
    /// `yielding`: permanent widgets of `bar` that may hide for a message, the first first.
    StatusBarRoom(QStatusBar* bar, QList<QWidget*> yielding);

    /// Hides the yielding widgets the current message needs the room of, shows the others.
    void fit();

   protected:
    /// Fits again when the bar changes width.
    bool eventFilter(QObject* watched, QEvent* event) override;

   private:
    QStatusBar* bar_;
    QList<QPointer<QWidget>> yielding_;
};

}  // namespace f2::viewer
