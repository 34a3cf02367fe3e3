#pragma once
/// Video files through the `ffmpeg` program: frames are piped to it as raw
/// rgb24 on its standard input, so f2 links no codec library and gets every
/// encoder ffmpeg has. ffmpeg writes a temporary file beside the output with
/// an explicit container format; finish() renames it into place, so an
/// interrupted render never leaves a partial video.
#include <sys/types.h>

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "core/render/image.h"

namespace f2 {

enum class VideoFormat { Mp4, Webm, Gif };

/// The format chosen by the file name's extension (.mp4, .webm, .gif; any
/// letter case); nullopt for anything else.
std::optional<VideoFormat> videoFormatForPath(const std::string& path);
const char* videoFormatName(VideoFormat format);

struct VideoSettings {
    VideoFormat format = VideoFormat::Mp4;
    int width = 0, height = 0;  ///< of the frames written
    int fps = 24;
    Rgb8 padColor;  ///< fills the extra row/column when H.264 needs even sizes
};

/// H.264 in yuv420p needs even sizes: true if the frames will be padded by
/// one row and/or column (to the right and bottom).
bool videoNeedsPadding(const VideoSettings& settings);

/// ffmpeg's arguments (without the program name) to read raw rgb24 frames from
/// stdin and write `outputPath` in the settings' format.
std::vector<std::string> ffmpegArguments(const VideoSettings& settings, const std::string& outputPath);

/// Full path of an executable `name` on $PATH, or "" if there is none.
std::string findProgram(const std::string& name);

class VideoEncoder {
   public:
    VideoEncoder() = default;
    /// Aborts (kills ffmpeg, removes the temporary file) unless finish() succeeded.
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    /// Starts ffmpeg writing `<path>.tmp-<pid>`. Ignores SIGPIPE for the whole
    /// process, so that an ffmpeg that dies shows up as a write error. False
    /// with `error` set if ffmpeg is missing or cannot be started.
    bool open(const VideoSettings& settings, const std::string& path, std::string& error);
    /// Sends one frame (its size must be the settings' size).
    bool write(const Image& frame, std::string& error);
    /// Ends the stream, waits for ffmpeg and renames the file into place. If
    /// `cancel` is raised while ffmpeg is still finishing (a GIF's palette pass
    /// can take a while), aborts instead and returns false.
    bool finish(std::string& error, const std::atomic<bool>* cancel = nullptr);
    /// Stops ffmpeg at once and removes the temporary file.
    void abort();

    const std::string& tempPath() const { return tempPath_; }

   private:
    bool waitForExit(std::string& error, const std::atomic<bool>* cancel = nullptr);

    VideoSettings settings_;
    std::string path_, tempPath_;
    int pipe_ = -1;
    pid_t pid_ = -1;
    bool finished_ = false;
};

}  // namespace f2
