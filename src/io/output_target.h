#pragma once
/// Where an output file really goes. A path may name a new file, an existing
/// regular file, a symbolic link to one, or a device such as /dev/null; each
/// is written differently so that nothing but the named file ever changes,
/// and it changes only once it is complete.
#include <string>

namespace f2 {

struct OutputTarget {
    enum class Kind {
        File,     ///< a regular file or none yet: written to a temporary file, then renamed onto it
        Special,  ///< a device, FIFO or socket: written directly (renaming would replace the node)
    };
    std::string path;      ///< as the user gave it, for messages
    std::string realPath;  ///< symbolic links of the last component followed
    Kind kind = Kind::File;
    bool exists = false;  ///< realPath exists (it is replaced or written into)
};

/// Resolves `path`, following symbolic links to the file they name (also a
/// dangling link: the file it names is created). False with `error` set if it
/// names a directory or a loop of links.
bool resolveOutput(const std::string& path, OutputTarget& target, std::string& error);

/// Creates the directory that will hold `path`, parents included (an existing
/// one is fine). False with `error` set if that is impossible; when a file
/// stands where a directory must go, the error names that file.
bool createDirectoryOf(const std::string& path, std::string& error);

/// What a Special target is, for messages: "a character device", "a FIFO", ...
std::string specialFileDescription(const std::string& path);

/// Creates a new, empty file beside `realPath` for writing its next version:
/// `<name>.tmp-XXXXXX` in the same directory (so the rename is atomic), the
/// XXXXXX random and the file created exclusively, so two writers never share
/// one, even two processes with the same PID in different containers. The name
/// is shortened to fit the file-name limit. The file gets the permissions of
/// the file it will replace (new files: 0666 less the umask). Returns the open
/// descriptor (close-on-exec) and sets `tempPath`, or -1 with `error` set.
int createTemporaryBeside(const std::string& realPath, std::string& tempPath, std::string& error);

/// True if `name` (a file name without directory) is a temporary file that
/// createTemporaryBeside made for `target` (a file name as well).
bool isTemporaryOf(const std::string& name, const std::string& target);

/// True if `name` (a file name) has the form of a temporary file that
/// createTemporaryBeside makes, for whichever target: a cheap filter before
/// isTemporaryOf when a directory is searched for leftovers.
bool looksLikeTemporary(const std::string& name);

/// Makes a finished file durable and gives it its real name: fsync, then rename
/// `tempPath` onto `realPath`. False with `error` set (the temporary file is
/// then still there for the caller to remove).
bool replaceWithTemporary(const std::string& tempPath, const OutputTarget& target, std::string& error);

}  // namespace f2
