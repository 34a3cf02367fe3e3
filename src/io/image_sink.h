#pragma once
/// One PNG image: the single frame of a one-frame range.
#include <cstdio>
#include <string>

#include "io/frame_sink.h"

namespace f2 {

class PngImageSink : public FrameSink {
   public:
    explicit PngImageSink(std::string path) : path_(std::move(path)) {}
    /// Writes to an open stream (standard output), named `name` in messages.
    PngImageSink(std::FILE* stream, std::string name) : path_(std::move(name)), stream_(stream) {}
    /// False unless exactly one frame is coming.
    bool begin(const FrameFormat& format, std::string& error) override;
    /// Writes the file atomically (temporary file, then rename; a device directly).
    bool write(const Image& image, std::int64_t frame, std::string& error,
               const std::atomic<bool>* cancel) override;
    bool finish(std::string& error, const std::atomic<bool>* cancel) override;
    void abandon() override {}
    std::int64_t framesCompleted() const override { return written_ ? 1 : 0; }

   private:
    std::string path_;
    std::FILE* stream_ = nullptr;
    bool written_ = false;
};

}  // namespace f2
