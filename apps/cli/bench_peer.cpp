#include "bench_peer.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "io/child_process.h"
#include "io/prims_export.h"

namespace f2::cli {

namespace {
/// The value of `key=` in the peer's "RESULT key=value ..." line, or -1.
double resultValue(const std::string& output, const std::string& key) {
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("RESULT ", 0) != 0) continue;
        std::istringstream fields(line);
        std::string field;
        while (fields >> field)
            if (field.rfind(key + "=", 0) == 0) return std::strtod(field.c_str() + key.size() + 1, nullptr);
    }
    return -1;
}

/// A temporary file holding `text`, removed when this goes out of scope.
class TemporaryFile {
   public:
    explicit TemporaryFile(const std::string& text) {
        const char* dir = std::getenv("TMPDIR");
        path_ = std::string(dir && *dir ? dir : "/tmp") + "/f2-study-XXXXXX.prims";
        int fd = mkstemps(path_.data(), 6);
        if (fd < 0) {
            path_.clear();
            return;
        }
        std::size_t written = 0;
        while (written < text.size()) {
            ssize_t n = ::write(fd, text.data() + written, text.size() - written);
            if (n <= 0) break;
            written += std::size_t(n);
        }
        ::close(fd);
        ok_ = written == text.size();
    }
    ~TemporaryFile() {
        if (!path_.empty()) std::remove(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    bool ok() const { return ok_; }
    const std::string& path() const { return path_; }

   private:
    std::string path_;
    bool ok_ = false;
};
}  // namespace

std::optional<PeerResult> runPeer(const PeerSettings& settings, const SceneDesc& scene, double t,
                                  const Camera& camera, const std::string& name, std::string& error) {
    TemporaryFile frame(primsScene(scene, t, camera, name));
    if (!frame.ok()) {
        error = "cannot write a temporary primitive list";
        return std::nullopt;
    }
    PeerResult best;
    for (const std::string& mode : settings.modes) {
        std::string output, errors;
        bool cancelled = false;
        int status = runToCompletion(settings.program,
                                     {frame.path(), "--threads", std::to_string(settings.threads),
                                      "--seconds", std::to_string(settings.seconds), "--rebuild", mode},
                                     output, errors, nullptr, cancelled);
        double fps = resultValue(output, "total_fps");
        if (status != 0 || fps < 0) {
            error =
                settings.program + " --rebuild " + mode + " failed" + (errors.empty() ? "" : ": " + errors);
            return std::nullopt;
        }
        if (fps > best.fps) best = {fps, mode};
    }
    return best;
}

}  // namespace f2::cli
