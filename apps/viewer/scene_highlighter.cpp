#include "scene_highlighter.h"

#include <QStringView>

#include "core/parse/language.h"
#include "core/parse/number.h"

namespace f2::viewer {

namespace {

bool isMode(QStringView word) { return modeFromWord(word.toString().toStdString()).has_value(); }

// The parser's own rule (a decimal number, even one too large for a float);
// it also lets documents be highlighted in several threads at once.
bool isNumber(QStringView word) {
    if (word.size() > 1 && word.endsWith(u's')) word.chop(1);  // a time in seconds, `2.5s` (SPEC 10.4)
    const NumberStatus status = parseNumber(word.toString().toStdString()).status;
    return status == NumberStatus::Ok || status == NumberStatus::OutOfRange;
}

bool isSpace(QChar c) { return c == u' ' || c == u'\t' || c == u'\r'; }

}  // namespace

SceneHighlighter::SceneHighlighter(QTextDocument* document) : QSyntaxHighlighter(document) {
    auto& command = formats_[int(Kind::Command)];
    command.setForeground(QColor(0x1f, 0x5f, 0xbf));
    command.setFontWeight(QFont::Bold);
    formats_[int(Kind::Number)].setForeground(QColor(0x9a, 0x4e, 0x00));
    formats_[int(Kind::Name)].setForeground(QColor(0x1a, 0x7a, 0x3a));
    formats_[int(Kind::Part)].setForeground(QColor(0x6a, 0x3d, 0x9a));
    auto& mode = formats_[int(Kind::Mode)];
    mode.setForeground(QColor(0xa0, 0x1c, 0x6c));
    mode.setFontItalic(true);
    formats_[int(Kind::Expression)].setForeground(QColor(0x00, 0x7a, 0x87));
    formats_[int(Kind::Text)].setForeground(QColor(0xb0, 0x30, 0x20));
    auto& comment = formats_[int(Kind::Comment)];
    comment.setForeground(QColor(0x80, 0x80, 0x80));
    comment.setFontItalic(true);
}

void SceneHighlighter::highlightBlock(const QString& text) {
    // Tokens as the lexer cuts them: spaces separate, `#` ends the line, and
    // brackets keep their spaces inside one argument (SPEC 9.4).
    const int n = int(text.size());
    int i = 0;
    bool first = true;
    while (i < n) {
        if (isSpace(text[i])) {
            ++i;
            continue;
        }
        if (text[i] == u'#') {
            setKind(i, n - i, Kind::Comment);
            return;
        }
        const int start = i;
        int depth = 0;
        bool quoted = false;  // a caption's text (SPEC 10.5): spaces and '#' inside, \" does not close it
        while (i < n && (quoted || depth > 0 || (!isSpace(text[i]) && text[i] != u'#'))) {
            if (quoted) {
                if (text[i] == u'\\' && i + 1 < n)
                    ++i;
                else if (text[i] == u'"')
                    quoted = false;
            } else if (text[i] == u'"') {
                quoted = true;
            } else if (text[i] == u'(' || text[i] == u'{') {
                ++depth;
            } else if ((text[i] == u')' || text[i] == u'}') && depth > 0) {
                --depth;
            }
            ++i;
        }
        if (first && text[start] == u'/')
            setKind(start, i - start, Kind::Command);
        else if (text[start] == u'"')
            setKind(start, i - start, Kind::Text);
        else
            highlightWord(text, start, i - start);
        first = false;
    }
}

void SceneHighlighter::highlightWord(const QString& text, int start, int length) {
    const QStringView word = QStringView(text).mid(start, length);
    if (word.startsWith(u'(')) {
        setKind(start, length, Kind::Expression);
    } else if (isNumber(word)) {
        setKind(start, length, Kind::Number);
    } else if (isMode(word)) {
        setKind(start, length, Kind::Mode);
    } else {
        // A name, maybe `name.part`, maybe with `{ … }` pieces inside.
        const qsizetype dot = word.indexOf(u'.');
        setKind(start, length, Kind::Name);
        if (dot > 0) setKind(start + int(dot) + 1, length - int(dot) - 1, Kind::Part);
        for (qsizetype open = word.indexOf(u'{'); open >= 0; open = word.indexOf(u'{', open + 1)) {
            const qsizetype close = word.indexOf(u'}', open);
            const int end = close < 0 ? length : int(close) + 1;
            setKind(start + int(open), end - int(open), Kind::Expression);
        }
    }
}

}  // namespace f2::viewer
