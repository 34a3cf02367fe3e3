#include "io/video_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

extern char** environ;

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

bool writeAll(int fd, const std::uint8_t* data, std::size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;  // a signal; the caller checks its cancel flag between frames
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
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

VideoEncoder::~VideoEncoder() {
    if (!finished_) abort();
}

bool VideoEncoder::open(const VideoSettings& settings, const std::string& path, std::string& error) {
    settings_ = settings;
    path_ = path;
    std::string ffmpeg = findProgram("ffmpeg");
    if (ffmpeg.empty()) {
        error = std::string("writing ") + videoFormatName(settings.format) +
                " needs the ffmpeg program, which is not on PATH; install it (Debian/Ubuntu: "
                "sudo apt-get install ffmpeg; macOS: brew install ffmpeg) or write a PNG sequence "
                "with -o frames/f_%04d.png";
        return false;
    }
    tempPath_ = path + ".tmp-" + std::to_string(::getpid());
    // Fail early and clearly if the directory is not writable; ffmpeg's own
    // message would be less plain.
    int probe = ::open(tempPath_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (probe < 0) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        return false;
    }
    ::close(probe);

    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        error = std::string("cannot create a pipe to ffmpeg: ") + std::strerror(errno);
        std::remove(tempPath_.c_str());
        return false;
    }
    ::signal(SIGPIPE, SIG_IGN);

    std::vector<std::string> args = ffmpegArguments(settings, tempPath_);
    args.insert(args.begin(), ffmpeg);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    // Own process group: Ctrl+C in the terminal reaches only f2, which then
    // decides what happens to the file (ffmpeg would otherwise finish it).
    // SIGPIPE back to default for ffmpeg, since the ignore above is inherited.
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF);
    int rc = ::posix_spawn(&pid_, ffmpeg.c_str(), &actions, &attr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(fds[0]);
    if (rc != 0) {
        ::close(fds[1]);
        pid_ = -1;
        std::remove(tempPath_.c_str());
        error = "cannot start '" + ffmpeg + "': " + std::strerror(rc);
        return false;
    }
    pipe_ = fds[1];
    return true;
}

bool VideoEncoder::write(const Image& frame, std::string& error) {
    if (pipe_ < 0) {
        error = "the video is not open";
        return false;
    }
    if (frame.width != settings_.width || frame.height != settings_.height) {
        error = "frame size changed during the video";
        return false;
    }
    static_assert(sizeof(Rgb8) == 3, "frames are sent as packed rgb24");
    if (!writeAll(pipe_, reinterpret_cast<const std::uint8_t*>(frame.pixels.data()),
                  frame.pixels.size() * 3)) {
        std::string status;
        ::close(pipe_);
        pipe_ = -1;
        waitForExit(status);
        error = "ffmpeg stopped accepting frames (" + status + "); its messages, if any, are above";
        abort();
        return false;
    }
    return true;
}

bool VideoEncoder::waitForExit(std::string& error, const std::atomic<bool>* cancel) {
    if (pid_ < 0) return true;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0) {
        if (errno == EINTR && cancel && cancel->load()) {
            error = "interrupted";
            return false;  // ffmpeg still runs; the caller aborts
        }
        if (errno != EINTR) {
            error = std::string("waiting for ffmpeg: ") + std::strerror(errno);
            pid_ = -1;
            return false;
        }
    }
    pid_ = -1;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
    error = WIFEXITED(status) ? "ffmpeg exited with status " + std::to_string(WEXITSTATUS(status))
                              : "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
    return false;
}

bool VideoEncoder::finish(std::string& error, const std::atomic<bool>* cancel) {
    if (pipe_ >= 0) {
        ::close(pipe_);  // end of stream: ffmpeg flushes and writes the trailer
        pipe_ = -1;
    }
    std::string status;
    if (!waitForExit(status, cancel)) {
        error = cancel && cancel->load() ? "interrupted"
                                         : "ffmpeg failed (" + status + "); its messages, if any, are above";
        abort();
        return false;
    }
    // ffmpeg has closed the file; make it durable before it takes the real name.
    int fd = ::open(tempPath_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    if (std::rename(tempPath_.c_str(), path_.c_str()) != 0) {
        error = "cannot rename onto '" + path_ + "': " + std::strerror(errno);
        abort();
        return false;
    }
    finished_ = true;
    return true;
}

void VideoEncoder::abort() {
    if (pipe_ >= 0) {
        ::close(pipe_);
        pipe_ = -1;
    }
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        std::string ignored;
        waitForExit(ignored);
    }
    if (!tempPath_.empty()) std::remove(tempPath_.c_str());
    finished_ = true;
}

}  // namespace f2
