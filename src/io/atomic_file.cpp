#include "io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace f2 {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    tempPath_ = path_ + ".tmp-" + std::to_string(::getpid());
    file_ = std::fopen(tempPath_.c_str(), "wb");
    if (!file_) error_ = "cannot write '" + path_ + "': " + std::strerror(errno);
}

AtomicFile::~AtomicFile() {
    if (file_) std::fclose(file_);
    if (!committed_) std::remove(tempPath_.c_str());
}

bool AtomicFile::commit() {
    if (!file_) return false;
    bool flushed = std::fflush(file_) == 0 && ::fsync(fileno(file_)) == 0;
    int closeResult = std::fclose(file_);
    file_ = nullptr;
    if (!flushed || closeResult != 0) {
        error_ = "cannot write '" + path_ + "': " + std::strerror(errno);
        return false;
    }
    if (std::rename(tempPath_.c_str(), path_.c_str()) != 0) {
        error_ = "cannot rename onto '" + path_ + "': " + std::strerror(errno);
        return false;
    }
    committed_ = true;
    return true;
}

}  // namespace f2
