#pragma once
/// Writing output files so that an interrupted program never leaves a
/// half-written one: write to a temporary file beside it, then rename.
#include <cstdio>
#include <string>

namespace f2 {

class AtomicFile {
public:
    /// Opens `<path>.tmp-<pid>` for writing. Check ok() / error().
    explicit AtomicFile(std::string path);
    /// Removes the temporary file unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    bool ok() const { return file_ != nullptr; }
    std::FILE* handle() { return file_; }
    const std::string& error() const { return error_; }
    const std::string& tempPath() const { return tempPath_; }

    /// Flushes, closes and renames onto the final path.
    bool commit();

private:
    std::string path_, tempPath_, error_;
    std::FILE* file_ = nullptr;
    bool committed_ = false;
};

}  // namespace f2
