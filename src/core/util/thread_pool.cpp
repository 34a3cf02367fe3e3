#include "core/util/thread_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace f2 {

namespace {
// About 50 microseconds of polling before a thread sleeps.
constexpr int kSpinRounds = 4096;

inline void cpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

/// Polls `ready` for a while; true when it became true without sleeping.
template <class Ready>
bool spinUntil(Ready&& ready) {
    for (int i = 0; i < kSpinRounds; ++i) {
        if (ready()) return true;
        cpuRelax();
    }
    return ready();
}
}  // namespace

int ThreadPool::hardwareThreads() {
    unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : int(n);
}

ThreadPool::ThreadPool(int threads) {
    if (threads <= 0) threads = hardwareThreads();
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

void ThreadPool::drain() {
    for (std::uint32_t i = next_.fetch_add(1, std::memory_order_relaxed); i < count_;
         i = next_.fetch_add(1, std::memory_order_relaxed))
        fn_(ctx_, i);
}

void ThreadPool::run(std::uint32_t count, ItemFn fn, void* ctx) {
    if (count == 0) return;
    if (workers_.empty() || count == 1) {
        for (std::uint32_t i = 0; i < count; ++i) fn(ctx, i);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        fn_ = fn;
        ctx_ = ctx;
        count_ = count;
        next_.store(0, std::memory_order_relaxed);
        busy_.store(int(workers_.size()), std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    drain();
    auto finished = [this] { return busy_.load(std::memory_order_acquire) == 0; };
    if (spinUntil(finished)) return;
    std::unique_lock lock(mutex_);
    done_.wait(lock, finished);
}

void ThreadPool::workerLoop() {
    std::uint64_t seen = 0;
    auto newLoop = [&] { return generation_.load(std::memory_order_acquire) != seen; };
    for (;;) {
        if (!spinUntil(newLoop)) {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || newLoop(); });
            if (stop_) return;
        }
        seen = generation_.load(std::memory_order_acquire);
        drain();
        if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            std::lock_guard lock(mutex_);  // the caller may be between its check and its wait
            done_.notify_one();
        }
    }
}

}  // namespace f2
