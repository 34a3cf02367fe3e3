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

VideoSink::VideoSink(QString path, Rgb8 padColor) : path_(std::move(path)), padColor_(padColor) {}

bool VideoSink::begin(int width, int height, int fps, int, std::string& error) {
    const std::string path = QFile::encodeName(path_).toStdString();
    const auto format = videoFormatForPath(path);
    if (!format) {
        error = QStringLiteral("%1: unknown video format (use .mp4, .webm or .gif)").arg(path_).toStdString();
        return false;
    }
    return encoder_.open(VideoSettings{*format, width, height, fps, padColor_}, path, error);
}

bool VideoSink::write(const Image& image, int, std::string& error) { return encoder_.write(image, error); }

bool VideoSink::finish(bool cancelled, std::string& error) {
    if (cancelled) {
        encoder_.abort();  // no partial file
        return true;
    }
    return encoder_.finish(error);
}

}  // namespace f2::viewer
