#include "interrupt.h"

#include <signal.h>

namespace f2::cli {

namespace {
std::atomic<bool> gInterrupted{false};
volatile sig_atomic_t gSignal = 0;
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onInterrupt(int signal) {
    gSignal = signal;
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
}

const std::atomic<bool>& interruptFlag() { return gInterrupted; }
int interruptSignal() { return int(gSignal); }

}  // namespace f2::cli
