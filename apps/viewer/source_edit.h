#pragma once
/// The one way the studio changes the scene text: replace ranges of it.
/// Offsets are QString (UTF-16) indices into the editor's plain text, which
/// are also QTextCursor positions, so the same edits apply to a string in a
/// test and to the editor in the window. Plus how numbers are written back
/// (shortestNumber) and scrubbed (scrubNumber), and the scene text cut into
/// tokens with their offsets (scanSource).
#include <QString>
#include <QStringView>
#include <optional>
#include <vector>

class QPlainTextEdit;

namespace f2::viewer {

/// Replace [begin, end) of the text with `text` (begin == end: an insertion).
struct SpanEdit {
    qsizetype begin = 0;
    qsizetype end = 0;
    QString text;
    friend bool operator==(const SpanEdit&, const SpanEdit&) = default;
};

/// `text` with `edits` applied. Every edit's offsets are in the original
/// `text`; edits must not overlap (two insertions at one offset keep their order).
QString withEdits(const QString& text, std::vector<SpanEdit> edits);

/// The one edit that turns `before` into `after`: what lies between their
/// common start and common end.
SpanEdit changedSpan(const QString& before, const QString& after);

/// Applies `edits` (offsets as for withEdits, in the editor's current text)
/// to `editor` as one undo step, and selects `select` (offsets in the text
/// after the edits) when given.
void applySourceEdits(QPlainTextEdit* editor, std::vector<SpanEdit> edits,
                      std::optional<std::pair<qsizetype, qsizetype>> select = std::nullopt);

/// `value` as a person writes it. The rule: round to 6 significant digits and
/// to at most 6 decimals (what a float position or angle means; it drops the
/// 0.30000000000000004 and 1e-07 noise of float arithmetic), then the shortest
/// decimal that reads back as that, in fixed notation (never an exponent);
/// `-0` is written `0`. 1.25 → "1.25", 40 → "40", 0.1 + 0.2 → "0.3".
QString shortestNumber(double value);

/// The step a scrubbed number moves by: one unit of its last written digit
/// ("1.25" → 0.01, "40" → 1, "3." → 1, "2e3" → 1000).
double numberStep(QStringView number);
/// `number` moved by `steps` of numberStep(number), written with the same
/// count of decimals (so "1.25" + 5 steps is "1.30", which stays its width
/// while scrubbing); nothing if it is not a plain number.
std::optional<QString> scrubNumber(QStringView number, int steps);

/// A token of the scene text (the core lexer's cut: brackets and quotes keep
/// their spaces; a comment is no token), at [begin, end) of the whole text.
struct SourceToken {
    qsizetype begin = 0;
    qsizetype end = 0;
    QString text;
};

/// A line of the scene text with its tokens and the blocks it stands in.
struct SourceLine {
    qsizetype begin = 0;  ///< offset of its first character
    qsizetype end = 0;    ///< offset of its line end (or the end of the text)
    std::vector<SourceToken> tokens;
    /// Inside a `/repeat` loop: the index of the line of the outermost loop's
    /// `/end` (a line after it is read once); -1 outside loops. A loop without
    /// its `/end` runs to the end of the text (then the last line's index).
    int loopEnd = -1;
    int loopStart = -1;    ///< that loop's `/repeat` line, or -1
    bool inModel = false;  ///< inside a `/model` block
    /// The command word ("/key"), or empty.
    QStringView command() const { return tokens.empty() ? QStringView() : QStringView(tokens[0].text); }
};

/// Every line of `text` (split at '\n'; a '\r' before it is not part of the line's tokens).
std::vector<SourceLine> scanSource(const QString& text);

/// Inserting `written` as a line of its own after line `after` of `lines`
/// (scanSource(text)); -1: before the first. A text ending in a line end still does.
SpanEdit insertLineAfter(const QString& text, const std::vector<SourceLine>& lines, int after,
                         const QString& written);
/// Removing line `line` of `lines` with its line end.
SpanEdit removeLine(const QString& text, const std::vector<SourceLine>& lines, int line);

/// A token's value if it is a plain number (no expression, no suffix).
std::optional<double> plainNumber(QStringView token);

}  // namespace f2::viewer
