#pragma once
/// Writing output files so that an interrupted program never leaves a
/// half-written one: write to a temporary file beside it, then rename. A
/// device such as /dev/null is written directly instead (a rename would
/// replace the device node), and a symbolic link is followed: the file it
/// names is replaced, the link stays.
#include <cstdio>
#include <string>

#include "io/output_target.h"

namespace f2 {

class AtomicFile {
   public:
    /// Opens a unique temporary file beside `path` (see createTemporaryBeside),
    /// or `path` itself if it is a device. Check ok() / error().
    explicit AtomicFile(std::string path);
    /// Removes the temporary file unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    bool ok() const { return file_ != nullptr; }
    std::FILE* handle() { return file_; }
    const std::string& error() const { return error_; }
    /// The temporary file ("" when writing a device directly).
    const std::string& tempPath() const { return tempPath_; }

    /// Flushes, closes and renames onto the final path; false (and error()) if
    /// any write failed, for example on a full disk or /dev/full.
    bool commit();

   private:
    OutputTarget target_;
    std::string tempPath_, error_;
    std::FILE* file_ = nullptr;
    bool committed_ = false;
};

}  // namespace f2
