#include "io/video_encoder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace f2 {

namespace {
std::string lowerExtension(const std::string& path) {
    auto slash = path.find_last_of('/');
    auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string hexColor(Rgb8 c) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%02X%02X%02X", c.r, c.g, c.b);
    return text;
}

/// "; <program> said: <what it said>" with its lines joined by "; ", or "" if it said nothing.
std::string messageFrom(const std::string& program, const std::string& said) {
    std::string text;
    std::size_t start = 0;
    while (start < said.size()) {
        std::size_t end = said.find_first_of("\r\n", start);
        if (end == std::string::npos) end = said.size();
        if (end > start) text += (text.empty() ? "" : "; ") + said.substr(start, end - start);
        start = end + 1;
    }
    return text.empty() ? "" : "; " + program + " said: " + text;
}
}  // namespace

std::optional<VideoFormat> videoFormatForPath(const std::string& path) {
    std::string ext = lowerExtension(path);
    if (ext == "mp4") return VideoFormat::Mp4;
    if (ext == "webm") return VideoFormat::Webm;
    if (ext == "gif") return VideoFormat::Gif;
    return std::nullopt;
}

const char* videoFormatName(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4:
            return "mp4";
        case VideoFormat::Webm:
            return "webm";
        case VideoFormat::Gif:
            return "gif";
    }
    return "?";
}

bool videoNeedsPadding(const VideoSettings& s) {
    return s.format == VideoFormat::Mp4 && (s.width % 2 != 0 || s.height % 2 != 0);
}

std::vector<std::string> ffmpegArguments(const VideoSettings& s, const std::string& outputPath) {
    std::vector<std::string> args = {"-hide_banner",
                                     "-loglevel",
                                     "error",
                                     "-nostdin",
                                     "-y",
                                     "-f",
                                     "rawvideo",
                                     "-pix_fmt",
                                     "rgb24",
                                     "-video_size",
                                     std::to_string(s.width) + "x" + std::to_string(s.height),
                                     "-framerate",
                                     std::to_string(s.fps),
                                     "-i",
                                     "pipe:0"};
    auto add = [&args](std::initializer_list<const char*> more) {
        args.insert(args.end(), more.begin(), more.end());
    };
    switch (s.format) {
        case VideoFormat::Mp4:
            if (videoNeedsPadding(s)) {
                args.push_back("-vf");
                args.push_back("pad=ceil(iw/2)*2:ceil(ih/2)*2:0:0:color=" + hexColor(s.padColor));
            }
            // yuv420p: the pixel format every player decodes; faststart: playable while downloading.
            add({"-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p", "-movflags",
                 "+faststart", "-f", "mp4"});
            break;
        case VideoFormat::Webm:
            // Constant quality (-b:v 0 -crf); row-mt uses every core.
            add({"-c:v", "libvpx-vp9", "-crf", "32", "-b:v", "0", "-row-mt", "1", "-pix_fmt", "yuv420p", "-f",
                 "webm"});
            break;
        case VideoFormat::Gif:
            // One palette for the whole animation from its changing pixels, then
            // dither with it: far better colours than GIF's default palette.
            add({"-filter_complex",
                 "[0:v]split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_"
                 "scale=4",
                 "-loop", "0", "-f", "gif"});
            break;
    }
    args.push_back(outputPath);
    return args;
}

std::string findProgram(const std::string& name) {
    if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? name : "";
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        std::string dir = dirs.substr(start, end - start);
        std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        struct stat info {};
        if (::stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
            ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
        start = end + 1;
    }
    return "";
}

std::string ffmpegFileName(const std::string& path) {
    if (path.starts_with('/')) return "file:" + path;
    std::string cwd(PATH_MAX, '\0');
    if (!::getcwd(cwd.data(), cwd.size())) return "file:" + path;  // the relative name is still a file
    cwd.resize(std::strlen(cwd.c_str()));
    return "file:" + cwd + (cwd.ends_with('/') ? "" : "/") + path;
}

VideoEncoder::~VideoEncoder() {
    if (!finished_) abort();
}

bool VideoEncoder::fail(VideoFailure why, std::string message, std::string& error) {
    failure_ = why;
    error = std::move(message);
    abort();
    return false;
}

bool VideoEncoder::open(const VideoSettings& settings, const std::string& path, std::string& error) {
    settings_ = settings;
    failure_ = VideoFailure::None;
    framesWritten_ = 0;
    if (!resolveOutput(path, target_, error)) return false;
    if (target_.kind == OutputTarget::Kind::Special) {
        error = "cannot write a video to '" + path + "': it is " + specialFileDescription(target_.realPath) +
                ", and a video is written only to a regular file";
        return false;
    }
    std::string ffmpeg = findProgram("ffmpeg");
    if (ffmpeg.empty()) {
        error = std::string("writing ") + videoFormatName(settings.format) +
                " needs the ffmpeg program, which is not on PATH; install it (Debian/Ubuntu: "
                "sudo apt-get install ffmpeg; macOS: brew install ffmpeg)";
        return false;
    }
    // Created here, so a directory we cannot write fails early and plainly,
    // and the name is ours alone; ffmpeg (-y) writes into it.
    int fd = createTemporaryBeside(target_.realPath, tempPath_, error);
    if (fd < 0) return false;
    ::close(fd);
    finished_ = false;
    if (!ffmpeg_.start(ffmpeg, ffmpegArguments(settings, ffmpegFileName(tempPath_)), error)) {
        abort();
        return false;
    }
    return true;
}

bool VideoEncoder::write(const Image& frame, std::string& error, const std::atomic<bool>* cancel) {
    if (!ffmpeg_.running()) {
        error = "the video is not open";
        return false;
    }
    if (frame.width != settings_.width || frame.height != settings_.height) {
        error = "frame size changed during the video";
        return false;
    }
    static_assert(sizeof(Rgb8) == 3, "frames are sent as packed rgb24");
    switch (ffmpeg_.writeInput(frame.pixels.data(), frame.pixels.size() * 3, cancel)) {
        case ChildProcess::Io::Done:
            ++framesWritten_;
            return true;
        case ChildProcess::Io::Cancelled:
            return fail(VideoFailure::Cancelled, "interrupted", error);
        case ChildProcess::Io::Closed:
            break;
    }
    // ffmpeg closed its input: it has failed. Let it finish saying why.
    ffmpeg_.closeInput();
    if (ffmpeg_.wait(cancel) == ChildProcess::Io::Cancelled)
        return fail(VideoFailure::Cancelled, "interrupted", error);
    std::string exit = ffmpeg_.describeExit();
    return fail(VideoFailure::Failed,
                "cannot write '" + target_.path + "': ffmpeg stopped accepting frames" +
                    (exit.empty() ? "" : " (" + exit + ")") + messageFrom("ffmpeg", ffmpeg_.standardError()),
                error);
}

bool VideoEncoder::finish(std::string& error, const std::atomic<bool>* cancel) {
    if (finished_) {
        error = "the video is not open";
        return false;
    }
    ffmpeg_.closeInput();  // end of stream: ffmpeg flushes and writes the trailer
    if (ffmpeg_.wait(cancel) == ChildProcess::Io::Cancelled)
        return fail(VideoFailure::Cancelled, "interrupted", error);
    std::string exit = ffmpeg_.describeExit();
    if (!exit.empty())
        return fail(VideoFailure::Failed,
                    "cannot write '" + target_.path + "': ffmpeg failed (" + exit + ")" +
                        messageFrom("ffmpeg", ffmpeg_.standardError()),
                    error);
    // At log level "error" ffmpeg says nothing when all is well. It exits 0
    // after some failures (a full disk), so anything it says is one.
    if (!ffmpeg_.standardError().empty())
        return fail(VideoFailure::Failed,
                    "cannot write '" + target_.path + "': ffmpeg reported an error" +
                        messageFrom("ffmpeg", ffmpeg_.standardError()),
                    error);
    if (!checkResult(error, cancel)) return false;
    if (!replaceWithTemporary(tempPath_, target_, error)) return fail(VideoFailure::Failed, error, error);
    finished_ = true;
    return true;
}

bool VideoEncoder::checkResult(std::string& error, const std::atomic<bool>* cancel) {
    struct stat info {};
    if (::stat(tempPath_.c_str(), &info) != 0 || info.st_size == 0)
        return fail(VideoFailure::Failed, "cannot write '" + target_.path + "': ffmpeg wrote an empty file",
                    error);
    // The frame count, where ffprobe is installed: a truncated file has fewer
    // or none. Packets are counted, not decoded: one packet per frame here.
    std::string ffprobe = findProgram("ffprobe");
    if (ffprobe.empty()) return true;
    std::string output, errors;
    bool cancelled = false;
    int status = runToCompletion(ffprobe,
                                 {"-v", "error", "-select_streams", "v:0", "-count_packets", "-show_entries",
                                  "stream=nb_read_packets", "-of", "csv=p=0", ffmpegFileName(tempPath_)},
                                 output, errors, cancel, cancelled);
    if (cancelled) return fail(VideoFailure::Cancelled, "interrupted", error);
    long long frames = -1;
    if (status == 0) {
        try {
            frames = std::stoll(output);
        } catch (const std::exception&) {
        }
    }
    if (frames != framesWritten_)
        return fail(VideoFailure::Failed,
                    "cannot write '" + target_.path + "': ffmpeg's video is broken: ffprobe " +
                        (frames < 0 ? std::string("cannot read it") : "finds " + std::to_string(frames)) +
                        " of " + std::to_string(framesWritten_) + " frames" + messageFrom("ffprobe", errors),
                    error);
    return true;
}

void VideoEncoder::abort() {
    ffmpeg_.kill();
    if (!tempPath_.empty()) std::remove(tempPath_.c_str());
    tempPath_.clear();
    finished_ = true;
}

}  // namespace f2
