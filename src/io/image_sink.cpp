#include "io/image_sink.h"

#include "io/png_writer.h"

namespace f2 {

bool PngImageSink::begin(const FrameFormat& format, std::string& error) {
    if (format.frameCount == 1) return true;
    error = "'" + path_ + "' holds one image, not " + std::to_string(format.frameCount) + " frames";
    return false;
}

bool PngImageSink::write(const Image& image, std::int64_t, std::string& error, const std::atomic<bool>*) {
    written_ = stream_ ? writePng(image, stream_, error) : writePng(image, path_, error);
    return written_;
}

bool PngImageSink::finish(std::string& error, const std::atomic<bool>*) {
    if (!written_) error = "no image was rendered for '" + path_ + "'";
    return written_;
}

}  // namespace f2
