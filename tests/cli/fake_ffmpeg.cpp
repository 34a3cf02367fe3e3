// fake_ffmpeg: stands in for the ffmpeg program (installed as `ffmpeg` in a
// directory put first on PATH) to make f2 meet, on demand and without timing,
// the ways a real ffmpeg fails. F2_FAKE_FFMPEG picks the behaviour:
//   enospc      reads every frame, writes a few bytes, says "No space left on
//               device" and exits 0: what ffmpeg does on a full disk
//   silent-junk reads every frame, writes bytes that are no video, exits 0
//               without a word (only a probe of the result can tell)
//   stall       writes its PID to $F2_FAKE_FFMPEG_PIDFILE, reads nothing, and
//               once its input pipe is full creates $F2_FAKE_FFMPEG_READY and
//               waits for ever (stopped by SIGSTOP itself if F2_FAKE_FFMPEG_STOP
//               is set): f2 is then certainly blocked writing a frame
//   rendezvous  appends "PARENT_PID OUTPUT" to $F2_FAKE_FFMPEG_LOG, waits
//               until $F2_FAKE_FFMPEG_PARTIES lines are there (every worker is
//               encoding at once), then runs $F2_REAL_FFMPEG with its arguments
#include <fcntl.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace {

std::string env(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

/// ffmpeg's output file: its last argument, maybe as `file:PATH`.
std::string outputPath(int argc, char** argv) {
    std::string path = argv[argc - 1];
    return path.starts_with("file:") ? path.substr(5) : path;
}

void readAllInput() {
    char buffer[65536];
    while (::read(STDIN_FILENO, buffer, sizeof buffer) > 0) {
    }
}

void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

int lineCount(const std::string& path) {
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    int n = 0;
    for (char c : text) n += c == '\n';
    return n;
}

void pauseBriefly() { ::usleep(2000); }  // polling a condition, not waiting for time to pass

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return 2;
    const std::string mode = env("F2_FAKE_FFMPEG");
    const std::string output = outputPath(argc, argv);
    if (mode == "enospc") {
        readAllInput();
        writeFile(output, std::string("\0\0\0\x20"
                                      "ftyp",
                                      8));  // the start of an MP4, no more
        std::fprintf(stderr, "[out#0/mp4 @ 0x5563] Error writing trailer: No space left on device\n");
        return 0;
    }
    if (mode == "silent-junk") {
        readAllInput();
        writeFile(output, std::string(4096, 'x'));
        return 0;
    }
    if (mode == "stall") {
        writeFile(env("F2_FAKE_FFMPEG_PIDFILE"), std::to_string(::getpid()) + "\n");
        const int capacity = ::fcntl(STDIN_FILENO, F_GETPIPE_SZ);
        for (int queued = 0; ::ioctl(STDIN_FILENO, FIONREAD, &queued) == 0 && queued < capacity;)
            pauseBriefly();
        writeFile(env("F2_FAKE_FFMPEG_READY"), "full\n");
        if (!env("F2_FAKE_FFMPEG_STOP").empty()) ::raise(SIGSTOP);
        for (;;) ::pause();
    }
    if (mode == "rendezvous") {
        const std::string log = env("F2_FAKE_FFMPEG_LOG");
        const std::string line = std::to_string(::getppid()) + " " + output + "\n";
        int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd < 0 || ::write(fd, line.data(), line.size()) != ssize_t(line.size())) return 3;
        ::close(fd);
        const int parties = std::atoi(env("F2_FAKE_FFMPEG_PARTIES").c_str());
        while (lineCount(log) < parties) pauseBriefly();
        const std::string real = env("F2_REAL_FFMPEG");
        argv[0] = const_cast<char*>(real.c_str());
        ::execv(real.c_str(), argv);
        return 4;
    }
    std::fprintf(stderr, "fake_ffmpeg: unknown F2_FAKE_FFMPEG '%s'\n", mode.c_str());
    return 2;
}
