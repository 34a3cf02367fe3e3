#pragma once
/// Where exported frames go: a PNG sequence or a video file (through the
/// CLI's ffmpeg-based f2::VideoEncoder). AnimationExporter drives either.
#include <QString>
#include <string>

#include "core/render/image.h"
#include "io/video_encoder.h"

namespace f2::viewer {

class FrameSink {
   public:
    virtual ~FrameSink() = default;
    /// Called once before the first frame. False (and `error`) aborts the export.
    virtual bool begin(int width, int height, int fps, int frameCount, std::string& error) = 0;
    /// Called for frames in order; `index` counts from 0.
    virtual bool write(const Image& image, int index, std::string& error) = 0;
    /// Called once after the last frame, or after a cancel (`cancelled`).
    virtual bool finish(bool cancelled, std::string& error) = 0;
    /// Human-readable destination, for messages.
    virtual QString destination() const = 0;
};

/// `<dir>/<stem>_0000.png`, `<stem>_0001.png`, ... written atomically by f2::io.
class PngSequenceSink : public FrameSink {
   public:
    PngSequenceSink(QString directory, QString stem);
    bool begin(int width, int height, int fps, int frameCount, std::string& error) override;
    bool write(const Image& image, int index, std::string& error) override;
    bool finish(bool cancelled, std::string& error) override;
    QString destination() const override;
    /// File name of frame `index` (after begin()).
    QString fileName(int index) const;

   private:
    QString directory_;
    QString stem_;
    int digits_ = 4;
};

/// One video file (.mp4, .webm or .gif, chosen by the extension) encoded by
/// f2::VideoEncoder. The file appears only when finish() succeeds; a cancel
/// or an error aborts ffmpeg and removes the temporary file.
class VideoSink : public FrameSink {
   public:
    /// `padColor` fills the extra row/column H.264 needs for odd sizes.
    explicit VideoSink(QString path, Rgb8 padColor = {});
    bool begin(int width, int height, int fps, int frameCount, std::string& error) override;
    bool write(const Image& image, int index, std::string& error) override;
    bool finish(bool cancelled, std::string& error) override;
    QString destination() const override { return path_; }

   private:
    QString path_;
    Rgb8 padColor_;
    VideoEncoder encoder_;
};

}  // namespace f2::viewer
