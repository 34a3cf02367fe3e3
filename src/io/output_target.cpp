#include "io/output_target.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>

namespace f2 {

namespace {
constexpr int kMaxLinks = 40;  // as the kernel's own limit on links in a path
constexpr const char* kTempMarker = ".tmp-";
constexpr std::size_t kRandomChars = 6;
constexpr std::size_t kTempSuffixBytes = 5 + kRandomChars;  // ".tmp-" and the random part

std::string directoryOf(const std::string& path) {
    auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return "";
    return path.substr(0, slash + 1);  // keeps the slash: "" or "dir/"
}

std::string fileNameOf(const std::string& path) {
    auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The part of `name` that goes into its temporary file's name: all of it if
/// the result fits NAME_MAX, else cut (not inside a UTF-8 sequence).
std::string temporaryStem(const std::string& name) {
    std::size_t keep = name.size();
    if (keep + kTempSuffixBytes > NAME_MAX) {
        keep = NAME_MAX - kTempSuffixBytes;
        while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
    }
    return name.substr(0, keep);
}

std::string randomChars() {
    static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    unsigned char bytes[kRandomChars];
    std::size_t got = 0;
    while (got < sizeof bytes) {
        ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += std::size_t(n);
    }
    // getrandom cannot fail here in practice; O_EXCL keeps the name unique regardless.
    std::string out;
    for (std::size_t i = 0; i < kRandomChars; ++i)
        out += kAlphabet[(i < got ? bytes[i] : (::getpid() + i)) % (sizeof kAlphabet - 1)];
    return out;
}

std::string kindName(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}
}  // namespace

bool resolveOutput(const std::string& path, OutputTarget& target, std::string& error) {
    target = OutputTarget{path, path, OutputTarget::Kind::File, false};
    if (path.empty()) {
        error = "the output file name is empty";
        return false;
    }
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0) {
        target.exists = true;
        if (S_ISDIR(info.st_mode)) {
            error = "cannot write '" + path + "': it is a directory";
            return false;
        }
        // A device, FIFO or socket is opened by the name given: that also
        // works through /proc's links, such as /dev/stdout onto a pipe.
        if (!S_ISREG(info.st_mode)) {
            target.kind = OutputTarget::Kind::Special;
            return true;
        }
    }
    // A regular file, or none yet: follow the links to the name to replace or create.
    std::string current = path;
    for (int links = 0;; ++links) {
        if (::lstat(current.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) {
            target.realPath = current;
            return true;
        }
        if (links == kMaxLinks) {
            error = "cannot write '" + path + "': too many levels of symbolic links";
            return false;
        }
        std::string link(PATH_MAX, '\0');
        ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
        if (n < 0) {
            error = "cannot write '" + path + "': " + std::strerror(errno);
            return false;
        }
        link.resize(std::size_t(n));
        current = link.starts_with('/') ? link : directoryOf(current) + link;
    }
}

std::string specialFileDescription(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 ? kindName(info.st_mode) : "not a regular file";
}

int createTemporaryBeside(const std::string& realPath, std::string& tempPath, std::string& error) {
    const std::string prefix = directoryOf(realPath) + temporaryStem(fileNameOf(realPath)) + kTempMarker;
    mode_t mode = 0666;  // less the umask, as any new file
    struct stat existing {};
    const bool replaces = ::stat(realPath.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
    for (int attempt = 0; attempt < 100; ++attempt) {
        tempPath = prefix + randomChars();
        int fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
        if (fd >= 0) {
            if (replaces) ::fchmod(fd, existing.st_mode & 07777);
            return fd;
        }
        if (errno != EEXIST) break;
    }
    error = "cannot write '" + realPath + "': " + std::strerror(errno);
    tempPath.clear();
    return -1;
}

bool isTemporaryOf(const std::string& name, const std::string& target) {
    const std::string prefix = temporaryStem(target) + kTempMarker;
    return name.size() == prefix.size() + kRandomChars && name.starts_with(prefix);
}

bool looksLikeTemporary(const std::string& name) {
    const std::size_t marker = name.rfind(kTempMarker);
    return marker != std::string::npos && name.size() == marker + kTempSuffixBytes;
}

bool replaceWithTemporary(const std::string& tempPath, const OutputTarget& target, std::string& error) {
    int fd = ::open(tempPath.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
        error = "cannot write '" + target.path + "': " + std::strerror(errno);
        if (fd >= 0) ::close(fd);
        return false;
    }
    ::close(fd);
    if (std::rename(tempPath.c_str(), target.realPath.c_str()) != 0) {
        error = "cannot rename onto '" + target.path + "': " + std::strerror(errno);
        return false;
    }
    return true;
}

bool createDirectoryOf(const std::string& path, std::string& error) {
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (dir.empty() || std::filesystem::is_directory(dir, ec)) return true;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        error = "cannot create the directory '" + dir.string() + "' for '" + path + "': ";
        // "Not a directory" alone does not say which name is in the way.
        for (std::filesystem::path p = dir; !p.empty() && p != p.root_path(); p = p.parent_path()) {
            std::error_code statError;
            if (std::filesystem::exists(p, statError) && !std::filesystem::is_directory(p, statError)) {
                error += "'" + p.string() + "' is a file, not a directory; choose another output name";
                return false;
            }
        }
        error += ec.message();
        return false;
    }
    return true;
}

}  // namespace f2
