#include "test_pause.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "interrupt.h"

namespace f2::cli {

void pauseForTestAfter(int framesDone) {
    static const char* after = std::getenv("F2_TEST_PAUSE_AFTER_FRAMES");
    static const char* file = std::getenv("F2_TEST_PAUSE_FILE");
    if (!after || !file || std::atoi(after) != framesDone) return;
    if (std::FILE* f = std::fopen(file, "w")) {
        std::fprintf(f, "%d\n", framesDone);
        std::fclose(f);
    }
    // Polled rather than sigsuspend(): the signal may be delivered to any of
    // the render pool's threads, and only the flag is sure to see it.
    while (!interruptFlag().load()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

}  // namespace f2::cli
