#pragma once
/// A helper program (ffmpeg, ffprobe) run with pipes to its standard input and
/// from its standard output and error. Every wait can be cancelled: while the
/// child does not read or does not exit, the caller's cancel flag is looked at
/// at least every kCancelPollMs, so Ctrl+C stops us within a fraction of a
/// second whatever the child does. Changes no process-wide state: a closed
/// pipe is an error code here, never a SIGPIPE for the whole process.
#include <sys/types.h>

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

namespace f2 {

class ChildProcess {
   public:
    /// How often a blocked write or wait looks at the cancel flag.
    static constexpr int kCancelPollMs = 100;
    /// At most this much of each output stream is kept.
    static constexpr std::size_t kMaxKeptOutput = 64 * 1024;

    enum class Io { Done, Cancelled, Closed };

    ChildProcess() = default;
    /// Kills and reaps the child if it still runs.
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    /// Starts `program` (a path) with `args` (without the program name) in its
    /// own process group, so that a terminal's Ctrl+C reaches only us and we
    /// decide what happens to the child. False with `error` set on failure.
    bool start(const std::string& program, const std::vector<std::string>& args, std::string& error);

    /// Writes all of `data` to the child's standard input. Closed: the child
    /// closed its input (exited); Cancelled: `cancel` was raised first.
    Io writeInput(const void* data, std::size_t size, const std::atomic<bool>* cancel);
    /// End of the input stream.
    void closeInput();

    /// Waits until the child exits, keeping its output. Cancelled: `cancel` was
    /// raised first (the child still runs; kill() it). Done: see exitStatus().
    Io wait(const std::atomic<bool>* cancel);
    /// Kills the child's whole process group and reaps it. Also a stopped child.
    void kill();

    bool running() const { return pid_ > 0; }
    pid_t pid() const { return pid_; }
    /// The raw status from waitpid after wait() returned Done.
    int exitStatus() const { return status_; }
    /// "exit status 1", "killed by signal 9" or "" for a clean exit.
    std::string describeExit() const;
    const std::string& standardOutput() const { return out_; }
    const std::string& standardError() const { return err_; }

   private:
    /// Waits up to `blockMs` for output (which it keeps), for room in the input
    /// pipe (`alsoInput`) or for the child's exit. True if the child has exited.
    bool pump(int blockMs, bool alsoInput);

    pid_t pid_ = -1;
    int pidfd_ = -1;
    int in_ = -1, outPipe_ = -1, errPipe_ = -1;
    int status_ = 0;
    std::string out_, err_;
};

/// Runs `program args` to completion and returns its exit status (-1 if it
/// could not start); its output is kept in `output` and `errors`.
int runToCompletion(const std::string& program, const std::vector<std::string>& args, std::string& output,
                    std::string& errors, const std::atomic<bool>* cancel, bool& cancelled);

}  // namespace f2
