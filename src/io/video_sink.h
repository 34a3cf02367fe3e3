#pragma once
/// One video file (.mp4, .webm or .gif) encoded by ffmpeg through
/// VideoEncoder. The file appears only when finish() succeeds; a cancel or an
/// error stops ffmpeg and removes the temporary file.
#include <string>

#include "io/frame_sink.h"
#include "io/video_encoder.h"

namespace f2 {

class VideoSink : public FrameSink {
   public:
    /// `padColor` fills the extra row/column H.264 needs for odd sizes.
    VideoSink(std::string path, VideoFormat format, Rgb8 padColor = {});
    bool begin(const FrameFormat& format, std::string& error) override;
    bool write(const Image& image, std::int64_t frame, std::string& error,
               const std::atomic<bool>* cancel) override;
    bool finish(std::string& error, const std::atomic<bool>* cancel) override;
    void abandon() override { encoder_.abort(); }
    std::int64_t framesCompleted() const override { return encoder_.framesWritten(); }

    const VideoEncoder& encoder() const { return encoder_; }

   private:
    std::string path_;
    VideoFormat format_;
    Rgb8 padColor_;
    VideoEncoder encoder_;
};

}  // namespace f2
