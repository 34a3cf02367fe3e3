#include "autosave.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QStandardPaths>

namespace f2::viewer {

namespace {
/// First line of a copy: which file it belongs to, for a person looking in the folder.
const QByteArray kHeader = "# f2-viewer autosave of: ";
}  // namespace

QString Autosave::directory() {
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
           QStringLiteral("/autosave");
}

QString Autosave::copyPath(const QString& scenePath) {
    const QByteArray key = scenePath.isEmpty() ? QByteArray("untitled") : scenePath.toUtf8();
    const QString hash = QString::fromLatin1(QCryptographicHash::hash(key, QCryptographicHash::Sha1).toHex());
    return directory() + QLatin1Char('/') + hash.left(16) + QStringLiteral(".f2");
}

bool Autosave::write(const QString& scenePath, const QString& text) {
    if (!QDir().mkpath(directory())) return false;
    QSaveFile file(copyPath(scenePath));  // temporary file + rename
    if (!file.open(QIODevice::WriteOnly)) return false;
    file.write(kHeader + (scenePath.isEmpty() ? QByteArray("(untitled)") : scenePath.toUtf8()) + '\n');
    file.write(text.toUtf8());
    return file.commit();
}

std::optional<QString> Autosave::read(const QString& scenePath) {
    QFile file(copyPath(scenePath));
    if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
    const QByteArray bytes = file.readAll();
    const qsizetype eol = bytes.indexOf('\n');
    if (!bytes.startsWith(kHeader) || eol < 0) return std::nullopt;
    return QString::fromUtf8(bytes.mid(eol + 1));
}

void Autosave::remove(const QString& scenePath) { QFile::remove(copyPath(scenePath)); }

}  // namespace f2::viewer
