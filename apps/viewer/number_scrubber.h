#pragma once
/// Number scrubbing in the scene editor: Ctrl+drag sideways on a number (or
/// Alt+wheel over it) moves it in steps of its last written digit
/// (source_edit.h's scrubNumber: 1.25 by 0.01, 40 by 1), keeping its count of
/// decimals. A drag is one undo step, and so is a run of wheel turns on one
/// number; Esc during a drag puts the number back. Every change asks for the
/// picture at once (scrubbed), without waiting for typing to pause.
#include <QElapsedTimer>
#include <QObject>
#include <QPoint>
#include <QString>
#include <optional>

class QPlainTextEdit;

namespace f2::viewer {

class NumberScrubber : public QObject {
    Q_OBJECT
   public:
    /// Scrubs numbers of `editor` (installs itself on it and its viewport).
    explicit NumberScrubber(QPlainTextEdit* editor);

    /// Pixels of a drag per step.
    static constexpr int kPixelsPerStep = 6;
    /// Wheel turns on one number this close together (ms) make one undo step.
    static constexpr int kWheelJoinMs = 1000;
    /// A drag is under way.
    bool isScrubbing() const { return drag_.has_value(); }

   signals:
    /// A number changed: the text is worth parsing now.
    void scrubbed();

   protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

   private:
    /// A number of the text: where it is and what it was when the gesture began.
    struct Number {
        int begin = 0;
        int length = 0;
        QString original;
    };
    /// The plain number at document position `position`, if any.
    std::optional<Number> numberAt(int position) const;
    /// Writes `number` moved by `steps`; `join` adds the change to the previous undo step.
    void write(Number& number, int steps, bool join);

    QPlainTextEdit* editor_;
    struct Drag {
        Number number;
        int startX = 0;
        int steps = 0;
        bool written = false;
    };
    std::optional<Drag> drag_;
    // The number Alt+wheel turns: joined while the turns keep coming.
    std::optional<Number> wheel_;
    int wheelSteps_ = 0;
    QElapsedTimer wheelClock_;
};

}  // namespace f2::viewer
