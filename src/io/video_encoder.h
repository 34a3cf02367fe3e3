#pragma once
/// Video files through the `ffmpeg` program: frames are piped to it as raw
/// rgb24 on its standard input, so f2 links no codec library and gets every
/// encoder ffmpeg has. ffmpeg writes a temporary file beside the output, named
/// `file:` + its absolute path (so no output name is read as a protocol) with
/// an explicit container format; finish() checks it and renames it into
/// place, so an interrupted or failed render never leaves a partial video.
#include <sys/types.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/render/image.h"
#include "io/child_process.h"
#include "io/output_target.h"

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

/// How ffmpeg must be given the file `path` so that it reads no protocol into
/// the name (`pipe:x.gif`, `file:y.gif`, `http:...`): `file:` and the absolute path.
std::string ffmpegFileName(const std::string& path);

/// Full path of an executable `name` on $PATH, or "" if there is none.
std::string findProgram(const std::string& name);

/// Why VideoEncoder::write or finish failed.
enum class VideoFailure { None, Cancelled, Failed };

class VideoEncoder {
   public:
    VideoEncoder() = default;
    /// Aborts (kills ffmpeg, removes the temporary file) unless finish() succeeded.
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    /// Starts ffmpeg writing a temporary file beside `path` (symbolic links
    /// followed). False with `error` set if ffmpeg is missing or cannot be
    /// started, or `path` is a directory or a device (a video is only ever
    /// written to a regular file).
    bool open(const VideoSettings& settings, const std::string& path, std::string& error);
    /// Sends one frame (its size must be the settings' size). While ffmpeg does
    /// not read, `cancel` is looked at every ChildProcess::kCancelPollMs.
    bool write(const Image& frame, std::string& error, const std::atomic<bool>* cancel = nullptr);
    /// Ends the stream, waits for ffmpeg and checks what it wrote: its exit
    /// status, its error output (ffmpeg exits 0 on a full disk), the file's size
    /// and, where ffprobe is installed, the number of frames in it. Only then is
    /// the file renamed into place; on any failure it is removed. If `cancel` is
    /// raised meanwhile (a GIF's palette pass can take a while), aborts instead.
    bool finish(std::string& error, const std::atomic<bool>* cancel = nullptr);
    /// Stops ffmpeg at once (also a stopped one), reaps it and removes the temporary file.
    void abort();

    /// Why the last write() or finish() failed.
    VideoFailure failure() const { return failure_; }
    const std::string& tempPath() const { return tempPath_; }
    /// Frames sent so far.
    std::int64_t framesWritten() const { return framesWritten_; }

   private:
    bool fail(VideoFailure why, std::string message, std::string& error);
    bool checkResult(std::string& error, const std::atomic<bool>* cancel);

    VideoSettings settings_;
    OutputTarget target_;
    std::string tempPath_;
    ChildProcess ffmpeg_;
    std::int64_t framesWritten_ = 0;
    VideoFailure failure_ = VideoFailure::None;
    bool finished_ = false;
};

}  // namespace f2
