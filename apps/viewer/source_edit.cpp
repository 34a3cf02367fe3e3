#include "source_edit.h"

#include <QPlainTextEdit>
#include <QTextBlock>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "core/parse/lexer.h"
#include "core/parse/number.h"

namespace f2::viewer {

namespace {

/// Later edits first, so each one's offsets still hold when it is applied;
/// at one offset the one given first stays first in the text.
std::vector<SpanEdit> backToFront(std::vector<SpanEdit> edits) {
    std::stable_sort(edits.begin(), edits.end(),
                     [](const SpanEdit& a, const SpanEdit& b) { return a.begin > b.begin; });
    // stable_sort keeps insertions at one offset in their given order; applied
    // back to front that would reverse them, so reverse each run of equal begins.
    for (auto run = edits.begin(); run != edits.end();) {
        auto next = std::find_if(run, edits.end(), [&](const SpanEdit& e) { return e.begin != run->begin; });
        std::reverse(run, next);
        run = next;
    }
    return edits;
}

double fromChars(const char* first, const char* last) {
    double value = 0;
    std::from_chars(first, last, value);
    return value;
}

}  // namespace

QString withEdits(const QString& text, std::vector<SpanEdit> edits) {
    QString out = text;
    for (const SpanEdit& edit : backToFront(std::move(edits)))
        out.replace(edit.begin, edit.end - edit.begin, edit.text);
    return out;
}

SpanEdit changedSpan(const QString& before, const QString& after) {
    const qsizetype shorter = std::min(before.size(), after.size());
    qsizetype prefix = 0;
    while (prefix < shorter && before[prefix] == after[prefix]) ++prefix;
    qsizetype suffix = 0;
    while (suffix < shorter - prefix &&
           before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix])
        ++suffix;
    return {prefix, before.size() - suffix, after.mid(prefix, after.size() - suffix - prefix)};
}

void applySourceEdits(QPlainTextEdit* editor, std::vector<SpanEdit> edits,
                      std::optional<std::pair<qsizetype, qsizetype>> select) {
    if (edits.empty()) return;
    QTextCursor cursor(editor->document());
    cursor.beginEditBlock();
    for (const SpanEdit& edit : backToFront(std::move(edits))) {
        cursor.setPosition(int(edit.begin));
        cursor.setPosition(int(edit.end), QTextCursor::KeepAnchor);
        cursor.insertText(edit.text);
    }
    cursor.endEditBlock();
    if (select) {
        QTextCursor selection(editor->document());
        selection.setPosition(int(select->first));
        selection.setPosition(int(select->second), QTextCursor::KeepAnchor);
        editor->setTextCursor(selection);
    }
}

QString shortestNumber(double value) {
    if (!std::isfinite(value)) return QStringLiteral("0");
    char buffer[400];
    // 6 significant digits...
    auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific, 5).ptr;
    double rounded = fromChars(buffer, end);
    // ...and at most 6 decimals.
    end = std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed, 6).ptr;
    rounded = fromChars(buffer, end);
    if (rounded == 0) return QStringLiteral("0");  // also -0
    end = std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed).ptr;
    return QString::fromLatin1(buffer, end - buffer);
}

namespace {

/// The parts of a plain number: decimals written and its exponent.
struct NumberShape {
    int decimals = 0;
    int exponent = 0;
    bool hasExponent = false;
};

std::optional<NumberShape> shapeOf(QStringView number) {
    if (!plainNumber(number)) return std::nullopt;
    NumberShape shape;
    qsizetype e = number.indexOf(u'e', 0, Qt::CaseInsensitive);
    const QStringView mantissa = e < 0 ? number : number.left(e);
    if (const qsizetype dot = mantissa.indexOf(u'.'); dot >= 0)
        shape.decimals = int(mantissa.size() - dot - 1);
    if (e >= 0) {
        shape.hasExponent = true;
        shape.exponent = number.mid(e + 1).toInt();
    }
    return shape;
}

}  // namespace

double numberStep(QStringView number) {
    const auto shape = shapeOf(number);
    if (!shape) return 1;
    return std::pow(10.0, shape->exponent - shape->decimals);
}

std::optional<QString> scrubNumber(QStringView number, int steps) {
    const auto shape = shapeOf(number);
    if (!shape) return std::nullopt;
    const double step = std::pow(10.0, shape->exponent - shape->decimals);
    // In whole steps from the written value, so repeated scrubs do not drift.
    const double value = std::round(*plainNumber(number) / step + steps) * step;
    if (shape->hasExponent || shape->exponent - shape->decimals > 0) return shortestNumber(value);
    QString written = QString::number(value, 'f', shape->decimals);
    if (std::fabs(value) < step / 2 && written.startsWith(u'-')) written.remove(0, 1);
    return written;
}

SpanEdit insertLineAfter(const QString& text, const std::vector<SourceLine>& lines, int after,
                         const QString& written) {
    const std::size_t next = std::size_t(after + 1);
    if (next < lines.size()) return {lines[next].begin, lines[next].begin, written + u'\n'};
    // After the empty line a final line end leaves: before it, so the text still ends with one.
    if (lines.size() > 1 && lines.back().begin == lines.back().end)
        return {lines.back().begin, lines.back().begin, written + u'\n'};
    return {text.size(), text.size(), u'\n' + written};
}

SpanEdit removeLine(const QString& text, const std::vector<SourceLine>& lines, int line) {
    const SourceLine& removed = lines[std::size_t(line)];
    if (std::size_t(line + 1) < lines.size()) return {removed.begin, lines[std::size_t(line + 1)].begin, {}};
    // The last line: with the line end before it.
    return {std::max<qsizetype>(0, removed.begin - 1), text.size(), {}};
}

std::optional<double> plainNumber(QStringView token) {
    if (token.isEmpty()) return std::nullopt;
    const QByteArray bytes = token.toUtf8();
    const ParsedNumber parsed = parseNumber(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    if (parsed.status != NumberStatus::Ok) return std::nullopt;
    return parsed.value;
}

std::vector<SourceLine> scanSource(const QString& text) {
    std::vector<SourceLine> lines;
    qsizetype start = 0;
    LineTokens tokens;
    std::string bytes;  // reused: one line's UTF-8
    while (true) {
        qsizetype end = text.indexOf(u'\n', start);
        const bool last = end < 0;
        if (last) end = text.size();
        SourceLine line;
        line.begin = start;
        line.end = end;
        QStringView view = QStringView(text).mid(start, end - start);
        if (view.endsWith(u'\r')) view.chop(1);
        // An ASCII line (nearly all of a scene) is its own UTF-8: bytes are UTF-16 offsets.
        bytes.clear();
        bool ascii = true;
        for (QChar c : view) {
            if (c.unicode() >= 0x80) {
                ascii = false;
                break;
            }
            bytes.push_back(char(c.unicode()));
        }
        if (!ascii) bytes = view.toUtf8().toStdString();
        tokenizeLine(bytes, tokens);
        const int stored = std::min(tokens.count, kMaxStoredTokens);
        line.tokens.reserve(std::size_t(stored));
        for (int i = 0; i < stored; ++i) {
            const Token& token = tokens.tokens[std::size_t(i)];
            // Byte columns to UTF-16 offsets: the length of the text before it.
            const qsizetype at =
                start + (ascii ? token.column - 1 : QString::fromUtf8(bytes.data(), token.column - 1).size());
            const QString written = ascii
                                        ? view.mid(at - start, qsizetype(token.text.size())).toString()
                                        : QString::fromUtf8(token.text.data(), qsizetype(token.text.size()));
            line.tokens.push_back({at, at + written.size(), written});
        }
        lines.push_back(std::move(line));
        if (last) break;
        start = end + 1;
    }
    // Blocks: /repeat and /model open one, /end closes the innermost.
    std::vector<std::pair<bool, int>> open;  // (is a loop, its first line)
    auto closeLoop = [&](int from, int to) {
        for (int i = from; i <= to; ++i) {
            lines[std::size_t(i)].loopEnd = to;
            lines[std::size_t(i)].loopStart = from;
        }
    };
    for (int i = 0; i < int(lines.size()); ++i) {
        SourceLine& line = lines[std::size_t(i)];
        line.inModel = std::any_of(open.begin(), open.end(), [](const auto& b) { return !b.first; });
        const QStringView command = line.command();
        if (command == u"/repeat" || command == u"/model") {
            open.emplace_back(command == u"/repeat", i);
        } else if (command == u"/end" && !open.empty()) {
            const auto [loop, from] = open.back();
            open.pop_back();
            const bool outermost =
                loop && std::none_of(open.begin(), open.end(), [](const auto& b) { return b.first; });
            if (outermost) closeLoop(from, i);
        }
    }
    // A loop without its /end: to the end of the text.
    for (const auto& [loop, from] : open) {
        if (loop) {
            closeLoop(from, int(lines.size()) - 1);
            break;
        }
    }
    return lines;
}

}  // namespace f2::viewer
