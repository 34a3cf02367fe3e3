#pragma once
/// Colours scene text as the language reads it (SPEC 7 and 9): commands,
/// numbers, names and `name.part` targets, interpolation modes, `( … )`
/// expressions and `{ … }` in names, and `#` comments. Line by line, like the
/// language, so typing rehighlights only the line that changed.
#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace f2::viewer {

class SceneHighlighter : public QSyntaxHighlighter {
    Q_OBJECT
   public:
    explicit SceneHighlighter(QTextDocument* document);

    /// What a span of text is, for the colours and for tests.
    enum class Kind { Command, Number, Name, Part, Mode, Expression, Comment, Text, Count };
    const QTextCharFormat& format(Kind kind) const { return formats_[int(kind)]; }

   protected:
    void highlightBlock(const QString& text) override;

   private:
    void setKind(int start, int length, Kind kind) { setFormat(start, length, format(kind)); }
    void highlightWord(const QString& text, int start, int length);

    QTextCharFormat formats_[int(Kind::Count)];
};

}  // namespace f2::viewer
