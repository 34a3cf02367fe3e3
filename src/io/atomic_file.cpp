#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace f2 {

AtomicFile::AtomicFile(std::string path) {
    if (!resolveOutput(path, target_, error_)) return;
    int fd = -1;
    if (target_.kind == OutputTarget::Kind::Special) {
        fd = ::open(target_.realPath.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) error_ = "cannot write '" + target_.path + "': " + std::strerror(errno);
    } else {
        fd = createTemporaryBeside(target_.realPath, tempPath_, error_);
    }
    if (fd < 0) return;
    file_ = ::fdopen(fd, "wb");
    if (!file_) {
        error_ = "cannot write '" + target_.path + "': " + std::strerror(errno);
        ::close(fd);
    }
}

AtomicFile::~AtomicFile() {
    if (file_) std::fclose(file_);
    if (!committed_ && !tempPath_.empty()) std::remove(tempPath_.c_str());
}

bool AtomicFile::commit() {
    if (!file_) return false;
    bool flushed = std::fflush(file_) == 0 && !std::ferror(file_);
    int flushErrno = errno;
    int closeResult = std::fclose(file_);
    file_ = nullptr;
    if (!flushed || closeResult != 0) {
        error_ = "cannot write '" + target_.path + "': " + std::strerror(flushed ? errno : flushErrno);
        return false;
    }
    if (!tempPath_.empty() && !replaceWithTemporary(tempPath_, target_, error_)) return false;
    committed_ = true;
    return true;
}

}  // namespace f2
