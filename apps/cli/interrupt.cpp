#include "interrupt.h"

#include <signal.h>

namespace f2::cli {

namespace {
std::atomic<bool> gInterrupted{false};
std::atomic<int> gSignal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "set from a signal handler");

extern "C" void onInterrupt(int signal) {
    int none = 0;
    gSignal.compare_exchange_strong(none, signal);  // the first one decides the exit code
    gInterrupted.store(true);
}
}  // namespace

void installInterruptHandlers() {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART: a blocked write returns and the loop sees the flag
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    // A closed terminal or ssh session: the same clean stop, unless the user
    // asked to ignore it (`nohup f2 render ...` must go on rendering).
    struct sigaction hangup {};
    if (sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN)
        sigaction(SIGHUP, &action, nullptr);
}

const std::atomic<bool>& interruptFlag() { return gInterrupted; }
int interruptSignal() { return gSignal.load(); }

}  // namespace f2::cli
