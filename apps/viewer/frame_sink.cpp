#include "frame_sink.h"

#include <QDir>
#include <QFile>
#include <algorithm>

#include "io/png_writer.h"

namespace f2::viewer {

PngSequenceSink::PngSequenceSink(QString directory, QString stem)
    : directory_(std::move(directory)), stem_(std::move(stem)) {}

bool PngSequenceSink::begin(int, int, int, int frameCount, std::string& error) {
    digits_ = std::max(4, int(QString::number(std::max(0, frameCount - 1)).size()));
    if (!QDir().mkpath(directory_)) {
        error = QStringLiteral("cannot create folder %1").arg(directory_).toStdString();
        return false;
    }
    return true;
}

QString PngSequenceSink::fileName(int index) const {
    return QDir(directory_)
        .filePath(QStringLiteral("%1_%2.png").arg(stem_).arg(index, digits_, 10, QChar('0')));
}

bool PngSequenceSink::write(const Image& image, int index, std::string& error) {
    return writePng(image, QFile::encodeName(fileName(index)).toStdString(), error);
}

bool PngSequenceSink::finish(bool, std::string&) { return true; }  // frames written so far are kept

QString PngSequenceSink::destination() const { return QDir(directory_).filePath(stem_ + "_*.png"); }

}  // namespace f2::viewer
