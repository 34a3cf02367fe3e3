#include "text_capture.h"

#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QStringList>
#include <QTextBlock>
#include <cmath>

#include "source_edit.h"

namespace f2::viewer {

namespace {

/// The arguments of a command line as the lexer cuts them (brackets keep
/// their spaces), and the comment with the spaces before it.
QStringList argumentsOf(const QString& line, QString* comment) {
    QStringList tokens;
    QString current;
    int depth = 0;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (depth == 0 && c == u'#') {
            if (comment) {
                qsizetype start = i;
                while (start > 0 && line[start - 1].isSpace()) --start;
                *comment = line.mid(start);
            }
            break;
        }
        if (depth == 0 && c.isSpace()) {
            if (!current.isEmpty()) tokens << current;
            current.clear();
            continue;
        }
        if (c == u'(' || c == u'{') ++depth;
        if ((c == u')' || c == u'}') && depth > 0) --depth;
        current += c;
    }
    if (!current.isEmpty()) tokens << current;
    return tokens;
}

QString poseText(const Pose& pose) {
    QStringList numbers;
    for (float v : {pose.position.x, pose.position.y, pose.position.z, pose.rotation.x, pose.rotation.y,
                    pose.rotation.z})
        numbers << formatNumber(v);
    return numbers.join(u' ');
}

}  // namespace

QString formatNumber(double value) {
    if (std::fabs(value) < 0.005) return QStringLiteral("0");  // no "-0"
    QString s = QString::number(value, 'f', 2);
    while (s.endsWith(u'0')) s.chop(1);
    if (s.endsWith(u'.')) s.chop(1);
    return s;
}

int cameraLine(const QString& text) {
    const QStringList lines = text.split(u'\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QStringList args = argumentsOf(lines[i], nullptr);
        if (!args.isEmpty() && args[0] == QStringLiteral("/camera")) return int(i) + 1;
    }
    return 0;
}

TextEdit cameraEdit(const QString& text, const CameraDesc& camera, const Pose& pose) {
    if (const int line = cameraLine(text)) {
        const QString written = text.section(u'\n', line - 1, line - 1);
        QString comment;
        const QStringList args = argumentsOf(written, &comment);
        if (args.size() >= 4) {
            const qsizetype indent = written.indexOf(u'/');
            return {line, true,
                    written.left(indent) + QStringList(args.mid(0, 4)).join(u' ') + u' ' + poseText(pose) +
                        comment};
        }
    }
    return {1, false,
            QStringLiteral("/camera %1 %2 %3 %4")
                .arg(camera.width)
                .arg(camera.height)
                .arg(formatNumber(camera.distance), poseText(pose))};
}

TextEdit keyEdit(const QString& text, const QString& target, int frame, const Pose& pose, int createdAt) {
    const QString line = QStringLiteral("/key %1 %2 %3").arg(frame).arg(target, poseText(pose));
    const QStringList lines = text.split(u'\n');
    int lastKey = 0;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QStringList args = argumentsOf(lines[i], nullptr);
        if (args.size() < 3 || args[0] != QStringLiteral("/key") || args[2] != target) continue;
        bool ok = false;
        if (args[1].toDouble(&ok) == frame && ok) return {int(i) + 1, true, line};
        lastKey = int(i) + 1;
    }
    if (lastKey > 0) return {lastKey + 1, false, line};
    if (createdAt > 0 && createdAt <= lines.size()) return {createdAt + 1, false, line};
    // At the end, on a line of its own.
    const int end = int(lines.size()) + (lines.last().isEmpty() ? 0 : 1);
    return {end, false, line};
}

QString withEdit(const QString& text, const TextEdit& edit) {
    QStringList lines = text.split(u'\n');
    if (edit.line > lines.size()) {
        // Past the last line: a new one (the last line is empty after a final '\n').
        if (lines.last().isEmpty())
            lines.last() = edit.text;
        else
            lines << edit.text;
    } else if (edit.replace) {
        lines[edit.line - 1] = edit.text;
    } else {
        lines.insert(edit.line - 1, edit.text);
    }
    return lines.join(u'\n');
}

void applyEdit(QPlainTextEdit* editor, const TextEdit& edit) { applyEdits(editor, {edit}); }

void applyEdits(QPlainTextEdit* editor, const std::vector<TextEdit>& edits) {
    if (edits.empty()) return;
    // The line edits as the one span of text they change (source_edit.h).
    const QString before = editor->toPlainText();
    QString after = before;
    for (const TextEdit& edit : edits) after = withEdit(after, edit);
    applySourceEdits(editor, {changedSpan(before, after)});
    QTextCursor select(editor->document()->findBlockByNumber(edits.back().line - 1));
    select.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
    editor->setTextCursor(select);
    editor->centerCursor();
}

}  // namespace f2::viewer
