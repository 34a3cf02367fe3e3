#include "io/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

extern char** environ;

namespace f2 {

namespace {
void closeFd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

void setNonBlocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

/// Blocks SIGPIPE in this thread while it lives and swallows a SIGPIPE that a
/// write raised meanwhile, so a child that closes its input is an EPIPE error
/// for this call only; the process's signal dispositions stay as they are.
class SigpipeGuard {
   public:
    SigpipeGuard() {
        sigemptyset(&pipe_);
        sigaddset(&pipe_, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &pipe_, &previous_);
        sigset_t pending;
        sigpending(&pending);
        wasPending_ = sigismember(&pending, SIGPIPE) == 1;
    }
    ~SigpipeGuard() {
        sigset_t pending;
        sigpending(&pending);
        if (!wasPending_ && sigismember(&pending, SIGPIPE) == 1) {
            const timespec now{};
            while (sigtimedwait(&pipe_, nullptr, &now) < 0 && errno == EINTR) {
            }
        }
        pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
    }
    SigpipeGuard(const SigpipeGuard&) = delete;
    SigpipeGuard& operator=(const SigpipeGuard&) = delete;

   private:
    sigset_t pipe_, previous_;
    bool wasPending_ = false;
};

bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(); }

/// Appends what `fd` has to `kept` (up to the limit); closes it at end of file.
void drain(int& fd, std::string& kept) {
    char buffer[4096];
    for (;;) {
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            std::size_t room =
                ChildProcess::kMaxKeptOutput - std::min(kept.size(), ChildProcess::kMaxKeptOutput);
            kept.append(buffer, std::min(room, std::size_t(n)));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n == 0 || errno != EAGAIN) closeFd(fd);
        return;
    }
}
}  // namespace

ChildProcess::~ChildProcess() {
    if (running()) kill();
    closeFd(in_);
    closeFd(outPipe_);
    closeFd(errPipe_);
    closeFd(pidfd_);
}

bool ChildProcess::start(const std::string& program, const std::vector<std::string>& args,
                         std::string& error) {
    int in[2] = {-1, -1}, out[2] = {-1, -1}, err[2] = {-1, -1};
    if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0) {
        error = std::string("cannot create a pipe: ") + std::strerror(errno);
        for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]})
            if (fd >= 0) ::close(fd);
        return false;
    }
    std::vector<std::string> words = args;
    words.insert(words.begin(), program);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    // The child starts with default signal handling and nothing blocked,
    // whatever this thread blocks or the process ignores.
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&defaults, s);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    int rc = ::posix_spawn(&pid_, program.c_str(), &actions, &attr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(in[0]), ::close(out[1]), ::close(err[1]);
    if (rc != 0) {
        ::close(in[1]), ::close(out[0]), ::close(err[0]);
        pid_ = -1;
        error = "cannot start '" + program + "': " + std::strerror(rc);
        return false;
    }
    in_ = in[1], outPipe_ = out[0], errPipe_ = err[0];
    for (int fd : {in_, outPipe_, errPipe_}) setNonBlocking(fd);
    // Readable when the child exits, so waits need not poll on a timer (Linux 5.3+).
    pidfd_ = int(::syscall(SYS_pidfd_open, pid_, 0));
    status_ = 0;
    out_.clear();
    err_.clear();
    return true;
}

bool ChildProcess::pump(int blockMs, bool alsoInput) {
    pollfd fds[4] = {{outPipe_, POLLIN, 0},
                     {errPipe_, POLLIN, 0},
                     {pidfd_, POLLIN, 0},
                     {alsoInput ? in_ : -1, POLLOUT, 0}};
    if (::poll(fds, 4, blockMs) <= 0) return false;  // timeout or a signal: the caller looks at its flag
    if (fds[0].revents) drain(outPipe_, out_);
    if (fds[1].revents) drain(errPipe_, err_);
    return fds[2].revents != 0;
}

ChildProcess::Io ChildProcess::writeInput(const void* data, std::size_t size,
                                          const std::atomic<bool>* cancel) {
    const auto* bytes = static_cast<const char*>(data);
    SigpipeGuard guard;
    while (size > 0) {
        if (cancelled(cancel)) return Io::Cancelled;
        if (in_ < 0) return Io::Closed;
        ssize_t n = ::write(in_, bytes, size);
        if (n > 0) {
            bytes += n;
            size -= std::size_t(n);
            continue;
        }
        if (n < 0 && errno == EPIPE) return Io::Closed;
        if (n < 0 && errno != EAGAIN && errno != EINTR) return Io::Closed;
        // Full pipe: wait until the child reads, its output needs reading (it
        // could otherwise block writing it), or it is time to look at the flag.
        // A child that has exited reads no more, even if a descendant holds the pipe.
        if (pump(kCancelPollMs, true)) return Io::Closed;
    }
    return Io::Done;
}

void ChildProcess::closeInput() { closeFd(in_); }

ChildProcess::Io ChildProcess::wait(const std::atomic<bool>* cancel) {
    while (running()) {
        int status = 0;
        pid_t r = ::waitpid(pid_, &status, WNOHANG);
        if (r == pid_) {
            status_ = status;
            pid_ = -1;
            break;
        }
        if (r < 0 && errno != EINTR) {  // not our child any more (someone reaped it)
            status_ = 0;
            pid_ = -1;
            break;
        }
        if (cancelled(cancel)) return Io::Cancelled;
        pump(kCancelPollMs, false);
    }
    // What it wrote last; a descendant that keeps the pipes open is not waited for.
    if (outPipe_ >= 0) drain(outPipe_, out_);
    if (errPipe_ >= 0) drain(errPipe_, err_);
    closeFd(pidfd_);
    return Io::Done;
}

void ChildProcess::kill() {
    if (!running()) return;
    closeFd(in_);
    ::kill(-pid_, SIGKILL);  // its process group: helpers it started go too
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    status_ = status;
    pid_ = -1;
    closeFd(pidfd_);
}

std::string ChildProcess::describeExit() const {
    if (WIFEXITED(status_))
        return WEXITSTATUS(status_) == 0 ? "" : "exit status " + std::to_string(WEXITSTATUS(status_));
    if (WIFSIGNALED(status_)) return "killed by signal " + std::to_string(WTERMSIG(status_));
    return "status " + std::to_string(status_);
}

int runToCompletion(const std::string& program, const std::vector<std::string>& args, std::string& output,
                    std::string& errors, const std::atomic<bool>* cancel, bool& wasCancelled) {
    ChildProcess child;
    wasCancelled = false;
    if (!child.start(program, args, errors)) return -1;
    child.closeInput();
    if (child.wait(cancel) == ChildProcess::Io::Cancelled) {
        child.kill();
        wasCancelled = true;
        return -1;
    }
    output = child.standardOutput();
    errors = child.standardError();
    const int status = child.exitStatus();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace f2
