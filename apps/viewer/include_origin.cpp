#include "include_origin.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>

#include "core/parse/parser.h"
#include "core/parse/source_expander.h"

namespace f2::viewer {

namespace {

/// A command the language does not have, so no scene line can be one.
constexpr std::string_view kMarker = "/f2-viewer:include-marker";

/// Takes no errors (the scene parsed) and lets no argument be evaluated.
class QuietSink : public ExpansionSink {
   public:
    void expansionError(SourcePos, std::string) override {}
    bool knowsCommand(std::string_view) const override { return false; }
};

bool isInclude(const QString& line) {
    const QString command = line.trimmed().section(u' ', 0, 0).section(u'\t', 0, 0);
    return command == QStringLiteral("/include");
}

}  // namespace

int includingLine(const QString& mainText, const std::string& mainName, const SourceLoc& created,
                  int instance) {
    if (created.file == mainName) return 0;
    // The main text with "/f2-viewer:include-marker N" before the /include at line N.
    QStringList lines = mainText.split(u'\n');
    QStringList marked;
    marked.reserve(lines.size() * 2);
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (isInclude(lines[i]))
            marked << QStringLiteral("%1 %2")
                          .arg(QString::fromLatin1(kMarker.data(), kMarker.size()))
                          .arg(i + 1);
        marked << lines[i];
    }
    lines.clear();
    const std::string text = marked.join(u'\n').toStdString();
    marked.clear();

    // The parser's default limits (the scene on screen parsed within them).
    const ParseLimits limits;
    const ExpansionLimits expansion{limits.maxExpandedLines, limits.maxExpandedBytes, limits.maxLoopDepth,
                                    limits.maxIncludeDepth,  limits.maxLineBytes,     limits.maxSceneBytes};
    QuietSink sink;
    SourceExpander expander(expansion, sink);
    expander.start(text, mainName);
    // Lines are read in the parser's order: the marker read last before the
    // creating line is that of the main file's /include it is inside.
    LogicalLine line;
    int include = 0;
    int seen = 0;
    while (expander.next(line)) {
        if (line.count == 0) continue;
        if (line.pos.file == 0) {
            if (line.count >= 2 && line.tokens[0].text == kMarker)
                include = std::stoi(std::string(line.tokens[1].text));
            continue;
        }
        if (line.pos.line != created.line || expander.fileName(line.pos.file) != created.file) continue;
        if (seen++ == instance) return include;
    }
    return 0;
}

QString includedFileName(const std::string& file, const QString& scenePath) {
    const QString name = QFile::decodeName(QByteArray::fromStdString(file));
    const QString folder = scenePath.isEmpty() ? QDir::currentPath() : QFileInfo(scenePath).absolutePath();
    const QString relative = QDir(folder).relativeFilePath(QFileInfo(name).absoluteFilePath());
    return relative.startsWith(QStringLiteral("..")) ? name : relative;
}

}  // namespace f2::viewer
