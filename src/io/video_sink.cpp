#include "io/video_sink.h"

namespace f2 {

VideoSink::VideoSink(std::string path, VideoFormat format, Rgb8 padColor)
    : path_(std::move(path)), format_(format), padColor_(padColor) {}

bool VideoSink::begin(const FrameFormat& format, std::string& error) {
    return encoder_.open(VideoSettings{format_, format.width, format.height, format.fps, padColor_}, path_,
                         error);
}

bool VideoSink::write(const Image& image, std::int64_t, std::string& error, const std::atomic<bool>* cancel) {
    return encoder_.write(image, error, cancel);
}

bool VideoSink::finish(std::string& error, const std::atomic<bool>* cancel) {
    return encoder_.finish(error, cancel);
}

}  // namespace f2
